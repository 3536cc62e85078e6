// Displacement conditions on gap nodes composed with contact (doc/contact.md, "Conditions at
// gap nodes"), on a rotated box of 4 x 3 x 3 cells split at its middle plane (side set 10):
// - the global x and y components held on faces 3 and 5, which lean to the gap normal: contact acts
//   on the component of the normal that the condition leaves free; the Jacobian against
//   central differences with the pairs closed ("Contact") and tied ("Sliding");
// - face 3 clamped (all three components): its gap pairs are held by the condition, with no
//   contact unknown; the others are in contact; the Jacobian against central differences;
// - a condition on the faces of one side of the gap only (a side set made here from face 3's
//   side-a cells): the pair is over-determined, an InputError naming both nodes.
// KILN_TEST_NP: 1 2
#include "physics/coupled_problem.hpp"

#include "support/parameter_lists.hpp"
#include "support/problem_fixture.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace
{
using namespace kiln_test;
using kiln::LO;
using kiln::Point;
using testing::HasSubstr;
using Vector = kiln::NonlinearProblem::Vector;

constexpr double tolerance = 1.0e-7;

kiln::Mesh split_box()
{
  return box_mesh({{0.04, 0.03, 0.03}, {4, 3, 3}, 30.0, -20.0}, 10);
}

Teuchos::ParameterList thermal_block()
{
  Teuchos::ParameterList thermal;
  thermal.set("Initial Temperature", 300.0);
  Teuchos::ParameterList &held = thermal.sublist("Boundary Conditions").sublist("held");
  held.set("Type", "Temperature");
  held.set("Side Sets", ids({1, 2}));
  held.set("Temperature", constant_function(320.0));
  return thermal;
}

/// Rollers on faces 1 and 2 (the ends, parallel to the gap), and `extra` as given.
Teuchos::ParameterList mechanics_block(const std::string &kind, const Teuchos::ParameterList &extra)
{
  Teuchos::ParameterList mechanics;
  Teuchos::ParameterList &bcs = mechanics.sublist("Boundary Conditions");
  Teuchos::ParameterList &rollers = bcs.sublist("rollers");
  rollers.set("Type", "Normal Displacement");
  rollers.set("Side Sets", ids({1, 2}));
  bcs.set(extra.name(), extra);
  mechanics.sublist("Contact").set("Kind", kind);
  return mechanics;
}

Teuchos::ParameterList components(const std::string &name, const std::vector<int> &sets,
                                  const std::vector<std::string> &which)
{
  Teuchos::ParameterList p(name);
  p.set("Type", "Displacement");
  p.set("Side Sets", ids(sets));
  p.set("Components", Teuchos::Array<std::string>(which.begin(), which.end()));
  return p;
}

/// x: T = 320 K, the two sides pushed into each other by `delta` along the gap normal, plus
/// random displacements up to `noise` [m], in the nodes' frames.
Vector state(const ProblemFixture &s, kiln::CoupledProblem &problem, const double delta,
             const double noise)
{
  const std::vector<std::array<Point, 3>> q = node_frames(problem);
  const Point n = s.mesh.gap_pairs.front().normal;
  std::mt19937 random(5u);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Point> jitter(s.mesh.n_nodes());
  for (Point &p : jitter)
    for (double &v : p)
      v = noise * unit(random);
  std::vector<char> side_b(s.mesh.n_nodes(), 0);
  for (int c = 0; c < s.mesh.n_cells(); ++c)
    for (const int node : s.mesh.cell_nodes(c))
      side_b[node] = s.mesh.block_id[c] == 2;
  Vector x(problem.solution_map());
  problem.initial_condition(0.0, x);
  const auto &owned = s.dofs.owned_nodes();
  for (std::size_t i = 0; i < owned.size(); ++i)
  {
    const int node = owned[i];
    x.replaceLocalValue(static_cast<LO>(4 * i), 320.0);
    Point u = jitter[node];
    for (int d = 0; d < 3; ++d)
      u[d] += (side_b[node] ? -0.5 : 0.5) * delta * n[d];
    for (int k = 0; k < 3; ++k)
      if (kiln::dot(q[i][k], q[i][k]) > 0.25)
        x.replaceLocalValue(static_cast<LO>(4 * i + 1 + k), kiln::dot(q[i][k], u));
  }
  return x;
}

TEST(ContactConditions, LeaningConditionContactOnTheFreeComponent)
{
  for (const std::string kind : {"Contact", "Sliding"})
  {
    ProblemFixture s(split_box(), kiln::DofLayout{true, true, true});
    auto problem = s.problem(thermal_block(),
                             mechanics_block(kind, components("held x and y", {3, 5}, {"x", "y"})));
    ASSERT_EQ(problem->n_pairs(), 16);
    Vector x = state(s, *problem, 2.0e-7, 1.0e-9);
    EXPECT_LE(jacobian_error(s, *problem, x, 16), tolerance) << kind;
  }
}

TEST(ContactConditions, ClampedGapNodesAreHeld)
{
  ProblemFixture s(split_box(), kiln::DofLayout{true, true, true});
  auto problem = s.problem(thermal_block(),
                           mechanics_block("Contact", components("clamped", {3}, {"x", "y", "z"})));
  Vector x = state(s, *problem, 2.0e-7, 1.0e-9);
  // Face 3 holds the 4 pairs of its edge on the gap: the other 12 are in contact.
  EXPECT_LE(jacobian_error(s, *problem, x, 12), tolerance);
  const auto out = problem->contact_output(x);
  int held = 0;
  for (const kiln::GapPair &pair : s.mesh.gap_pairs)
    held += out.active[pair.node_a] == 0.0;
  EXPECT_EQ(held, 4);
}

TEST(ContactConditions, ConditionOnOneSideOnlyIsAnInputError)
{
  kiln::Mesh mesh = split_box();
  // Side set 20: the faces of side set 3 whose cells are in block 1 (side a of the gap).
  kiln::SideSet one_side;
  one_side.id = 20;
  for (const kiln::SideSet &set : mesh.side_sets)
    if (set.id == 3)
      for (int i = 0; i < set.n_sides(); ++i)
        if (mesh.block_id[set.cells[i]] == 1)
        {
          one_side.cells.push_back(set.cells[i]);
          one_side.faces.push_back(set.faces[i]);
        }
  mesh.side_sets.push_back(one_side);
  ProblemFixture s(std::move(mesh), kiln::DofLayout{true, true, true});
  const std::string message = input_error_message(
      [&]
      {
        s.problem(thermal_block(),
                  mechanics_block("Contact", components("one side", {20}, {"x", "y", "z"})));
      });
  EXPECT_THAT(message, HasSubstr("cannot pair gap nodes"));
  EXPECT_THAT(message, HasSubstr("conditions \"one side\""));
  EXPECT_THAT(message, HasSubstr("over-determined"));
}
} // namespace
