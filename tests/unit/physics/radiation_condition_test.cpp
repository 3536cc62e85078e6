// Tests src/physics/heat/radiation_condition.cpp, the radiation boundary condition
// eps sigma (T^4 - T_amb^4), added by the recipe of doc/architecture.md:
// - its face terms against the exact integrals on a parallelogram at a uniform temperature
//   (R_i = eps sigma (T^4 - T_amb^4) A/4, dR/dT = 4 eps sigma T^3 M with the face mass matrix);
// - its local Jacobian against central differences at a non-uniform temperature;
// - the Jacobian of a whole problem with radiation against central differences of its residual;
// - the steady state of a rotated bar held at T0 at one end and radiating at the other, split at
//   its middle by a gap of conductance h: the flux q = (T0 - Ts)/(L/k + 1/h) = eps sigma (Ts^4 -
//   T_amb^4) gives a temperature linear on each side with a jump q/h at the gap, which Q1
//   represents exactly, so every node matches the analytic value to the solver tolerance;
// - its input errors.
// KILN_TEST_NP: 1 2
#include "physics/heat/radiation_condition.hpp"

#include "app/simulation.hpp"
#include "base/parameters.hpp"
#include "mesh/box_mesh_generator.hpp"
#include "mesh/hex_geometry.hpp"
#include "physics/coupled_problem.hpp"
#include "physics/heat/thermal_conditions.hpp"
#include "physics/heat/thermal_physics.hpp"
#include "solvers/newton_solver.hpp"
#include "support/jacobian_check.hpp"
#include "support/parameter_lists.hpp"
#include "support/reference_cells.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_Tuple.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

using testing::HasSubstr;

namespace
{
using kiln::Point;
using Vector = kiln::NonlinearProblem::Vector;
using Matrix = kiln::NonlinearProblem::Matrix;

constexpr double sigma = 5.670374419e-8;
constexpr double eps = 0.8, T_amb = 300.0;
const std::string where = "test.xml: Kiln/Thermal/Boundary Conditions";

kiln::Mesh box()
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  p.set("Size", Teuchos::Array<double>(Teuchos::tuple(0.1, 0.02, 0.02)));
  p.set("Cells", Teuchos::Array<int>(Teuchos::tuple(4, 1, 1)));
  return kiln::BoxMeshGenerator(p, "test/Box").generate();
}

Teuchos::ParameterList radiation(const Teuchos::Array<int> &side_sets)
{
  Teuchos::ParameterList p;
  p.set("Type", "Radiation");
  p.set("Side Sets", side_sets);
  p.set("Emissivity", eps);
  p.set("Ambient Temperature", kiln_test::constant_function(T_amb));
  return p;
}

/// The condition read from a "Boundary Conditions" list holding `user` as sublist "hot".
std::unique_ptr<kiln::BoundaryCondition> read(const kiln::Mesh &mesh,
                                              const Teuchos::ParameterList &user)
{
  Teuchos::ParameterList thermal;
  thermal.sublist("Boundary Conditions").set("hot", user);
  const Teuchos::ParameterList p = kiln::validated(
      thermal, kiln::ThermalPhysics::valid_parameters(), "test.xml", "Kiln/Thermal");
  auto conditions = kiln::read_boundary_conditions(
      kiln::thermal_conditions(), p.sublist("Boundary Conditions"), mesh,
      kiln::InteriorFaceCheck(mesh), where, "heat crosses it through the gap");
  return std::move(conditions.front());
}

std::string error(const kiln::Mesh &mesh, const Teuchos::ParameterList &user)
{
  return kiln_test::input_error_message([&] { read(mesh, user); });
}

