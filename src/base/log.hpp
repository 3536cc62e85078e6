#pragma once
/// A stream that prints on rank 0 only (deal.II ConditionalOStream, step-40).
#include <Teuchos_Comm.hpp>
#include <Teuchos_FancyOStream.hpp>
#include <Teuchos_RCP.hpp>

namespace kiln
{
/// std::cout on rank 0, a black hole elsewhere.
Teuchos::RCP<Teuchos::FancyOStream> rank0_stream(const Teuchos::Comm<int> &comm);
} // namespace kiln
