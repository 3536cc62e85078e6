#pragma once
/// What tests on several ranks need around their checks: reductions of measured values, output
/// printed once, and file paths every rank agrees on.
#include <Teuchos_Comm.hpp>
#include <mpi.h>

#include <ostream>
#include <string>

namespace kiln_test
{
/// The largest `local` over the ranks of comm (collective).
double global_max(const Teuchos::Comm<int> &comm, double local);
/// The sum of `local` over the ranks of comm (collective).
double global_sum(const Teuchos::Comm<int> &comm, double local);
int global_sum(const Teuchos::Comm<int> &comm, int local);

/// std::cout on rank 0 of the default communicator, a black hole elsewhere (measured figures
/// are printed once).
std::ostream &rank0_out();

/// The rank of the calling process in comm.
int rank_of(MPI_Comm comm);

/// A fresh, empty folder kiln_<name>_<process id of rank 0> in the temp directory, made by rank
/// 0; its path on every rank of comm (collective).
std::string shared_test_folder(MPI_Comm comm, const std::string &name);
} // namespace kiln_test
