// Tests src/physics/mechanics/gravity_kernel.cpp, the body force rho(T) g of a material whose
// density depends on T (doc/materials.md, "Gravity with a density of T"), and its place in the
// assembled problem:
// - on one cell of a rotated box with rho(T) linear (a table): the sum of the force rows is
//   -g ∫ rho(T) dV = -g V (rho(T0) + rho' grad T . (centroid - x0)) for a linear T (exact: the
//   2-point rule integrates the linear rho times phi_i); the u-T block against central
//   differences; no u columns; a material with a constant density takes no term here;
// - the assembled Thermo-Elasticity problem (MaterialMap: block 1 rho(T), block 2 a number;
//   alpha = 0, so that the u-T block is the weight's alone) against central differences of the
//   residual, and that block nonzero.
// KILN_TEST_NP: 1 2
#include "physics/mechanics/gravity_kernel.hpp"

#include "base/parameters.hpp"
#include "support/jacobian_check.hpp"
#include "support/parameter_lists.hpp"
#include "support/problem_fixture.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace
{
using namespace kiln_test;
using kiln::Point;

/// rho(T) = 8000 - 10 (T - 300) kg/m^3 on (300, 600) K, a table.
kiln::TemperatureFunction density()
{
  Teuchos::ParameterList p;
  p.set("Type", "Table");
  p.set("Temperatures", values({300.0, 600.0}));
  p.set("Values", values({8000.0, 5000.0}));
  const Teuchos::ParameterList valid =
      kiln::validated(p, kiln::TemperatureFunction::valid_parameters(1.0, "rho"), "test.xml",
                      "Kiln/Material/Density");
  return kiln::TemperatureFunction(valid, "test.xml: Density");
}
constexpr double rho_300 = 8000.0, rho_slope = -10.0;
const Point gravity{1.0, -2.0, -9.81};

/// T slot 0, u slots 1..3 of a 4-field local system.
constexpr kiln::FieldSlots slots{0, 1};

/// The local system of `kernel` on cell `c` with nodal temperatures T (u = 0).
kiln::LocalSystem evaluate(const kiln::GravityKernel &kernel, const kiln::Mesh &mesh, const int c,
                           const std::vector<double> &T)
{
  kiln::ElementValues fe;
  fe.reinit(mesh, c);
  const int n = fe.n_shape();
  const std::vector<double> T_dot(n, 0.0);
  const std::vector<Point> u(n, Point{});
  const kiln::CellState state{
      fe, {T.data(), n}, {T_dot.data(), n}, {u.data(), n}, 0.0, 0.0, slots, c, 0, {}};
  kiln::LocalSystem local(n, 4, true);
  kernel.evaluate(state, local);
  return local;
}
} // namespace

TEST(GravityKernel, WeightOfALinearDensityAndItsTemperatureDerivative)
{
  const kiln::Mesh mesh = box_mesh({{0.2, 0.1, 0.15}, {2, 1, 1}, 30.0, -20.0}, 0);
  const kiln::GravityKernel kernel(mesh, {density()}, {1}, {}, gravity);
  const int c = 0;
  // T = T0 + a . (x - x0): linear in space, within the table.
  const Point a{150.0, -300.0, 200.0};
  const double T0 = 420.0;
  const Point x0 = mesh.coordinates[mesh.cell_nodes(c)[0]];
  std::vector<double> T;
  Point centroid{};
  for (const int node : mesh.cell_nodes(c))
  {
    const Point &x = mesh.coordinates[node];
    T.push_back(T0 + a[0] * (x[0] - x0[0]) + a[1] * (x[1] - x0[1]) + a[2] * (x[2] - x0[2]));
    for (int d = 0; d < 3; ++d)
      centroid[d] += x[d] / 8.0;
  }
  for (const double t : T)
    ASSERT_TRUE(t > 300.0 && t < 600.0) << t;
  const double volume = 0.1 * 0.1 * 0.15;
  const double T_centroid = T0 + a[0] * (centroid[0] - x0[0]) + a[1] * (centroid[1] - x0[1]) +
                            a[2] * (centroid[2] - x0[2]);
  const double weight = volume * (rho_300 + rho_slope * (T_centroid - 300.0));

  kiln::LocalSystem local = evaluate(kernel, mesh, c, T);
  for (int d = 0; d < 3; ++d)
  {
    double sum = 0.0;
    for (int i = 0; i < 8; ++i)
      sum += local.residual(slots.u + d, i);
    EXPECT_NEAR(sum, -gravity[d] * weight, 1e-12 * std::abs(gravity[2] * weight)) << d;
  }

  // The Jacobian against central differences (the state: T, u_x, u_y, u_z per node; the
  // kernel reads T alone).
  const Dense J = local_jacobian(local);
  const auto residual = [&](const std::vector<double> &state)
  {
    std::vector<double> T_nodes(8);
    for (int j = 0; j < 8; ++j)
      T_nodes[j] = state[4 * j];
    kiln::LocalSystem l = evaluate(kernel, mesh, c, T_nodes);
    std::vector<double> r(32);
    for (int i = 0; i < 8; ++i)
      for (int f = 0; f < 4; ++f)
        r[l.index(f, i)] = l.residual(f, i);
    return r;
  };
  std::vector<double> state(32, 0.0);
  for (int j = 0; j < 8; ++j)
    state[4 * j] = T[j];
  const Dense fd = finite_difference_jacobian(residual, state, 1e-3);
  double largest = 0.0;
  for (int row = 0; row < 32; ++row)
    for (int col = 0; col < 32; ++col)
    {
      largest = std::max(largest, std::abs(J[row][col]));
      if (col % 4 != 0 || row % 4 == 0) // nothing depends on u; no heat rows
      {
        EXPECT_EQ(J[row][col], 0.0) << row << ", " << col;
      }
    }
  EXPECT_GT(largest, 0.0);
  EXPECT_LE(max_difference(J, fd), 1e-9 * largest);

  // A material whose density is a number takes its weight in the elasticity kernel, not here.
  const kiln::GravityKernel none(mesh, {density()}, {0}, {}, gravity);
  kiln::LocalSystem empty = evaluate(none, mesh, c, T);
  EXPECT_EQ(max_abs(local_jacobian(empty)), 0.0);
  for (int i = 0; i < 8; ++i)
    for (int f = 0; f < 4; ++f)
      EXPECT_EQ(empty.residual(f, i), 0.0);
}

