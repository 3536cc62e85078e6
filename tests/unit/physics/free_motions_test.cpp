// FreeMotions on the assembled problem: a split box (rotated, its nodes moved) clamped on one
// end, so that contact holds its second half along the gap's normal only. The three free
// motions found (the second half's translations in the gap's plane and its rotation about
// the normal) are the Jacobian's null space on both sides, J v = 0 and v^T J = 0 (what the
// minimum-norm solve of the Newton solver relies on), with the contact pairs of a random
// state partly closed (rows combined) and partly open, and F(x + v) = F(x). With the default
// "Free Motions" = "Error" the same problem is refused, naming the motions.
// KILN_TEST_NP: 1 2
#include "physics/coupled_problem.hpp"

#include "support/parameter_lists.hpp"
#include "support/problem_fixture.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace
{
using namespace kiln_test;
using Vector = kiln::NonlinearProblem::Vector;
using Matrix = kiln::NonlinearProblem::Matrix;

/// The box 0.04 x 0.03 x 0.03 m, 4 x 3 x 3 cells, rotated (30, -20 degrees), its inner nodes
/// moved by up to 20% of a cell (the gap stays plane), split at side set 10.
kiln::Mesh split_box()
{
  return distorted_box({{0.04, 0.03, 0.03}, {4, 3, 3}, 30.0, -20.0}, 0.2, 10, true);
}

/// Clamped on side set 1 (the first half's end); contact across the gap.
Teuchos::ParameterList mechanics(const std::string &free_motions)
{
  Teuchos::ParameterList m;
  m.set("Free Motions", free_motions);
  Teuchos::ParameterList &clamp = m.sublist("Boundary Conditions").sublist("clamped end");
  clamp.set("Type", "Displacement");
  clamp.set("Side Sets", ids({1}));
  clamp.set("Components", Teuchos::Array<std::string>(Teuchos::tuple<std::string>("x", "y", "z")));
  return m;
}

TEST(FreeMotions, TheMotionsAreTheJacobiansNullSpaceOnBothSides)
{
  const ProblemFixture s(split_box(), kiln::DofLayout{true, true, true});
  const auto problem = s.problem(Teuchos::ParameterList(), mechanics("Minimum Norm"));
  const auto V = problem->free_motions();
  ASSERT_FALSE(V.is_null());
  ASSERT_EQ(V->getNumVectors(), 3U);
  const std::vector<std::string> names = problem->free_motion_names();
  ASSERT_EQ(names.size(), 3U);
  EXPECT_THAT(names[0], testing::StartsWith("translation along ("));
  EXPECT_THAT(names[1], testing::StartsWith("translation along ("));
  EXPECT_THAT(names[2], testing::StartsWith("rotation about the axis ("));

  // A state: the initial one with random displacements of up to 1e-6 m, so that some pairs
  // interpenetrate (closed) and others open.
  const auto map = problem->solution_map();
  Vector x(map), b(map);
  problem->set_time_derivative(0.0, 0.0, b);
  problem->initial_condition(0.0, x);
  std::mt19937 random(11u + static_cast<unsigned>(map->getComm()->getRank()));
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  {
    auto values = x.getDataNonConst();
    for (decltype(values.size()) i = 0; i < values.size(); ++i)
      if (i % 4 != 0) // the displacement unknowns
        values[i] += 1e-6 * unit(random);
  }
  Vector f(map), f_moved(map), y(map);
  Matrix J(problem->jacobian_graph());
  problem->evaluate(x, &f, &J);
  const int active = problem->n_active_pairs(x);
  EXPECT_GT(active, 0);
  EXPECT_LT(active, problem->n_pairs());
  const double J_norm = J.getFrobeniusNorm();
  for (std::size_t j = 0; j < V->getNumVectors(); ++j)
  {
    const auto v = V->getVector(j);
    J.apply(*v, y);
    EXPECT_LT(y.norm2(), 1e-13 * J_norm * v->norm2()) << "J v, " << names[j];
    J.apply(*v, y, Teuchos::TRANS);
    EXPECT_LT(y.norm2(), 1e-13 * J_norm * v->norm2()) << "v^T J, " << names[j];
    // F(x + t v) = F(x), t a tenth of the random displacements' size over v's.
    Vector moved(x, Teuchos::Copy);
    moved.update(1e-7 / v->normInf(), *v, 1.0);
    problem->evaluate(moved, &f_moved, nullptr);
    f_moved.update(-1.0, f, 1.0);
    EXPECT_LT(f_moved.norm2(), 1e-9 * f.norm2()) << "F(x + t v) - F(x), " << names[j];
  }
}

TEST(FreeMotions, TheDefaultRefusesTheProblemAndNamesTheMotions)
{
  const ProblemFixture s(split_box(), kiln::DofLayout{true, true, true});
  const std::string message =
      input_error_message([&] { s.problem(Teuchos::ParameterList(), mechanics("Error")); });
  EXPECT_THAT(message, testing::StartsWith("test.xml: Kiln/Mechanics: the displacement "
                                           "conditions leave rigid motions free"));
  EXPECT_THAT(message, testing::HasSubstr("body 2 of 2 (element block 2, "));
  EXPECT_THAT(message, testing::HasSubstr("; contact across the gap holds the two sides together "
                                          "along its normal only"));
}
} // namespace
