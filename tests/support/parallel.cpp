#include "support/parallel.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_oblackholestream.hpp>

#include <unistd.h>

#include <filesystem>
#include <iostream>

namespace kiln_test
{
double global_max(const Teuchos::Comm<int> &comm, const double local)
{
  double global = 0.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, local, Teuchos::outArg(global));
  return global;
}

double global_sum(const Teuchos::Comm<int> &comm, const double local)
{
  double global = 0.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return global;
}

int global_sum(const Teuchos::Comm<int> &comm, const int local)
{
  int global = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return global;
}

std::ostream &rank0_out()
{
  static Teuchos::oblackholestream black_hole;
  return Teuchos::DefaultComm<int>::getComm()->getRank() == 0 ? std::cout : black_hole;
}

int rank_of(const MPI_Comm comm)
{
  int r = 0;
  MPI_Comm_rank(comm, &r);
  return r;
}

std::string shared_test_folder(const MPI_Comm comm, const std::string &name)
{
  std::string folder;
  if (rank_of(comm) == 0)
  {
    folder = (std::filesystem::temp_directory_path() /
              ("kiln_" + name + "_" + std::to_string(::getpid())))
                 .string();
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
  }
  int length = static_cast<int>(folder.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, comm);
  folder.resize(length);
  MPI_Bcast(folder.data(), length, MPI_CHAR, 0, comm);
  return folder;
}
} // namespace kiln_test
