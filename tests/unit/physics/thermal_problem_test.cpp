// Tests the heat conduction of src/physics/coupled_problem.cpp (temperature-only layout) and
// thermal_boundary_condition.cpp on a small
// rotated box split at its mid-plane: the assembled Jacobian against central differences of
// the residual with every boundary-condition type, a table k(T), the gap and a BDF2-like time
// derivative; the scaled identity rows of prescribed temperatures; the global heat balance at
// a uniform temperature; zero gap flux for equal temperatures across the gap; and the
// messages for inconsistent boundary conditions.
// KILN_TEST_NP: 1 2
#include "physics/coupled_problem.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "discretization/element_values.hpp"
#include "mesh/hex_geometry.hpp"
#include "physics/heat/convection_condition.hpp"
#include "physics/heat/heat_flux_condition.hpp"
#include "physics/heat/thermal_conditions.hpp"
#include "support/jacobian_check.hpp"
#include "support/parallel.hpp"
#include "support/parameter_lists.hpp"
#include "support/problem_fixture.hpp"
#include "support/reference_cells.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

using testing::HasSubstr;

namespace
{
using namespace kiln_test;
using kiln::GO;
using kiln::LO;
using kiln::Mesh;
using kiln::Point;
using Vector = kiln::NonlinearProblem::Vector;
using Matrix = kiln::NonlinearProblem::Matrix;

constexpr double Lx = 0.04, Ly = 0.02, Lz = 0.02;
/// Material: TableMaterial, rho c [J/(m^3 K)]; k = 120 + 2 (T - 280) W/(m K) on (280, 400) K.
constexpr double rho_c = TableMaterial::density * TableMaterial::specific_heat;
double k_table(const double T)
{
  return TableMaterial::conductivity(T);
}
/// Time of the evaluations [s]; the prescribed temperature, a smooth step 300 -> 320 K over
/// [0, 10] s, is then 300 + 20 s^2 (3 - 2 s), s = 0.4; the ambient temperature, a table
/// 290 -> 280 K over [0, 10] s, is 286 K.
constexpr double t_now = 4.0;
constexpr double T_prescribed = 300.0 + 20.0 * 0.16 * (3.0 - 0.8);
constexpr double T_ambient = 286.0;
constexpr double h_convection = 50.0, q_flux = 2.0e4, h_gap = 1.0e4;

Mesh split_box()
{
  return box_mesh({{Lx, Ly, Lz}, {4, 2, 2}, 30.0, -20.0}, 10);
}

void add_temperature_bc(Teuchos::ParameterList &thermal)
{
  Teuchos::ParameterList &bc = thermal.sublist("Boundary Conditions").sublist("hot end");
  bc.set("Type", "Temperature");
  bc.set("Side Sets", Teuchos::Array<int>(Teuchos::tuple(1)));
  bc.set("Temperature", smooth_step(300.0, 320.0));
}

void add_flux_bcs(Teuchos::ParameterList &thermal)
{
  Teuchos::ParameterList &convection = thermal.sublist("Boundary Conditions").sublist("cooled end");
  convection.set("Type", "Convection");
  convection.set("Side Sets", Teuchos::Array<int>(Teuchos::tuple(2)));
  convection.set("Coefficient", h_convection);
  Teuchos::ParameterList &ambient = convection.sublist("Ambient Temperature");
  ambient.set("Type", "Table");
  ambient.set("Times", Teuchos::Array<double>(Teuchos::tuple(0.0, 10.0)));
  ambient.set("Values", Teuchos::Array<double>(Teuchos::tuple(290.0, 280.0)));

  Teuchos::ParameterList &flux = thermal.sublist("Boundary Conditions").sublist("heated sides");
  flux.set("Type", "Heat Flux");
  flux.set("Side Sets", Teuchos::Array<int>(Teuchos::tuple(3, 5)));
  flux.set("Heat Flux", constant_function(q_flux));
}

Teuchos::ParameterList thermal_list(const bool temperature, const bool fluxes,
                                    const double gap_conductance)
{
  Teuchos::ParameterList thermal;
  thermal.set("Initial Temperature", 300.0);
  thermal.set("Gap Conductance", gap_conductance);
  if (temperature)
    add_temperature_bc(thermal);
  if (fluxes)
    add_flux_bcs(thermal);
  return thermal;
}

/// The split box with a temperature unknown per node.
struct Fixture : ProblemFixture
{
  Fixture() : ProblemFixture(split_box(), kiln::DofLayout{true, false, false}) {}
};

/// v_i = value(node of row i) on the owned rows (one unknown per node: gid = node).
void set_field(Vector &v, const std::function<double(int)> &value)
{
  const auto map = v.getMap();
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
    v.replaceLocalValue(static_cast<LO>(i),
                        value(static_cast<int>(map->getGlobalElement(static_cast<LO>(i)))));
}

/// A smooth nonuniform temperature in (290, 313) K, 3 K higher on the twins (side b).
double nonuniform_state(const Fixture &s, const int n)
{
  const Point &x = s.mesh.coordinates[n];
  return 300.0 + 10.0 * std::sin(60.0 * x[0] + 90.0 * x[1] - 70.0 * x[2] + 0.3) +
         (s.is_twin(n) ? 3.0 : 0.0);
}

} // namespace

