// Tests src/physics/coupled_problem.cpp, the assembled heat and thermo-elastic system with
// exact constraints in rotated nodal frames, on rotated boxes whose interior nodes are moved:
// - the Thermo-Elasticity Jacobian against central differences of the residual, entry by
//   entry and block by block (T-T, T-u, u-T, u-u), with a table k(T), a time derivative,
//   every thermal and mechanical boundary condition (rollers meeting at edges and corners, one
//   with a prescribed normal motion, a component condition on another side), gravity and a
//   body force; and that the physical displacement meets every constraint;
// - the Elasticity Jacobian with rotated rollers is symmetric and positive definite (CG), and
//   is the u-u block of the Thermo-Elasticity Jacobian with the same conditions;
// - the patch test: a uniform stress sigma = A diag(s) A^T, applied as tractions on three faces
//   of a distorted rotated box held by rollers on the other three, is reproduced to round-off
//   by a Newton solve (u = eps (x - x_corner), cell strain eps = C^-1 sigma, cell stress sigma);
//   and with a uniform temperature T0 != T_ref, where eps = C^-1 sigma + alpha (T0 - T_ref) I.
// KILN_TEST_NP: 1 2
#include "physics/coupled_problem.hpp"

#include "base/log.hpp"
#include "mesh/hex_geometry.hpp"
#include "solvers/newton_solver.hpp"
#include "support/jacobian_check.hpp"
#include "support/parallel.hpp"
#include "support/parameter_lists.hpp"
#include "support/problem_fixture.hpp"
#include "support/tensors.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
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
using Tensor = Matrix3;
using Fixture = ProblemFixture;

/// Material: TableMaterial (aluminium-like, k(T) a table, so k' counts in the Jacobian).
constexpr double youngs = TableMaterial::youngs, poisson = TableMaterial::poisson,
                 alpha = TableMaterial::alpha, T_ref = TableMaterial::T_ref;

/// Time of the finite-difference evaluations [s]: the Smooth Step conditions over [0, 10] s
/// are then at s = 0.4, s^2 (3 - 2 s) = 0.352 of the way.
constexpr double t_now = 4.0;
constexpr double step_fraction = 0.16 * (3.0 - 0.8);
/// The prescribed normal displacement of side set 3 at t_now, and u_y on side set 2 [m].
constexpr double g_3 = 5.0e-6 * step_fraction, g_2_y = -1.0e-6;

/// The thermal block of the finite-difference test: the temperature on side set 1 (a smooth
/// step 300 -> 320 K), convection on 2 and 6 (h = 50, ambient 290 -> 280 K), a heat flux on 3
/// and 5; 4 insulated.
Teuchos::ParameterList thermal_conditions()
{
  Teuchos::ParameterList thermal;
  thermal.set("Initial Temperature", 300.0);
  thermal.set("Gap Conductance", 1.0e4);
  Teuchos::ParameterList &bcs = thermal.sublist("Boundary Conditions");
  Teuchos::ParameterList &hot = bcs.sublist("hot end");
  hot.set("Type", "Temperature");
  hot.set("Side Sets", ids({1}));
  hot.set("Temperature", smooth_step(300.0, 320.0));
  Teuchos::ParameterList &cooled = bcs.sublist("cooled");
  cooled.set("Type", "Convection");
  cooled.set("Side Sets", ids({2, 6}));
  cooled.set("Coefficient", 50.0);
  Teuchos::ParameterList &ambient = cooled.sublist("Ambient Temperature");
  ambient.set("Type", "Table");
  ambient.set("Times", values({0.0, 10.0}));
  ambient.set("Values", values({290.0, 280.0}));
  Teuchos::ParameterList &heated = bcs.sublist("heated");
  heated.set("Type", "Heat Flux");
  heated.set("Side Sets", ids({3, 5}));
  heated.set("Heat Flux", constant_function(2.0e4));
  return thermal;
}

