// ParallelHdf5File::reserve takes the room it found: a disk that another program fills after
// the check can no longer fail the step's writes (issue 33; a write failing inside HDF5 on
// some ranks only hung the run). Runs for real only on a small tmpfs that
// tests/regression/disk_full/disk_full.sh (case filled_after_check) mounts and names in
// KILN_TEST_SMALL_DISK; skipped elsewhere.
#include "io/parallel_hdf5_file.hpp"

#include <gtest/gtest.h>
#include <mpi.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>
#include <vector>

namespace
{
/// Fills the disk of `folder` with a file of its own until the disk is full; its size.
std::uintmax_t fill_disk(const std::string &folder)
{
  const std::string path = folder + "/filler";
  std::FILE *out = std::fopen(path.c_str(), "wb");
  EXPECT_NE(out, nullptr);
  if (out == nullptr)
    return 0;
  const std::vector<char> block(4096, 'x');
  while (std::fwrite(block.data(), 1, block.size(), out) == block.size() && std::fflush(out) == 0)
  {
  }
  std::fclose(out);
  return std::filesystem::file_size(path);
}

/// `n` values 0, 1, ... as one dataset of `file`, written by rank 0 alone (the others own
/// no row).
void write_values(const kiln::internal::ParallelHdf5File &file, const std::string &name,
                  const int n)
{
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  std::vector<int> owned;
  std::vector<double> values;
  if (rank == 0)
  {
    owned.resize(static_cast<std::size_t>(n));
    std::iota(owned.begin(), owned.end(), 0);
    values.assign(owned.begin(), owned.end());
  }
  file.write_rows(file.root(), name, kiln::internal::OwnedRows(owned, n), 1, values);
}
} // namespace

TEST(ParallelHdf5File, TheRoomReservedSurvivesADiskFilledByAnotherProgram)
{
  const char *small = std::getenv("KILN_TEST_SMALL_DISK");
  if (small == nullptr)
    GTEST_SKIP() << "needs the tmpfs of disk_full.sh filled_after_check";
  const std::string folder = small;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  kiln::internal::ParallelHdf5File file(MPI_COMM_WORLD, folder + "/reserved.h5");
  write_values(file, "first", 1000);
  file.flush();
  // The step to come needs 400 kB; the check finds room and takes it.
  constexpr int n_step = 50000;
  ASSERT_NO_THROW(file.reserve(2 * 8 * n_step));
  // Another program takes every byte left.
  std::uintmax_t filled = 0;
  if (rank == 0)
    filled = fill_disk(folder);
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank == 0)
  {
    EXPECT_GT(filled, 0u);
  }
  EXPECT_NO_THROW({
    write_values(file, "step", n_step);
    file.flush();
    file.close();
  });
  if (rank == 0)
    std::filesystem::remove(folder + "/filler");
}
