// Tests src/io/collective_checks.cpp: a check that fails on one rank throws on every rank
// (InternalError or InputError, with one message), an InputError on rank 0 of
// run_on_rank_zero() reaches every rank, the out-of-turn calls and the field-name rule.
// KILN_TEST_NP: 1 2
#include "io/collective_checks.hpp"

#include "base/errors.hpp"
#include "mesh/mesh.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <mpi.h>

#include <string>
#include <vector>

namespace
{
using kiln::internal::Center;
using kiln::internal::FieldSpec;
using testing::HasSubstr;

int last_rank(const MPI_Comm comm)
{
  int size = 0;
  MPI_Comm_size(comm, &size);
  return size - 1;
}

int rank_of(const MPI_Comm comm)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  return rank;
}

TEST(CollectiveChecks, AFieldSizeWrongOnTheLastRankIsAnInternalErrorOnEveryRank)
{
  const MPI_Comm comm = MPI_COMM_WORLD;
  const FieldSpec stress{"stress", Center::cell, 6};
  EXPECT_NO_THROW(kiln::internal::check_field_size(comm, stress, 2, 12));
  const std::size_t n_values = rank_of(comm) == last_rank(comm) ? 11 : 12;
  try
  {
    kiln::internal::check_field_size(comm, stress, 2, n_values);
    ADD_FAILURE() << "no exception";
  }
  catch (const kiln::InternalError &e)
  {
    EXPECT_THAT(e.what(), HasSubstr("cell field \"stress\" has"));
    EXPECT_THAT(e.what(), HasSubstr("values on some rank, expected 6 per owned cell"));
  }
}

TEST(CollectiveChecks, AnInputErrorFoundOnTheLastRankIsThrownOnEveryRankWithItsMessage)
{
  const MPI_Comm comm = MPI_COMM_WORLD;
  const bool last = rank_of(comm) == last_rank(comm);
  try
  {
    kiln::internal::check_input_collectively(comm, !last, "out.h5", last ? "disk full" : "");
    ADD_FAILURE() << "no exception";
  }
  catch (const kiln::InputError &e)
  {
    EXPECT_EQ(std::string(e.what()), "out.h5: disk full");
  }
}

TEST(CollectiveChecks, AnInputErrorOnRankZeroIsThrownOnEveryRank)
{
  const MPI_Comm comm = MPI_COMM_WORLD;
  int runs = 0;
  EXPECT_NO_THROW(kiln::internal::run_on_rank_zero(comm, [&] { ++runs; }));
  EXPECT_EQ(runs, rank_of(comm) == 0 ? 1 : 0);
  try
  {
    kiln::internal::run_on_rank_zero(
        comm, [] { KILN_CHECK_INPUT(false, "out.exo", "cannot create the results file"); });
    ADD_FAILURE() << "no exception";
  }
  catch (const kiln::InputError &e)
  {
    EXPECT_EQ(std::string(e.what()), "out.exo: cannot create the results file");
  }
}

TEST(CollectiveChecks, CallsOutOfTurnAreInternalErrors)
{
  const FieldSpec temperature{"temperature", Center::node, 1};
  EXPECT_NO_THROW(kiln::internal::check_begin_step(false));
  EXPECT_NO_THROW(kiln::internal::check_write_field(true, temperature));
  EXPECT_NO_THROW(kiln::internal::check_end_step(true));
  EXPECT_THROW(kiln::internal::check_begin_step(true), kiln::InternalError);
  EXPECT_THROW(kiln::internal::check_end_step(false), kiln::InternalError);
  try
  {
    kiln::internal::check_write_field(false, temperature);
    ADD_FAILURE() << "no exception";
  }
  catch (const kiln::InternalError &e)
  {
    EXPECT_THAT(e.what(), HasSubstr("write_node_field(\"temperature\") called outside "
                                    "begin_step()/end_step()"));
  }
}

TEST(CollectiveChecks, FieldNamesArePlain)
{
  for (const std::string name : {"temperature", "gap_opening", "u-1.5", "."})
    EXPECT_TRUE(kiln::internal::is_valid_field_name(name)) << name;
  for (const std::string name : {"", "bad/name", "a b", "stress[0]", "t\xc3\xa9"})
    EXPECT_FALSE(kiln::internal::is_valid_field_name(name)) << name;
}

TEST(CollectiveChecks, OwnedRowsMustPartitionTheMesh)
{
  const MPI_Comm comm = MPI_COMM_WORLD;
  kiln::Mesh mesh;
  mesh.coordinates.resize(8, kiln::Point{});
  mesh.add_cell(kiln::CellType::hex8, {0, 1, 2, 3, 4, 5, 6, 7}, 1);
  const bool first = rank_of(comm) == 0;
  const std::vector<int> all_nodes{0, 1, 2, 3, 4, 5, 6, 7};
  const std::vector<int> nodes = first ? all_nodes : std::vector<int>{};
  const std::vector<int> cells = first ? std::vector<int>{0} : std::vector<int>{};
  EXPECT_NO_THROW(kiln::internal::check_row_partition(comm, mesh, nodes, cells, {0}));
  // Every rank claims the cell when there are several: not a partition.
  const std::vector<int> every_cell{0};
  if (last_rank(comm) > 0)
  {
    EXPECT_THROW(kiln::internal::check_row_partition(comm, mesh, nodes, every_cell, {0}),
                 kiln::InternalError);
  }
  const std::vector<int> unsorted = first ? std::vector<int>{1, 0, 2, 3, 4, 5, 6, 7} : nodes;
  EXPECT_THROW(kiln::internal::check_row_partition(comm, mesh, unsorted, cells, {0}),
               kiln::InternalError);
}
} // namespace