TEST(ThermalProblem, JacobianMatchesFiniteDifferencesWithAllConditions)
{
  Fixture s;
  auto problem = s.problem(thermal_list(true, true, h_gap));
  const auto map = problem->solution_map();
  const GO n_global = s.dofs.n_global_dofs();
  ASSERT_EQ(n_global, 5 * 3 * 3 + 3 * 3); // the nodes and the 9 twins of the mid-plane

  // BDF2-like: a = 1.5 / dt, b = -(2 x_n - x_{n-1} / 2) / dt, here a smooth nonuniform field.
  const double dt = 0.5, a = 1.5 / dt;
  Vector x(map), b(map), f(map);
  set_field(x, [&](const int n) { return nonuniform_state(s, n); });
  set_field(b,
            [&](const int n)
            {
              const Point &p = s.mesh.coordinates[n];
              return -a * (298.0 + 4.0 * std::cos(50.0 * p[0] - 30.0 * p[1] + 80.0 * p[2]));
            });
  problem->set_time_derivative(t_now, a, b);
  Matrix J(problem->jacobian_graph());
  problem->evaluate(x, &f, &J);
  const auto rows = dense_rows(J, n_global);

  double max_J = 0.0;
  for (const auto &row : rows)
    for (const double v : row)
      max_J = std::max(max_J, std::abs(v));
  max_J = global_max(*s.comm, max_J);
  ASSERT_GT(max_J, 0.0);

  // Column by column, every rank in lock step (evaluate is collective).
  const double eps = 1e-3;
  const Dense fd_rows = finite_difference_rows(*problem, x, [eps](GO) { return eps; });
  double max_difference = 0.0;
  int n_nonzero = 0;
  for (GO j = 0; j < n_global; ++j)
  {
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
      const double fd = fd_rows[i][j];
      const double difference = std::abs(fd - rows[i][j]);
      EXPECT_LT(difference, 1e-6 * max_J)
          << "row " << map->getGlobalElement(static_cast<LO>(i)) << ", column " << j
          << ": J = " << rows[i][j] << ", finite difference " << fd;
      max_difference = std::max(max_difference, difference);
      n_nonzero += rows[i][j] != 0.0;
    }
  }
  max_difference = global_max(*s.comm, max_difference);
  if (s.comm->getRank() == 0)
    std::cout << "ThermalProblem: max |J - J_fd| = " << max_difference << " (max |J| = " << max_J
              << ", relative " << max_difference / max_J << ")\n";
  // Every node couples with the nodes of its cells, twins with their partners: far more than
  // the diagonal.
  EXPECT_GT(global_sum(*s.comm, n_nonzero), 4 * n_global);
}

