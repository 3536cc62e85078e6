// Tests the Jacobian of CoupledProblem::evaluate where gaps cross, against central differences
// of the residual: a rotated box of 2 x 2 x 2 cells held by rollers on its six faces and split
// at its three mid-planes (side sets 10, 11, 12), so eight bodies of one cell each; the node
// at the centre has eight copies, each in three pairs (one per gap), the mid-edge nodes four
// copies in two pairs. Thermo-elastic with a constant gap conductance. States: each body
// moved toward the centre by delta along every box axis and heated (every pair closed,
// "Contact"), moved away and cooled (every pair open, "Contact"), and with random
// displacements for the kinds that always hold ("Sliding", "Bonded"); and with rollers on the
// three faces x-, y-, z- only and "Free Motions" = "Minimum Norm", every pair open, so that
// pairs are held shut where the bodies would be freer than at set-up (doc/contact.md, "Free
// motions while pairs open": tied rows at nodes with two and three gaps and held directions).
// The same box sheared (x += 0.3 z and y += 0.3 z in its frame) so that no two of its gap
// planes are perpendicular, nor the slanted outer faces (rollers) to the gap planes they cut:
// nodes with two and three non-perpendicular normals, and with held directions leaning to
// them, in frames that are not orthonormal (doc/contact.md, "Gaps that cross"); cut at all three
// mid-planes and at x = 0 and z = 0 only.
// Each block's entries agree with the finite differences to 1e-7 of the largest in its row.
// KILN_TEST_NP: 1 2 3
#include "physics/coupled_problem.hpp"