/// The mechanics block of the finite-difference and symmetry tests: rollers on 1 and 5 (one
/// condition), a prescribed normal motion of 3 (g_3 at t_now), u_y = g_2_y on 2, a traction
/// on 4, a pressure on 6; gravity and a body force.
Teuchos::ParameterList mechanical_conditions()
{
  Teuchos::ParameterList mechanics;
  mechanics.set("Gravity", values({0.0, 0.0, -9.81}));
  mechanics.set("Body Force", values({2.0e4, -1.0e4, 5.0e3}));
  Teuchos::ParameterList &bcs = mechanics.sublist("Boundary Conditions");
  Teuchos::ParameterList &rollers = bcs.sublist("rollers");
  rollers.set("Type", "Normal Displacement");
  rollers.set("Side Sets", ids({1, 5}));
  Teuchos::ParameterList &pushed = bcs.sublist("pushed");
  pushed.set("Type", "Normal Displacement");
  pushed.set("Side Sets", ids({3}));
  pushed.set("Displacement", smooth_step(0.0, 5.0e-6));
  Teuchos::ParameterList &sliding = bcs.sublist("sliding");
  sliding.set("Type", "Displacement");
  sliding.set("Side Sets", ids({2}));
  sliding.set("Components", Teuchos::Array<std::string>(1, "y"));
  sliding.set("Displacement", constant_function(g_2_y));
  Teuchos::ParameterList &load = bcs.sublist("load");
  load.set("Type", "Traction");
  load.set("Side Sets", ids({4}));
  load.set("Traction", values({1.0e6, -2.0e6, 3.0e5}));
  Teuchos::ParameterList &pressure = bcs.sublist("pressure");
  pressure.set("Type", "Pressure");
  pressure.set("Side Sets", ids({6}));
  pressure.set("Pressure", constant_function(5.0e5));
  return mechanics;
}

/// v at each owned row = value(global id of the row).
void set_by_gid(Vector &v, const std::vector<double> &value)
{
  const auto map = v.getMap();
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
    v.replaceLocalValue(static_cast<LO>(i), value[map->getGlobalElement(static_cast<LO>(i))]);
}
} // namespace