TEST(ThermalProblem, TemperatureRowsAreScaledIdentityRows)
{
  Fixture s;
  auto problem = s.problem(thermal_list(true, true, h_gap));
  const auto map = problem->solution_map();
  const std::vector<char> on_1 = s.nodes_of_side_set(1);

  // The scale: the conduction stiffness diagonal Σ_cells k(300 K) ∫ |∇φ_i|^2 at the initial
  // temperature, computed here cell by cell.
  std::vector<double> scale(s.mesh.n_nodes(), 0.0);
  kiln::ElementValues fe;
  for (int c = 0; c < s.mesh.n_cells(); ++c)
  {
    kiln_test::reinit(fe, kiln::cell_nodes(s.mesh, c));
    for (int i = 0; i < 8; ++i)
      for (int q = 0; q < fe.n_qpoints(); ++q)
      {
        const Point &g = fe.grad(i, q);
        scale[s.mesh.cell_nodes(c)[i]] +=
            k_table(300.0) * (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]) * fe.JxW(q);
      }
  }

  // The initial condition: 300 K, and the prescribed temperature on side set 1.
  Vector x(map), b(map), f(map);
  problem->initial_condition(t_now, x);
  {
    const auto v = x.getData();
    for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
    {
      const int n = static_cast<int>(map->getGlobalElement(static_cast<LO>(i)));
      EXPECT_NEAR(v[i], on_1[n] ? T_prescribed : 300.0, 1e-12 * 300.0) << "node " << n;
    }
  }

  set_field(x, [&](const int n) { return nonuniform_state(s, n); });
  set_field(b, [](int) { return -700.0; });
  problem->set_time_derivative(t_now, 3.0, b);
  Matrix J(problem->jacobian_graph());
  problem->evaluate(x, &f, &J);
  const auto rows = dense_rows(J, s.dofs.n_global_dofs());
  const auto r = f.getData(), v = x.getData();
  int n_checked = 0;
  for (std::size_t i = 0; i < rows.size(); ++i)
  {
    const int n = static_cast<int>(map->getGlobalElement(static_cast<LO>(i)));
    if (!on_1[n])
      continue;
    ++n_checked;
    for (std::size_t j = 0; j < rows[i].size(); ++j)
      EXPECT_TRUE(static_cast<int>(j) == n || rows[i][j] == 0.0)
          << "row " << n << ", column " << j << ": " << rows[i][j];
    const double s_n = rows[i][n];
    EXPECT_GT(s_n, 0.0);
    EXPECT_NEAR(s_n, scale[n], 1e-12 * scale[n]) << "node " << n;
    // No flux, convection, gap or storage term left in the row (side set 1 shares edges
    // with the heat-flux side sets 3 and 5).
    EXPECT_NEAR(r[i], s_n * (v[i] - T_prescribed), 1e-12 * s_n * 300.0) << "node " << n;
  }
  EXPECT_EQ(global_sum(*s.comm, n_checked), 3 * 3); // the x- face's nodes
}

TEST(ThermalProblem, UniformTemperatureBalancesStorageAndBoundaryFluxes)
{
  // Without prescribed temperatures, at a uniform T0 conduction and the gap give nothing in
  // total, so Σ_i F_i = rho c Tdot V - q (A_3 + A_5) + h (T0 - T_amb(t)) A_2.
  Fixture s;
  auto problem = s.problem(thermal_list(false, true, h_gap));
  const auto map = problem->solution_map();
  const double T0 = 305.0, a = 3.0, T_dot = 0.02;
  Vector x(map), b(map), f(map), ones(map);
  x.putScalar(T0);
  b.putScalar(T_dot - a * T0);
  ones.putScalar(1.0);
  problem->set_time_derivative(t_now, a, b);
  problem->evaluate(x, &f, nullptr);
  const double expected = rho_c * T_dot * Lx * Ly * Lz - q_flux * (Lx * Lz + Lx * Ly) +
                          h_convection * (T0 - T_ambient) * Ly * Lz;
  EXPECT_NEAR(f.dot(ones), expected, 1e-10 * q_flux * Lx * Ly);
}

