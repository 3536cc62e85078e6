#pragma once
/// Rank-0 output (deal.II ConditionalOStream, step-40) and warnings.
#include <Teuchos_Comm.hpp>
#include <Teuchos_FancyOStream.hpp>
#include <Teuchos_RCP.hpp>

#include <string>

namespace kiln
{
/// std::cout on rank 0, a black hole elsewhere. The rank-0 stream flushes at every end of
/// line: with stdout redirected to a file (a batch job, mpirun) the C library would
/// otherwise buffer whole blocks, and a run killed by a time limit would leave an empty
/// or truncated log.
Teuchos::RCP<Teuchos::FancyOStream> rank0_stream(const Teuchos::Comm<int> &comm);

/// Prints "kiln: warning: <message>" on std::cout, on rank 0 of MPI_COMM_WORLD only (every
/// rank may call it: inputs are replicated) and once per distinct message in a process.
/// For input that is valid but likely to make the run fail or mislead (say, a nearly
/// incompressible material); the message says what will happen and what to do.
/// Returns whether this call printed it.
bool warn_once(const std::string &message);
} // namespace kiln
