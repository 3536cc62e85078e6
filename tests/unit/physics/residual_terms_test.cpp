// Tests src/physics/residual_terms.cpp: a term that throws in one cell of one rank does not
// leave the other ranks waiting: every rank ends its terms and throws the same RunError,
// naming the rank, the cell and its block, and the term's message. A cell's kernels see the
// temperatures of the last accepted state (NodalFields::set_accepted) as T_old, not the
// current ones, and none before an accepted state.
// KILN_TEST_NP: 1 2
#include "physics/residual_terms.hpp"

#include "base/errors.hpp"
#include "discretization/assembler.hpp"
#include "discretization/nodal_constraints.hpp"
#include "physics/nodal_fields.hpp"
#include "support/problem_fixture.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
/// Adds nothing; throws in the first cell it is evaluated on, on rank `rank` only.
class ThrowingKernel final : public kiln::CellKernel
{
public:
  ThrowingKernel(const int rank, const int my_rank) : throws_(rank == my_rank) {}
  void evaluate(const kiln::CellState &, kiln::LocalSystem &) const override
  {
    if (throws_)
      throw std::runtime_error("the conductivity is not a number");
  }

private:
  bool throws_;
};

/// Records, per cell it is evaluated on, the smallest and largest T and T_old of its nodes
/// (NaN for T_old if it got none).
class RecordingKernel final : public kiln::CellKernel
{
public:
  struct Seen
  {
    double T_min, T_max, T_old_min, T_old_max;
  };
  mutable std::vector<Seen> seen;
  void evaluate(const kiln::CellState &state, kiln::LocalSystem &) const override
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Seen s{state.T[0], state.T[0], nan, nan};
    for (int i = 0; i < state.T.size(); ++i)
    {
      s.T_min = std::min(s.T_min, state.T[i]);
      s.T_max = std::max(s.T_max, state.T[i]);
      if (state.history.T_old != nullptr)
      {
        s.T_old_min =
            i == 0 ? state.history.T_old[i] : std::min(s.T_old_min, state.history.T_old[i]);
        s.T_old_max =
            i == 0 ? state.history.T_old[i] : std::max(s.T_old_max, state.history.T_old[i]);
      }
    }
    seen.push_back(s);
  }
};

TEST(ResidualTerms, CellsSeeTheTemperatureOfTheLastAcceptedStateAsTOld)
{
  kiln_test::ProblemFixture fixture(kiln_test::box_mesh({{0.04, 0.04, 0.04}, {4, 2, 2}}, 0),
                                    kiln::DofLayout{true, true, false});
  kiln::Assembler assembler(fixture.mesh, fixture.dofs);
  kiln::NodalConstraints constraints(fixture.mesh, fixture.dofs);
  constraints.close(1.0, 1.0);
  kiln::NodalFields fields(fixture.dofs, assembler, constraints, 298.0);
  kiln::ResidualTerms terms(fixture.mesh, fixture.dofs, kiln::FieldSlots{0, 1});
  const RecordingKernel kernel;
  terms.add_cell_kernel(kernel);
  const auto sink = [](const std::vector<int> &, kiln::LocalSystem &) {};
  // T = 300 K everywhere at the accepted state, 400 K at the one being solved (u = 0).
  const auto state = [&](const double T)
  {
    kiln::NodalFields::Vector x(fixture.dofs.owned_dof_map());
    const int F = fixture.dofs.n_node_fields();
    for (std::size_t i = 0; i < fixture.dofs.owned_nodes().size(); ++i)
      x.replaceLocalValue(static_cast<kiln::LO>(F * i), T);
    return x;
  };
  const kiln::NodalFields::Vector accepted = state(300.0), current = state(400.0);
  const auto x_overlap = assembler.make_overlap_vector();
  assembler.gather(current, *x_overlap);
  fields.update(*x_overlap);
  // No accepted state yet: no T_old (the model takes T).
  terms.evaluate(fields, false, sink);
  ASSERT_EQ(kernel.seen.size(), fixture.dofs.owned_cells().size());
  for (const auto &s : kernel.seen)
  {
    EXPECT_EQ(s.T_min, 400.0);
    EXPECT_TRUE(std::isnan(s.T_old_min));
  }
  EXPECT_FALSE(fields.has_accepted());
  fields.set_accepted(accepted);
  ASSERT_TRUE(fields.has_accepted());
  // A new step's time state keeps it.
  fields.set_time_derivative(1.0, 1.0, current);
  fields.update(*x_overlap);
  kernel.seen.clear();
  terms.evaluate(fields, false, sink);
  ASSERT_EQ(kernel.seen.size(), fixture.dofs.owned_cells().size());
  for (const auto &s : kernel.seen)
  {
    EXPECT_EQ(s.T_min, 400.0);
    EXPECT_EQ(s.T_max, 400.0);
    EXPECT_EQ(s.T_old_min, 300.0);
    EXPECT_EQ(s.T_old_max, 300.0);
  }
}

TEST(ResidualTerms, AnExceptionInOneRanksCellIsTheSameRunErrorOnEveryRank)
{
  kiln_test::ProblemFixture fixture(kiln_test::box_mesh({{0.04, 0.04, 0.04}, {4, 2, 2}}, 0),
                                    kiln::DofLayout{true, false, false});
  const auto &comm = *fixture.comm;
  const int last = comm.getSize() - 1;
  kiln::Assembler assembler(fixture.mesh, fixture.dofs);
  kiln::NodalConstraints constraints(fixture.mesh, fixture.dofs);
  constraints.close(1.0, 1.0);
  kiln::NodalFields fields(fixture.dofs, assembler, constraints, 298.0);
  fields.update(*assembler.make_overlap_vector());
  kiln::ResidualTerms terms(fixture.mesh, fixture.dofs, kiln::FieldSlots{0, -1});
  const ThrowingKernel kernel(last, comm.getRank());
  terms.add_cell_kernel(kernel);

  int sunk = 0;
  std::string message;
  try
  {
    terms.evaluate(fields, false, [&](const std::vector<int> &, kiln::LocalSystem &) { ++sunk; });
  }
  catch (const kiln::RunError &e)
  {
    message = e.what();
  }
  EXPECT_THAT(message, testing::MatchesRegex(
                           "the assembly of the residual failed on rank " + std::to_string(last) +
                           " of " + std::to_string(comm.getSize()) +
                           " at cell [0-9]+ \\(block [12]\\): the conductivity is not a number; "
                           "every rank stopped"));
  // The other ranks went through all their cells.
  const int expected =
      comm.getRank() != last ? static_cast<int>(fixture.dofs.owned_cells().size()) : 0;
  EXPECT_EQ(sunk, expected);
}
} // namespace