TEST(CoupledProblem, JacobianMatchesFiniteDifferencesWithAllConditions)
{
  const double phi = 30.0, theta = -20.0;
  Fixture s(distorted_box({{0.04, 0.03, 0.03}, {4, 3, 3}, phi, theta}, 0.2, 10),
            kiln::DofLayout{true, true, false});
  auto problem = s.problem(thermal_conditions(), mechanical_conditions());
  const auto map = problem->solution_map();
  const GO n_global = s.dofs.n_global_dofs();
  ASSERT_EQ(n_global, 4 * (5 * 4 * 4 + 4 * 4)); // nodes and the 16 twins of the mid-plane

  // A nonuniform state: T in (290, 310) K, u (in the nodes' frames) up to 1e-5 m; the
  // time derivative BDF2-like, a = 1.5 / dt, b = -a (298 K + up to 4 K).
  const double a = 3.0;
  std::vector<double> x_values(n_global), b_values(n_global);
  {
    std::mt19937 random(7u);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (GO j = 0; j < n_global; ++j)
    {
      const bool T = j % 4 == 0;
      x_values[j] = T ? 300.0 + 10.0 * unit(random) : 1.0e-5 * unit(random);
      b_values[j] = -a * (298.0 + 4.0 * unit(random));
    }
  }
  Vector x(map), b(map), f(map);
  set_by_gid(x, x_values);
  set_by_gid(b, b_values);
  problem->set_time_derivative(t_now, a, b);
  Matrix J(problem->jacobian_graph());
  problem->evaluate(x, &f, &J);
  const Dense rows = dense_rows(J, n_global);

  // The largest |J| of each block: (rows T or u) x (columns T or u).
  const auto block = thermo_mechanical_block;
  std::array<double, 4> max_J{}, max_J_global{};
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (GO j = 0; j < n_global; ++j)
    {
      const int k = block(map->getGlobalElement(static_cast<LO>(i)), j);
      max_J[k] = std::max(max_J[k], std::abs(rows[i][j]));
    }
  Teuchos::reduceAll(*s.comm, Teuchos::REDUCE_MAX, 4, max_J.data(), max_J_global.data());
  EXPECT_GT(max_J_global[0], 0.0); // heat conduction, storage, convection, gap
  EXPECT_EQ(max_J_global[1], 0.0); // the heat rows do not depend on u
  EXPECT_GT(max_J_global[2], 0.0); // thermal expansion
  EXPECT_GT(max_J_global[3], 0.0); // elasticity

  // Column by column, every rank in lock step (evaluate is collective). The residual is
  // quadratic in T between the table's points (k linear) and linear in u, so the central
  // difference is exact but for round-off.
  const Dense fd_rows =
      finite_difference_rows(*problem, x, [](const GO j) { return j % 4 == 0 ? 1.0e-3 : 1.0e-8; });
  std::array<double, 4> max_difference{}, max_difference_global{};
  int n_nonzero = 0;
  for (GO j = 0; j < n_global; ++j)
  {
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
      const GO gi = map->getGlobalElement(static_cast<LO>(i));
      const int k = block(gi, j);
      const double fd = fd_rows[i][j];
      const double difference = std::abs(fd - rows[i][j]);
      EXPECT_LE(difference, 1e-7 * max_J_global[k])
          << "row " << gi << ", column " << j << ": J = " << rows[i][j] << ", finite difference "
          << fd;
      max_difference[k] = std::max(max_difference[k], difference);
      n_nonzero += rows[i][j] != 0.0;
    }
  }
  Teuchos::reduceAll(*s.comm, Teuchos::REDUCE_MAX, 4, max_difference.data(),
                     max_difference_global.data());
  if (s.comm->getRank() == 0)
  {
    std::cout << "CoupledProblem (" << n_global << " unknowns):";
    for (int k = 0; k < 4; ++k)
      std::cout << "\n  block " << thermo_mechanical_block_names[k]
                << ": max |J| = " << max_J_global[k]
                << ", max |J - J_fd| = " << max_difference_global[k] << " (relative "
                << (max_J_global[k] > 0 ? max_difference_global[k] / max_J_global[k] : 0.0) << ")";
    std::cout << "\n";
  }
  // Each row couples with the unknowns of the nodes around its node, not just its own.
  EXPECT_GT(global_sum(*s.comm, n_nonzero), 20 * n_global);

  // The physical state meets every constraint: u.n_1 = 0, u.n_5 = 0, u.n_3 = g_3, u_y = g_2_y
  // (at edges and corners all at once: the directions are independent), T = T_1(t).
  const auto A = kiln::rotation_matrix(phi, theta);
  const Point e_x = column(A, 0), e_y = column(A, 1), e_z = column(A, 2);
  const auto on_1 = s.nodes_of_side_set(1), on_2 = s.nodes_of_side_set(2),
             on_3 = s.nodes_of_side_set(3), on_5 = s.nodes_of_side_set(5);
  const std::vector<Point> u = problem->node_displacements(x);
  const std::vector<double> T = problem->node_temperatures(x);
  const auto &owned = s.dofs.owned_nodes();
  int n_checked = 0;
  double max_violation = 0.0;
  for (std::size_t i = 0; i < owned.size(); ++i)
  {
    const int n = owned[i];
    const auto check = [&](const double value, const double expected, const char *what)
    {
      EXPECT_NEAR(value, expected, 1e-15) << what << " at node " << n;
      max_violation = std::max(max_violation, std::abs(value - expected));
      ++n_checked;
    };
    if (on_1[n])
    {
      check(-dot(u[i], e_x), 0.0, "u.n_1");
      EXPECT_NEAR(T[i], 300.0 + 20.0 * step_fraction, 1e-12) << "T at node " << n;
    }
    if (on_5[n])
      check(-dot(u[i], e_z), 0.0, "u.n_5");
    if (on_3[n])
      check(-dot(u[i], e_y), g_3, "u.n_3");
    if (on_2[n])
      check(u[i][1], g_2_y, "u_y");
  }
  max_violation = global_max(*s.comm, max_violation);
  if (s.comm->getRank() == 0)
    std::cout << "  constraints: max |u.n - g| = " << max_violation << " m\n";
  // Sides 1 and 2 (4 x 4 nodes each), 3 and 5 (5 x 4 nodes each and 4 twins on the cut).
  EXPECT_EQ(global_sum(*s.comm, n_checked), 16 + 16 + 2 * (5 * 4 + 4));
}

