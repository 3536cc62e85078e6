// Tests src/physics/residual_terms.cpp: a term that throws in one cell of one rank does not
// leave the other ranks waiting: every rank ends its terms and throws the same RunError,
// naming the rank, the cell and its block, and the term's message.
// KILN_TEST_NP: 1 2
#include "physics/residual_terms.hpp"

#include "base/errors.hpp"
#include "discretization/assembler.hpp"
#include "discretization/nodal_constraints.hpp"
#include "physics/nodal_fields.hpp"
#include "support/problem_fixture.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

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