TEST(ThermalProblem, EqualTemperaturesAcrossTheGapGiveNoGapFlux)
{
  Fixture s;
  // A uniform temperature equal to the prescribed one, no storage and no fluxes: F = 0 up to
  // the rounding of Σ_j ∇φ_j = 0 in the conduction term.
  {
    Teuchos::ParameterList thermal = thermal_list(false, false, h_gap);
    Teuchos::ParameterList &bc = thermal.sublist("Boundary Conditions").sublist("fixed end");
    bc.set("Type", "Temperature");
    bc.set("Side Sets", Teuchos::Array<int>(Teuchos::tuple(1)));
    bc.set("Temperature", constant_function(300.0));
    auto problem = s.problem(thermal);
    Vector x(problem->solution_map()), zero(problem->solution_map()), f(problem->solution_map());
    x.putScalar(300.0);
    problem->set_time_derivative(t_now, 0.0, zero);
    problem->evaluate(x, &f, nullptr);
    const double norm = f.normInf(); // collective
    EXPECT_LT(norm, 1e-9);
    if (s.comm->getRank() == 0)
      std::cout << "ThermalProblem: uniform 300 K, |F|_inf = " << norm << " W\n";
  }

  // A nonuniform field continuous across the gap: the gap adds exactly nothing, so the
  // residual with h = 1e4 equals the one with h = 0 bit for bit. With a uniform jump d on
  // side b the difference is the gap flux: +h d A on side a's gap nodes, -h d A on the twins.
  auto with_gap = s.problem(thermal_list(true, true, h_gap));
  auto without_gap = s.problem(thermal_list(true, true, 0.0));
  const auto map = with_gap->solution_map();
  Vector x(map), b(map), f_gap(map), f_none(map);
  set_field(b, [](int) { return -900.0; });
  with_gap->set_time_derivative(t_now, 3.0, b);
  without_gap->set_time_derivative(t_now, 3.0, b);
  const auto continuous = [&](const int n) { return nonuniform_state(s, s.mesh.parent_node[n]); };
  set_field(x, continuous);
  with_gap->evaluate(x, &f_gap, nullptr);
  without_gap->evaluate(x, &f_none, nullptr);
  {
    const auto r_gap = f_gap.getData(), r_none = f_none.getData();
    for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
      EXPECT_EQ(r_gap[i], r_none[i]) << "row " << map->getGlobalElement(static_cast<LO>(i));
  }

  const double jump = 2.5;
  set_field(x, [&](const int n) { return continuous(n) + (s.is_twin(n) ? -jump : 0.0); });
  with_gap->evaluate(x, &f_gap, nullptr);
  without_gap->evaluate(x, &f_none, nullptr);
  std::vector<char> side_a(s.mesh.n_nodes(), 0);
  for (const auto &pair : s.mesh.gap_pairs)
    side_a[pair.node_a] = 1;
  double flux_a = 0.0, flux_b = 0.0, elsewhere = 0.0;
  {
    const auto r_gap = f_gap.getData(), r_none = f_none.getData();
    for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
    {
      const int n = static_cast<int>(map->getGlobalElement(static_cast<LO>(i)));
      const double gap_part = r_gap[i] - r_none[i];
      if (side_a[n])
        flux_a += gap_part;
      else if (s.is_twin(n))
        flux_b += gap_part;
      else
        elsewhere = std::max(elsewhere, std::abs(gap_part));
    }
  }
  const double total = h_gap * jump * Ly * Lz;
  EXPECT_NEAR(global_sum(*s.comm, flux_a), total, 1e-10 * total);
  EXPECT_NEAR(global_sum(*s.comm, flux_b), -total, 1e-10 * total);
  EXPECT_EQ(global_max(*s.comm, elsewhere), 0.0);
}

namespace
{
const std::string bc_where = "test.xml: Kiln/Thermal/Boundary Conditions";

/// The condition of a "Boundary Conditions" list holding `user` as sublist "bad".
std::unique_ptr<kiln::BoundaryCondition> make_bc(const Mesh &mesh,
                                                 const Teuchos::ParameterList &user)
{
  Teuchos::ParameterList thermal;
  thermal.sublist("Boundary Conditions").set("bad", user);
  const Teuchos::ParameterList p = kiln::validated(
      thermal, kiln::ThermalPhysics::valid_parameters(), "test.xml", "Kiln/Thermal");
  auto conditions =
      kiln::read_boundary_conditions(kiln::thermal_conditions(), p.sublist("Boundary Conditions"),
                                     mesh, kiln::InteriorFaceCheck(mesh), bc_where,
                                     "heat crosses it through Kiln/Thermal/\"Gap Conductance\"");
  return std::move(conditions.front());
}

std::string bc_error(const Mesh &mesh, const Teuchos::ParameterList &user)
{
  return input_error_message([&] { make_bc(mesh, user); });
}

Teuchos::ParameterList temperature_on(const Teuchos::Array<int> &side_sets)
{
  Teuchos::ParameterList p;
  p.set("Type", "Temperature");
  p.set("Side Sets", side_sets);
  p.set("Temperature", constant_function(300.0));
  return p;
}
} // namespace