#include "mesh/hex_geometry.hpp"
#include "support/jacobian_check.hpp"
#include "support/parameter_lists.hpp"
#include "support/problem_fixture.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace
{
using namespace kiln_test;
using kiln::GO;
using kiln::LO;
using kiln::Point;
using Vector = kiln::NonlinearProblem::Vector;
using Matrix = kiln::NonlinearProblem::Matrix;

constexpr double phi = 30.0, theta = -20.0;
constexpr double tolerance = 1.0e-7;

Teuchos::ParameterList thermal_block()
{
  Teuchos::ParameterList thermal;
  thermal.set("Initial Temperature", 300.0);
  thermal.set("Gap Conductance", 1.0e4);
  Teuchos::ParameterList &cooled = thermal.sublist("Boundary Conditions").sublist("cooled");
  cooled.set("Type", "Convection");
  cooled.set("Side Sets", ids({1, 2, 3, 4, 5, 6}));
  cooled.set("Coefficient", 50.0);
  cooled.set("Ambient Temperature", constant_function(290.0));
  return thermal;
}

Teuchos::ParameterList mechanics_block(const std::string &kind,
                                       const std::vector<int> &rollers_on = {1, 2, 3, 4, 5, 6})
{
  Teuchos::ParameterList mechanics;
  Teuchos::ParameterList &rollers = mechanics.sublist("Boundary Conditions").sublist("rollers");
  rollers.set("Type", "Normal Displacement");
  rollers.set("Side Sets", ids(rollers_on));
  mechanics.sublist("Contact").set("Kind", kind);
  return mechanics;
}

/// x: T at each node, u of each node's body moved by `delta` toward (< 0: away from) the centre
/// along each box axis, plus random displacements up to `noise` [m]; put in the nodes' frames.
Vector state(ProblemFixture &s, kiln::CoupledProblem &problem, const double T, const double delta,
             const double noise)
{
  const auto map = problem.solution_map();
  const auto &owned = s.dofs.owned_nodes();
  const std::vector<std::array<Point, 3>> q = node_frames(problem);
  const auto A = kiln::rotation_matrix(phi, theta);
  std::mt19937 random(11u);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Point> jitter(s.mesh.n_nodes());
  for (Point &p : jitter)
    for (double &v : p)
      v = noise * unit(random);
  Vector x(map);
  problem.initial_condition(0.0, x);
  for (std::size_t i = 0; i < owned.size(); ++i)
  {
    const int n = owned[i];
    x.replaceLocalValue(static_cast<LO>(4 * i), T);
    // The body of node n: the side of the centre its cell lies on, along each box axis.
    int cell = 0;
    while (std::find(s.mesh.cell_nodes(cell).begin(), s.mesh.cell_nodes(cell).end(), n) ==
           s.mesh.cell_nodes(cell).end())
      ++cell;
    Point centroid{};
    for (const int m : s.mesh.cell_nodes(cell))
      for (int d = 0; d < 3; ++d)
        centroid[d] += s.mesh.coordinates[m][d] / 8.0;
    Point u = jitter[n];
    for (int axis = 0; axis < 3; ++axis)
    {
      double along = 0.0;
      for (int d = 0; d < 3; ++d)
        along += A[d][axis] * centroid[d];
      for (int d = 0; d < 3; ++d)
        u[d] -= delta * (along > 0.0 ? 1.0 : -1.0) * A[d][axis];
    }
    const std::array<double, 3> u_hat = frame_components(q[i], u);
    for (int k = 0; k < 3; ++k)
      if (std::sqrt(kiln::dot(q[i][k], q[i][k])) > 0.5)
        x.replaceLocalValue(static_cast<LO>(4 * i + 1 + k), u_hat[k]);
  }
  return x;
}

struct Crossed : ProblemFixture
{
  explicit Crossed(const double shear = 0.0, const std::vector<int> &gaps = {10, 11, 12})
      : ProblemFixture(crossed_box({{0.02, 0.02, 0.02}, {2, 2, 2}, phi, theta, {}, shear}, gaps),
                       kiln::DofLayout{true, true, true})
  {
  }
};

constexpr double shear = 0.3;

TEST(CrossingGapsJacobian, MeshHasEightBodiesAndThreePairsAtTheCentre)
{
  Crossed s;
  EXPECT_EQ(s.mesh.n_nodes(), 64);         // eight cells with nodes of their own
  EXPECT_EQ(s.mesh.gap_pairs.size(), 48U); // 16 per gap: four faces of 4 nodes
  // The centre: eight copies, each in three pairs, one per gap.
  std::vector<int> pairs_of(s.mesh.n_nodes(), 0);
  for (const kiln::GapPair &p : s.mesh.gap_pairs)
  {
    ++pairs_of[p.node_a];
    ++pairs_of[p.node_b];
  }
  int centre_copies = 0;
  for (int n = 0; n < s.mesh.n_nodes(); ++n)
    if (std::sqrt(kiln::dot(s.mesh.coordinates[n], s.mesh.coordinates[n])) < 1e-12)
    {
      ++centre_copies;
      EXPECT_EQ(pairs_of[n], 3) << "centre copy " << n;
    }
  EXPECT_EQ(centre_copies, 8);
}

TEST(CrossingGapsJacobian, ContactAllClosed)
{
  Crossed s;
  auto problem = s.problem(thermal_block(), mechanics_block("Contact"));
  Vector x = state(s, *problem, 340.0, 2.0e-7, 1.0e-9);
  EXPECT_LE(jacobian_error(s, *problem, x, 48), tolerance);
}

TEST(CrossingGapsJacobian, ContactAllOpen)
{
  Crossed s;
  auto problem = s.problem(thermal_block(), mechanics_block("Contact"));
  Vector x = state(s, *problem, 285.0, -2.0e-7, 1.0e-9);
  EXPECT_LE(jacobian_error(s, *problem, x, 0), tolerance);
}

TEST(CrossingGapsJacobian, SlidingAndBonded)
{
  for (const std::string kind : {"Sliding", "Bonded"})
  {
    Crossed s;
    auto problem = s.problem(thermal_block(), mechanics_block(kind));
    Vector x = state(s, *problem, 310.0, 1.0e-7, 3.0e-8);
    EXPECT_LE(jacobian_error(s, *problem, x, 48), tolerance) << kind;
  }
}

/// Rollers on x-, y-, z- only and "Free Motions" = "Minimum Norm", every pair open by about
/// 4e-7 m, the openings made distinct by the random part (3e-8 m), so that the least open
/// pairs, which are held shut, stay the same under the 1e-9 m steps.
void check_open_pairs_held_shut(const double box_shear)
{
  Crossed s(box_shear);
  Teuchos::ParameterList mechanics = mechanics_block("Contact", {1, 3, 5});
  mechanics.set("Free Motions", "Minimum Norm");
  auto problem = s.problem(thermal_block(), mechanics);
  Vector x = state(s, *problem, 285.0, -2.0e-7, 3.0e-8);
  const int shut = problem->n_active_pairs(x);
  EXPECT_GT(shut, 0) << "no pair held shut";
  EXPECT_LT(shut, 48);
  EXPECT_LE(jacobian_error(s, *problem, x, shut), tolerance);
}

TEST(CrossingGapsJacobian, ContactOpenPairsHeldShutWithMinimumNorm)
{
  check_open_pairs_held_shut(0.0);
}

TEST(CrossingGapsJacobian, ShearedFramesAreNotOrthonormal)
{
  // The frames of the centre's copies: three gap normals, no two perpendicular, so that the
  // unknowns' directions (the dual axes) are not orthogonal either.
  Crossed s(shear);
  auto problem = s.problem(thermal_block(), mechanics_block("Contact"));
  const std::vector<std::array<Point, 3>> t = node_frames(*problem);
  const auto &owned = s.dofs.owned_nodes();
  int leaning = 0;
  for (std::size_t i = 0; i < owned.size(); ++i)
    if (std::sqrt(kiln::dot(s.mesh.coordinates[owned[i]], s.mesh.coordinates[owned[i]])) < 1e-12)
    {
      const double worst =
          std::max({std::abs(kiln::dot(t[i][0], t[i][1])), std::abs(kiln::dot(t[i][0], t[i][2])),
                    std::abs(kiln::dot(t[i][1], t[i][2]))});
      EXPECT_GT(worst, 0.05) << "node " << owned[i];
      ++leaning;
    }
  int all = 0;
  Teuchos::reduceAll(*s.comm, Teuchos::REDUCE_SUM, leaning, Teuchos::outArg(all));
  EXPECT_EQ(all, 8);
}

TEST(CrossingGapsJacobian, ShearedContactAllClosed)
{
  Crossed s(shear);
  auto problem = s.problem(thermal_block(), mechanics_block("Contact"));
  Vector x = state(s, *problem, 340.0, 2.0e-7, 1.0e-9);
  EXPECT_LE(jacobian_error(s, *problem, x, 48), tolerance);
}

TEST(CrossingGapsJacobian, ShearedContactAllOpen)
{
  Crossed s(shear);
  auto problem = s.problem(thermal_block(), mechanics_block("Contact"));
  Vector x = state(s, *problem, 285.0, -2.0e-7, 1.0e-9);
  EXPECT_LE(jacobian_error(s, *problem, x, 0), tolerance);
}

TEST(CrossingGapsJacobian, ShearedTwoGapsClosed)
{
  // Gaps at x = 0 and z = 0 only: the mid-edge copies on y = 0 have two non-perpendicular
  // normals, those on the outer faces y = +-0.01 a roller too (perpendicular to both).
  Crossed s(shear, {10, 12});
  auto problem = s.problem(thermal_block(), mechanics_block("Contact"));
  Vector x = state(s, *problem, 340.0, 2.0e-7, 1.0e-9);
  EXPECT_LE(jacobian_error(s, *problem, x, 24), tolerance);
}

TEST(CrossingGapsJacobian, ShearedSlidingAndBonded)
{
  for (const std::string kind : {"Sliding", "Bonded"})
  {
    Crossed s(shear);
    auto problem = s.problem(thermal_block(), mechanics_block(kind));
    Vector x = state(s, *problem, 310.0, 1.0e-7, 3.0e-8);
    EXPECT_LE(jacobian_error(s, *problem, x, 48), tolerance) << kind;
  }
}

TEST(CrossingGapsJacobian, ShearedContactOpenPairsHeldShutWithMinimumNorm)
{
  check_open_pairs_held_shut(shear);
}
} // namespace