/// The face terms of `condition` on a parallelogram at nodal temperatures T.
kiln::LocalSystem face_terms(const kiln::BoundaryCondition &condition,
                             const std::array<double, 4> &T)
{
  const kiln::QuadNodes x = {Point{0.1, 0.2, 0.3}, Point{0.13, 0.21, 0.3}, Point{0.14, 0.24, 0.31},
                             Point{0.11, 0.23, 0.31}};
  kiln::FaceValues fv;
  kiln_test::reinit(fv, x);
  const std::array<Point, 4> u{};
  kiln::LocalSystem local(4, 1);
  condition.evaluate(kiln::FaceState{fv, T, u, 0.0, kiln::FieldSlots{0, -1}}, local);
  return local;
}
} // namespace

TEST(RadiationCondition, FaceTermsAreTheExactIntegralsAtAUniformTemperature)
{
  const kiln::Mesh mesh = box();
  const auto condition = read(mesh, radiation(Teuchos::Array<int>(1, 2)));
  const double T = 700.0;
  const kiln::LocalSystem local = face_terms(*condition, {T, T, T, T});
  // The parallelogram spanned by e1 = (0.03, 0.01, 0) and e2 = (0.01, 0.03, 0.01).
  const Point e1{0.03, 0.01, 0.0}, e2{0.01, 0.03, 0.01};
  const Point n{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                e1[0] * e2[1] - e1[1] * e2[0]};
  const double area = std::sqrt(kiln::dot(n, n));
  const double flux = eps * sigma * (std::pow(T, 4) - std::pow(T_amb, 4));
  const double dflux = 4.0 * eps * sigma * std::pow(T, 3);
  for (int i = 0; i < 4; ++i)
  {
    EXPECT_NEAR(local.residual_values()[i], flux * area / 4.0, 1e-13 * flux * area);
    for (int j = 0; j < 4; ++j)
    {
      // The bilinear mass matrix of a parallelogram: A/9, A/18 along an edge, A/36 across.
      const int apart = std::abs(i - j);
      const double mass = area * (i == j ? 1.0 / 9.0 : apart == 2 ? 1.0 / 36.0 : 1.0 / 18.0);
      EXPECT_NEAR(local.jacobian_values()[4 * i + j], dflux * mass, 1e-13 * dflux * area);
    }
  }
}

TEST(RadiationCondition, LocalJacobianMatchesFiniteDifferences)
{
  const kiln::Mesh mesh = box();
  const auto condition = read(mesh, radiation(Teuchos::Array<int>(1, 2)));
  const std::array<double, 4> T = {450.0, 610.0, 820.0, 530.0};
  const kiln::LocalSystem local = face_terms(*condition, T);
  const kiln_test::Dense fd = kiln_test::finite_difference_jacobian(
      [&](const std::vector<double> &state) {
        return face_terms(*condition, {state[0], state[1], state[2], state[3]}).residual_values();
      },
      {T.begin(), T.end()}, 1e-3);
  const double worst = kiln_test::max_difference(kiln_test::local_jacobian(local), fd);
  const double largest = kiln_test::max_abs(fd);
  EXPECT_LT(worst, 1e-8 * largest);
  // A residual-only system gets the same residual and no Jacobian.
  kiln::FaceValues fv;
  kiln_test::reinit(fv, kiln::QuadNodes{Point{0.1, 0.2, 0.3}, Point{0.13, 0.21, 0.3},
                                        Point{0.14, 0.24, 0.31}, Point{0.11, 0.23, 0.31}});
  kiln::LocalSystem residual_only(4, 1, false);
  const std::array<Point, 4> u{};
  condition->evaluate(kiln::FaceState{fv, T, u, 0.0, kiln::FieldSlots{0, -1}}, residual_only);
  EXPECT_EQ(residual_only.residual_values(), local.residual_values());
  EXPECT_TRUE(residual_only.jacobian_values().empty());
}