TEST(ThermalBoundaryCondition, ValidConditionsAreRead)
{
  const Mesh mesh = split_box();
  Teuchos::ParameterList thermal;
  add_flux_bcs(thermal);
  const auto read_convection =
      make_bc(mesh, thermal.sublist("Boundary Conditions").sublist("cooled end"));
  const auto *convection = dynamic_cast<const kiln::ConvectionCondition *>(read_convection.get());
  ASSERT_NE(convection, nullptr);
  EXPECT_EQ(convection->side_sets(), std::vector<int>{2});
  EXPECT_EQ(convection->coefficient(), h_convection);
  EXPECT_NEAR(convection->ambient_temperature(t_now), T_ambient, 1e-12);
  const auto read_flux =
      make_bc(mesh, thermal.sublist("Boundary Conditions").sublist("heated sides"));
  const auto *flux = dynamic_cast<const kiln::HeatFluxCondition *>(read_flux.get());
  ASSERT_NE(flux, nullptr);
  EXPECT_EQ(flux->side_sets(), (std::vector<int>{3, 5}));
  EXPECT_EQ(flux->flux(t_now), q_flux);
}

TEST(ThermalBoundaryCondition, InputErrors)
{
  const Mesh mesh = split_box();
  const std::string side_sets = bc_where + "/bad/\"Side Sets\": ";

  // A side set the mesh does not have: the message lists the boundary ones (not the gap).
  const auto unknown = temperature_on(Teuchos::Array<int>(Teuchos::tuple(1, 99)));
  EXPECT_THROW(make_bc(mesh, unknown), kiln::InputError);
  EXPECT_THAT(bc_error(mesh, unknown),
              HasSubstr(side_sets + "side set 99 is not in the mesh; its boundary side sets are "
                                    "1, 2, 3, 4, 5, 6"));

  // The gap side set.
  const auto gap = temperature_on(Teuchos::Array<int>(Teuchos::tuple(10)));
  EXPECT_THROW(make_bc(mesh, gap), kiln::InputError);
  EXPECT_THAT(bc_error(mesh, gap), HasSubstr(side_sets + "side set 10 is the gap"));
  EXPECT_THAT(bc_error(mesh, gap), HasSubstr("\"Gap Conductance\""));

  // No side sets, given empty or left out.
  const auto empty = temperature_on(Teuchos::Array<int>());
  EXPECT_THROW(make_bc(mesh, empty), kiln::InputError);
  EXPECT_THAT(bc_error(mesh, empty), HasSubstr(side_sets + "is missing or empty"));
  Teuchos::ParameterList missing = temperature_on(Teuchos::Array<int>(Teuchos::tuple(1)));
  missing.remove("Side Sets");
  EXPECT_THAT(bc_error(mesh, missing), HasSubstr(side_sets + "is missing or empty"));

  // A parameter of another Type.
  Teuchos::ParameterList coefficient = temperature_on(Teuchos::Array<int>(Teuchos::tuple(1)));
  coefficient.set("Coefficient", 10.0);
  EXPECT_THROW(make_bc(mesh, coefficient), kiln::InputError);
  EXPECT_THAT(bc_error(mesh, coefficient),
              HasSubstr(bc_where + "/bad/\"Coefficient\": applies to Type \"Convection\", not "
                                   "to Type \"Temperature\""));

  // Convection without its ambient temperature, and without its coefficient.
  Teuchos::ParameterList no_ambient;
  no_ambient.set("Type", "Convection");
  no_ambient.set("Side Sets", Teuchos::Array<int>(Teuchos::tuple(2)));
  no_ambient.set("Coefficient", 10.0);
  EXPECT_THROW(make_bc(mesh, no_ambient), kiln::InputError);
  EXPECT_THAT(bc_error(mesh, no_ambient),
              HasSubstr(bc_where + "/bad/\"Ambient Temperature\": is required for Type "
                                   "\"Convection\""));
  Teuchos::ParameterList no_coefficient = no_ambient;
  no_coefficient.remove("Coefficient");
  no_coefficient.set("Ambient Temperature", constant_function(290.0));
  EXPECT_THROW(make_bc(mesh, no_coefficient), kiln::InputError);
  EXPECT_THAT(bc_error(mesh, no_coefficient),
              HasSubstr(bc_where + "/bad/\"Coefficient\": is required for Type \"Convection\""));
}