TEST(GravityKernel, AssembledJacobianWithTwoMaterials)
{
  ProblemFixture s(distorted_box({{0.04, 0.03, 0.03}, {4, 3, 3}, 30.0, -20.0}, 0.2, 0),
                   kiln::DofLayout{true, true, false});
  Teuchos::ParameterList kiln_user;
  Teuchos::ParameterList &hot = kiln_user.sublist("Materials").sublist("hot");
  hot.set("Blocks", ids({1}));
  hot.set("Thermal Expansion", 0.0);
  Teuchos::ParameterList &rho = hot.sublist("Density");
  rho.set("Type", "Table");
  rho.set("Temperatures", values({300.0, 600.0}));
  rho.set("Values", values({8000.0, 5000.0}));
  Teuchos::ParameterList &cold = kiln_user.sublist("Materials").sublist("cold");
  cold.set("Blocks", ids({2}));
  cold.set("Thermal Expansion", 0.0);
  cold.set("Density", 2700.0);
  const kiln::MaterialMap materials = material_map(kiln_user, s.mesh.block_ids());

  Teuchos::ParameterList thermal;
  thermal.set("Initial Temperature", 400.0);
  Teuchos::ParameterList &held = thermal.sublist("Boundary Conditions").sublist("held");
  held.set("Type", "Temperature");
  held.set("Side Sets", ids({1}));
  held.set("Temperature", constant_function(400.0));
  Teuchos::ParameterList mechanics;
  mechanics.set("Gravity", values({gravity[0], gravity[1], gravity[2]}));
  Teuchos::ParameterList &rollers = mechanics.sublist("Boundary Conditions").sublist("rollers");
  rollers.set("Type", "Normal Displacement");
  rollers.set("Side Sets", ids({1, 3, 5}));
  auto problem = s.problem(thermal, mechanics, &materials);

  // T between 350 and 550 K, varying from node to node; u = 0, so that the force rows hold the
  // weight alone: the u-T entries (~1e-6 N/K) are then not lost in the round-off of stresses
  // (the u-u block is linear: its differences do not depend on u).
  kiln::NonlinearProblem::Vector x(problem->solution_map());
  problem->initial_condition(0.0, x);
  const auto &owned = s.dofs.owned_nodes();
  for (std::size_t i = 0; i < owned.size(); ++i)
  {
    const double r = std::sin(1.7 * owned[i] + 0.3);
    x.replaceLocalValue(static_cast<kiln::LO>(4 * i), 450.0 + 100.0 * r);
  }
  EXPECT_LE(jacobian_error(s, *problem, x, 0), 1e-7);

  // The u-T block is the weight's (alpha = 0): nonzero in block 1's rows.
  kiln::NonlinearProblem::Matrix J(problem->jacobian_graph());
  problem->evaluate(x, nullptr, &J);
  const Dense rows = dense_rows(J, s.dofs.n_global_dofs());
  double u_T = 0.0;
  for (std::size_t i = 0; i < rows.size(); ++i)
  {
    const GO gi = J.getRowMap()->getGlobalElement(static_cast<kiln::LO>(i));
    for (GO j = 0; j < static_cast<GO>(rows[i].size()); ++j)
      if (thermo_mechanical_block(gi, j) == 2)
        u_T = std::max(u_T, std::abs(rows[i][j]));
  }
  double global = 0.0;
  Teuchos::reduceAll(*s.comm, Teuchos::REDUCE_MAX, u_T, Teuchos::outArg(global));
  EXPECT_GT(global, 0.0);
}