TEST(CoupledProblem, ElasticityJacobianWithRotatedRollersIsSymmetricPositiveDefinite)
{
  Fixture s(distorted_box({{0.04, 0.03, 0.03}, {4, 3, 3}, 30.0, -20.0}, 0.2, 10),
            kiln::DofLayout{false, true, false});
  auto problem = s.problem(Teuchos::ParameterList(), mechanical_conditions());
  const auto map = problem->solution_map();
  const GO n = s.dofs.n_global_dofs();
  ASSERT_EQ(n, 3 * (5 * 4 * 4 + 4 * 4));

  Vector x(map), zero(map), f(map);
  x.randomize(-1.0e-5, 1.0e-5);
  problem->set_time_derivative(t_now, 0.0, zero);
  Matrix J(problem->jacobian_graph());
  problem->evaluate(x, &f, &J);
  Dense K = dense_matrix(J, n);

  double max_J = 0.0, max_asymmetry = 0.0;
  for (GO i = 0; i < n; ++i)
    for (GO j = 0; j < n; ++j)
    {
      max_J = std::max(max_J, std::abs(K[i][j]));
      max_asymmetry = std::max(max_asymmetry, std::abs(K[i][j] - K[j][i]));
    }
  EXPECT_LE(max_asymmetry, 1e-14 * max_J);

  // The same conditions in the Thermo-Elasticity layout give the same u-u block.
  double max_block_difference = 0.0;
  {
    Fixture coupled(distorted_box({{0.04, 0.03, 0.03}, {4, 3, 3}, 30.0, -20.0}, 0.2, 10),
                    kiln::DofLayout{true, true, false});
    auto coupled_problem = coupled.problem(thermal_conditions(), mechanical_conditions());
    const auto coupled_map = coupled_problem->solution_map();
    Vector x4(coupled_map), b4(coupled_map), f4(coupled_map);
    x4.putScalar(305.0);
    coupled_problem->set_time_derivative(t_now, 0.0, b4);
    Matrix J4(coupled_problem->jacobian_graph());
    coupled_problem->evaluate(x4, &f4, &J4);
    const Dense K4 = dense_matrix(J4, coupled.dofs.n_global_dofs());
    const auto u_dof = [](const GO i) { return 4 * (i / 3) + 1 + i % 3; };
    for (GO i = 0; i < n; ++i)
      for (GO j = 0; j < n; ++j)
        max_block_difference =
            std::max(max_block_difference, std::abs(K[i][j] - K4[u_dof(i)][u_dof(j)]));
  }
  EXPECT_LE(max_block_difference, 1e-14 * max_J);

  // Both halves are held (rollers on 1, 3, 5 on one; u_y on 2 with the normals of 3 and 5 on
  // the other), so K is positive definite: Cholesky meets no pivot <= 0.
  double min_pivot = max_J;
  for (GO j = 0; j < n; ++j)
  {
    double d = K[j][j];
    for (GO k = 0; k < j; ++k)
      d -= K[j][k] * K[j][k];
    ASSERT_GT(d, 0.0) << "pivot " << j;
    min_pivot = std::min(min_pivot, d);
    K[j][j] = std::sqrt(d);
    for (GO i = j + 1; i < n; ++i)
    {
      double v = K[i][j];
      for (GO k = 0; k < j; ++k)
        v -= K[i][k] * K[j][k];
      K[i][j] = v / K[j][j];
    }
  }
  if (s.comm->getRank() == 0)
    std::cout << "Elasticity Jacobian (" << n << " unknowns): max |J - J^T| = " << max_asymmetry
              << " (max |J| = " << max_J << ", relative " << max_asymmetry / max_J
              << "); max difference to the u-u block of Thermo-Elasticity " << max_block_difference
              << "; smallest Cholesky pivot " << min_pivot << " (relative " << min_pivot / max_J
              << ")\n";
}