namespace
{
/// A rotated bar, 0.1 m along its x axis, split in the middle (side set 10) by a gap of
/// conductance 1e4 W/(m^2 K): T0 on side set 1, radiation on side set 2, conductivity k;
/// steady.
std::unique_ptr<kiln::Simulation> bar(const double T0, const double k)
{
  const std::string xml = R"xml(
<ParameterList name="Kiln">
  <Parameter name="Physics" type="string" value="Heat Conduction"/>
  <ParameterList name="Mesh">
    <Parameter name="Gap Side Set" type="int" value="10"/>
    <ParameterList name="Box">
      <Parameter name="Size" type="Array(double)" value="{0.1, 0.02, 0.02}"/>
      <Parameter name="Cells" type="Array(int)" value="{4, 2, 2}"/>
      <Parameter name="Phi" type="double" value="30"/>
      <Parameter name="Theta" type="double" value="-20"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Material">
    <ParameterList name="Conductivity">
      <Parameter name="Type" type="string" value="Constant"/>
      <Parameter name="Value" type="double" value=")xml" +
                          std::to_string(k) + R"xml("/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Thermal">
    <Parameter name="Initial Temperature" type="double" value="500"/>
    <Parameter name="Gap Conductance" type="double" value="1e4"/>
    <ParameterList name="Boundary Conditions">
      <ParameterList name="held end">
        <Parameter name="Type" type="string" value="Temperature"/>
        <Parameter name="Side Sets" type="Array(int)" value="{1}"/>
        <ParameterList name="Temperature">
          <Parameter name="Value" type="double" value=")xml" +
                          std::to_string(T0) + R"xml("/>
        </ParameterList>
      </ParameterList>
      <ParameterList name="radiating end">
        <Parameter name="Type" type="string" value="Radiation"/>
        <Parameter name="Side Sets" type="Array(int)" value="{2}"/>
        <Parameter name="Emissivity" type="double" value="0.8"/>
        <ParameterList name="Ambient Temperature">
          <Parameter name="Value" type="double" value="300"/>
        </ParameterList>
      </ParameterList>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Time Stepping">
    <Parameter name="Method" type="string" value="Steady"/>
  </ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Absolute Tolerance" type="double" value="1e-12"/>
    <Parameter name="Relative Tolerance" type="double" value="1e-14"/>
  </ParameterList>
</ParameterList>)xml";
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  auto sim = std::make_unique<kiln::Simulation>(*Teuchos::getParametersFromXmlString(xml),
                                                "test.xml", comm);
  sim->setup();
  return sim;
}
} // namespace

TEST(RadiationCondition, ProblemJacobianMatchesFiniteDifferences)
{
  const auto sim = bar(900.0, 15.0);
  kiln::CoupledProblem &problem = sim->problem();
  const auto map = problem.solution_map();
  Vector x(map), b(map), f(map);
  problem.set_time_derivative(0.0, 0.0, b);
  // A non-uniform state: T = 500 + 3000 s^2 along the bar's axis (s in [0, 0.1] m).
  const auto A = kiln::rotation_matrix(30.0, -20.0);
  for (const int n : sim->dofs().owned_nodes())
  {
    const Point &p = sim->mesh().coordinates[n];
    const double s = A[0][0] * p[0] + A[1][0] * p[1] + A[2][0] * p[2] + 0.05;
    x.replaceGlobalValue(sim->dofs().dof(n, kiln::Field::T), 500.0 + 3000.0 * s * s);
  }
  Matrix J(problem.jacobian_graph());
  problem.evaluate(x, &f, &J);
  const long long n_global = static_cast<long long>(map->getGlobalNumElements());
  const kiln_test::Dense rows = kiln_test::dense_rows(J, n_global);
  const kiln_test::Dense fd =
      kiln_test::finite_difference_rows(problem, x, [](kiln_test::GO) { return 1e-2; });
  const auto &comm = *map->getComm();
  double global_worst = 0.0, global_largest = 0.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, kiln_test::max_difference(rows, fd),
                     Teuchos::outArg(global_worst));
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, kiln_test::max_abs(fd),
                     Teuchos::outArg(global_largest));
  std::cout << "problem Jacobian with radiation: max |J - J_fd| = " << global_worst << " of "
            << global_largest << "\n";
  EXPECT_LT(global_worst, 1e-9 * global_largest);
}