namespace
{
/// The patch test: a box of 4 x 3 x 5 cells, rotated and moved, its interior nodes moved by
/// up to 20% of a cell; rollers on 1, 3, 5; traction sigma n on 2, 4, 6 with
/// sigma = A diag(s) A^T; with `thermal`, T = T0 held on every face. Solves the steady
/// problem and checks u, the cell strains and the cell stresses.
void check_uniform_stress(const bool thermal, const double T0)
{
  const double phi = 30.0, theta = 20.0;
  const Point size{0.04, 0.03, 0.05}, s_block{1.0e8, -5.0e7, 2.0e7};
  Fixture s(distorted_box({size, {4, 3, 5}, phi, theta, {0.1, -0.2, 0.05}}, 0.2, 0),
            kiln::DofLayout{thermal, true, false});
  const auto A = kiln::rotation_matrix(phi, theta);

  Teuchos::ParameterList mechanics;
  Teuchos::ParameterList &bcs = mechanics.sublist("Boundary Conditions");
  Teuchos::ParameterList &rollers = bcs.sublist("rollers");
  rollers.set("Type", "Normal Displacement");
  rollers.set("Side Sets", ids({1, 3, 5}));
  for (int d = 0; d < 3; ++d)
  {
    // Face 2d + 2 has the outward normal A e_d: sigma n = s_d A e_d.
    Teuchos::ParameterList &load = bcs.sublist("load " + std::to_string(d));
    load.set("Type", "Traction");
    load.set("Side Sets", ids({2 * d + 2}));
    load.set("Traction",
             values({s_block[d] * A[0][d], s_block[d] * A[1][d], s_block[d] * A[2][d]}));
  }
  Teuchos::ParameterList thermal_list;
  if (thermal)
  {
    thermal_list.set("Initial Temperature", T0);
    Teuchos::ParameterList &held = thermal_list.sublist("Boundary Conditions").sublist("held");
    held.set("Type", "Temperature");
    held.set("Side Sets", ids({1, 2, 3, 4, 5, 6}));
    held.set("Temperature", constant_function(T0));
  }
  auto problem = s.problem(thermal_list, mechanics);

  Teuchos::ParameterList solver;
  solver.set("Relative Tolerance", 1e-13);
  solver.set("Absolute Tolerance", 1e-300);
  solver.set("Maximum Iterations", 4);
  Teuchos::ParameterList &belos =
      solver.sublist("Linear Solver").sublist("Linear Solver Types").sublist("Belos");
  const std::string krylov = thermal ? "Pseudo Block GMRES" : "Pseudo Block CG";
  belos.set("Solver Type", krylov);
  Teuchos::ParameterList &krylov_list = belos.sublist("Solver Types").sublist(krylov);
  krylov_list.set("Convergence Tolerance", 1e-13);
  krylov_list.set("Maximum Iterations", 2000);
  kiln::NewtonSolver newton(solver, problem, kiln::rank0_stream(*s.comm));

  const auto map = problem->solution_map();
  Vector x(map), zero(map);
  problem->set_time_derivative(0.0, 0.0, zero);
  problem->initial_condition(0.0, x);
  const kiln::NewtonSolver::Result result = newton.solve(x);
  EXPECT_TRUE(result.converged);

  // Expected: eps = A diag(e) A^T, e_d = (s_d - nu (s_other)) / E + alpha dT.
  const double dT = thermal ? T0 - T_ref : 0.0;
  Point e_block{};
  for (int d = 0; d < 3; ++d)
    e_block[d] = (s_block[d] - poisson * (s_block[(d + 1) % 3] + s_block[(d + 2) % 3])) / youngs +
                 alpha * dT;
  const Tensor sigma = rotated_diagonal(A, s_block), eps = rotated_diagonal(A, e_block);
  // The corner where faces 1, 3, 5 meet: node 0 of the box, on the boundary, not moved.
  const Point corner = s.mesh.coordinates[0];

  const auto &owned = s.dofs.owned_nodes();
  const std::vector<Point> u = problem->node_displacements(x);
  double max_u = 0.0, u_error = 0.0;
  for (std::size_t i = 0; i < owned.size(); ++i)
  {
    const Point &p = s.mesh.coordinates[owned[i]];
    for (int d = 0; d < 3; ++d)
    {
      double exact = 0.0;
      for (int k = 0; k < 3; ++k)
        exact += eps[d][k] * (p[k] - corner[k]);
      max_u = std::max(max_u, std::abs(exact));
      u_error = std::max(u_error, std::abs(u[i][d] - exact));
    }
  }
  double T_error = 0.0;
  if (thermal)
    for (const double T : problem->node_temperatures(x))
      T_error = std::max(T_error, std::abs(T - T0));

  double max_sigma = 0.0, max_eps = 0.0, stress_error = 0.0, strain_error = 0.0,
         thermal_strain_error = 0.0;
  for (int d = 0; d < 3; ++d)
    for (int k = 0; k < 3; ++k)
    {
      max_sigma = std::max(max_sigma, std::abs(sigma[d][k]));
      max_eps = std::max(max_eps, std::abs(eps[d][k]));
    }
  for (const auto &cell : problem->cell_averages(x))
    for (int d = 0; d < 3; ++d)
      for (int k = d; k < 3; ++k)
      {
        const int v = voigt_index[d][k];
        stress_error = std::max(stress_error, std::abs(cell.stress[v] - sigma[d][k]));
        strain_error = std::max(strain_error, std::abs(cell.strain[v] - eps[d][k]));
        thermal_strain_error = std::max(
            thermal_strain_error, std::abs(cell.thermal_strain[v] - (d == k ? alpha * dT : 0.0)));
      }
  u_error = global_max(*s.comm, u_error);
  max_u = global_max(*s.comm, max_u);
  T_error = global_max(*s.comm, T_error);
  stress_error = global_max(*s.comm, stress_error);
  strain_error = global_max(*s.comm, strain_error);
  thermal_strain_error = global_max(*s.comm, thermal_strain_error);
  if (s.comm->getRank() == 0)
  {
    std::cout << "Patch test (" << (thermal ? "Thermo-Elasticity" : "Elasticity");
    if (thermal)
      std::cout << ", T0 - T_ref = " << dT << " K";
    std::cout << ", " << s.dofs.n_global_dofs() << " unknowns): Newton " << result.newton_iterations
              << " iterations, " << result.linear_iterations << " linear; |F| "
              << result.initial_residual_norm << " -> " << result.final_residual_norm
              << "\n  max |u - u_exact| = " << u_error << " m (relative " << u_error / max_u
              << "), max |strain - eps| relative " << strain_error / max_eps
              << ", max |stress - sigma| relative " << stress_error / max_sigma
              << ", max |T - T0| = " << T_error
              << " K, max |thermal strain - alpha dT| = " << thermal_strain_error << "\n";
  }
  EXPECT_LE(u_error, 1e-10 * max_u);
  EXPECT_LE(strain_error, 1e-10 * max_eps);
  EXPECT_LE(stress_error, 1e-10 * max_sigma);
  EXPECT_LE(T_error, 1e-10 * T0);
  EXPECT_LE(thermal_strain_error, 1e-10 * max_eps);
}
} // namespace

TEST(CoupledProblem, UniformStressOnADistortedRotatedBoxIsExact)
{
  check_uniform_stress(false, T_ref);
}

TEST(CoupledProblem, UniformStressAndUniformTemperatureOnADistortedRotatedBoxAreExact)
{
  check_uniform_stress(true, 340.0);
}