TEST(RadiationCondition, SteadyBarIsTheAnalyticLinearProfile)
{
  const double T0 = 900.0, k = 15.0, L = 0.1, h = 1e4;
  // Ts from (T0 - Ts)/R = eps sigma (Ts^4 - T_amb^4), R = L/k + 1/h, by Newton.
  const double R = L / k + 1.0 / h;
  double Ts = 700.0;
  for (int it = 0; it < 50; ++it)
    Ts -= ((T0 - Ts) / R - eps * sigma * (std::pow(Ts, 4) - std::pow(T_amb, 4))) /
          (-1.0 / R - 4.0 * eps * sigma * std::pow(Ts, 3));
  const double q = (T0 - Ts) / R;
  const auto sim = bar(T0, k);
  kiln::CoupledProblem &problem = sim->problem();
  Vector x(problem.solution_map()), b(problem.solution_map());
  problem.initial_condition(0.0, x);
  problem.set_time_derivative(0.0, 0.0, b);
  const kiln::NewtonSolver::Result r = sim->newton_solver().solve(x);
  ASSERT_TRUE(r.converged);
  EXPECT_GE(r.newton_iterations, 3); // nonlinear
  const auto A = kiln::rotation_matrix(30.0, -20.0);
  const kiln::Mesh &mesh = sim->mesh();
  const auto position = [&](const Point &p)
  { return A[0][0] * p[0] + A[1][0] * p[1] + A[2][0] * p[2] + 0.5 * L; };
  // The nodes beyond the gap: those of cells in the far half (block 2).
  std::vector<char> beyond(mesh.n_nodes(), 0);
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (mesh.block_id[c] == 2)
      for (const int n : mesh.cell_nodes(c))
        beyond[n] = 1;
  const std::vector<double> T = problem.node_temperatures(x);
  const auto &owned = sim->dofs().owned_nodes();
  double worst = 0.0;
  for (std::size_t i = 0; i < owned.size(); ++i)
  {
    const double s = position(mesh.coordinates[owned[i]]);
    const double exact = T0 - q * s / k - (beyond[owned[i]] ? q / h : 0.0);
    worst = std::max(worst, std::abs(T[i] - exact));
  }
  std::cout << "steady radiating bar: Ts = " << Ts << " K, q = " << q << " W/m^2, max nodal error "
            << worst << " K\n";
  EXPECT_LT(worst, 1e-9 * T0);
  EXPECT_GT(T0 - Ts, 10.0); // the radiation matters
}

TEST(RadiationCondition, InputErrors)
{
  const kiln::Mesh mesh = box();
  const std::string path = where + "/hot/";

  Teuchos::ParameterList no_emissivity = radiation(Teuchos::Array<int>(1, 2));
  no_emissivity.remove("Emissivity");
  EXPECT_THAT(error(mesh, no_emissivity),
              HasSubstr(path + "\"Emissivity\": is required for Type \"Radiation\""));

  Teuchos::ParameterList too_large = radiation(Teuchos::Array<int>(1, 2));
  too_large.set("Emissivity", 1.5);
  EXPECT_THAT(error(mesh, too_large), HasSubstr("\"Emissivity\" = 1.5: must be in [0, 1]"));

  Teuchos::ParameterList no_ambient = radiation(Teuchos::Array<int>(1, 2));
  no_ambient.remove("Ambient Temperature");
  EXPECT_THAT(error(mesh, no_ambient),
              HasSubstr(path + "\"Ambient Temperature\": is required for Type \"Radiation\""));

  Teuchos::ParameterList coefficient = radiation(Teuchos::Array<int>(1, 2));
  coefficient.set("Coefficient", 10.0);
  EXPECT_THAT(error(mesh, coefficient),
              HasSubstr(path + "\"Coefficient\": applies to Type \"Convection\", not to Type "
                               "\"Radiation\""));
}
