// Tests src/physics/heat/block_heat_conduction_kernel.cpp and the enthalpy path of
// heat_conduction_kernel.cpp, src/physics/materials/enthalpy.cpp: H(T) = ∫ rho c dT of tables
// (exact: a product of linear functions integrated in closed form here), of formulas and of
// constants; two cells of two blocks whose materials give k(T), rho(T) and c(T) as tables and
// formulas, their Jacobians (lumped and consistent capacity, backward Euler and BDF2 weights)
// against central finite differences; the capacity term of a uniform cell is the change of H
// (conservation), and a constant material keeps the bit-for-bit constant path.
// KILN_TEST_NP: 1
#include "physics/heat/block_heat_conduction_kernel.hpp"

#include "base/parameters.hpp"
#include "discretization/element_values.hpp"
#include "discretization/local_system.hpp"
#include "mesh/hex_geometry.hpp"
#include "mesh/mesh.hpp"
#include "physics/materials/enthalpy.hpp"
#include "physics/materials/temperature_function.hpp"
#include "support/jacobian_check.hpp"
#include "support/reference_cells.hpp"

#include <Teuchos_Array.hpp>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using namespace kiln_test;
using Capacity = kiln::HeatConductionKernel::Capacity;

kiln::TemperatureFunction property(const Teuchos::ParameterList &user)
{
  const Teuchos::ParameterList p = kiln::validated(
      user, kiln::TemperatureFunction::valid_parameters(), "test.xml", "Kiln/Material/P");
  return kiln::TemperatureFunction(p, "test.xml: Kiln/Material/P");
}

kiln::TemperatureFunction table(const std::vector<double> &T, const std::vector<double> &values)
{
  Teuchos::ParameterList user;
  user.set("Type", "Table");
  user.set("Temperatures", Teuchos::Array<double>(T.begin(), T.end()));
  user.set("Values", Teuchos::Array<double>(values.begin(), values.end()));
  return property(user);
}

kiln::TemperatureFunction formula(const std::string &text, const std::vector<double> &samples)
{
  Teuchos::ParameterList user;
  user.set("Type", "Expression");
  user.set("Expression", text);
  user.set("Temperatures", Teuchos::Array<double>(samples.begin(), samples.end()));
  return property(user);
}

/// Material A: rho a table, c a formula, k a table. Material B: rho a formula, c a table,
/// k a formula. Slopes chosen so that each term is far above the finite differences' error.
kiln::HeatConductionKernel material_a(const Capacity capacity)
{
  return kiln::HeatConductionKernel(
      kiln::Enthalpy(table({250.0, 320.0, 400.0}, {2700.0, 2500.0, 2650.0}),
                     formula("900 + 2*(T - 300) + 0.01*(T - 300)^2", {250.0, 400.0})),
      table({250.0, 350.0}, {100.0, 300.0}), capacity);
}

kiln::HeatConductionKernel material_b(const Capacity capacity)
{
  return kiln::HeatConductionKernel(kiln::Enthalpy(formula("7900 - 3*(T - 300)", {250.0, 400.0}),
                                                   table({280.0, 340.0}, {450.0, 600.0})),
                                    formula("40 + 0.5*(T - 300)", {250.0, 400.0}), capacity);
}

using NodalValues = std::array<double, 8>;

/// The residual of `kernel` on the cell `cell` at T with the time history (T_dot = a T + b).
std::vector<double> residual_of(const kiln::CellKernel &kernel, const kiln::ElementValues &fe,
                                const int cell, const NodalValues &T, const double a,
                                const kiln::TemperatureHistory &history, const bool jacobian,
                                kiln::LocalSystem *out = nullptr)
{
  NodalValues T_dot{};
  for (int i = 0; i < 8; ++i)
  {
    T_dot[i] = a * T[i];
    for (int k = 0; k < history.n; ++k)
      T_dot[i] += history.weights[k] * history.T_past[k][i];
  }
  const std::array<kiln::Point, 8> u{};
  kiln::LocalSystem local(8, 1, jacobian);
  const kiln::CellState state{
      fe, {T.data(), 8}, {T_dot.data(), 8}, {u.data(), 8}, a, 0.0, {0, -1}, cell, cell, history};
  kernel.evaluate(state, local);
  if (out != nullptr)
    *out = local;
  return local.residual_values();
}
} // namespace

TEST(Enthalpy, TablesIntegrateExactly)
{
  // rho = 2 + 0.01 (T - 300) and c = 3 - 0.002 (T - 300) on [300, 400]: rho c a quadratic,
  // ∫_{300}^{T} = 6 s + (0.03 - 0.004) s^2 / 2 - 0.00002 s^3 / 3, s = T - 300; constant beyond.
  const kiln::Enthalpy H(table({300.0, 400.0}, {2.0, 3.0}), table({300.0, 400.0}, {3.0, 2.8}));
  EXPECT_FALSE(H.is_linear());
  const auto exact = [](const double s) { return 6 * s + 0.013 * s * s - 0.00002 * s * s * s / 3; };
  for (const double T : {300.0, 317.3, 350.0, 399.9})
    EXPECT_NEAR(H.value(T) - H.value(300.0), exact(T - 300.0), 1e-12 * H.value(T)) << T;
  // Beyond the tables rho c is constant: below 300 K 6, above 400 K 3 * 2.8.
  EXPECT_NEAR(H.value(280.0) - H.value(300.0), -6.0 * 20.0, 1e-10);
  EXPECT_NEAR(H.value(450.0) - H.value(400.0), 8.4 * 50.0, 1e-10);
  // dH/dT = rho c, also across breakpoints of either table.
  const kiln::Enthalpy kinked(table({250.0, 320.0, 400.0}, {2700.0, 2500.0, 2650.0}),
                              table({280.0, 340.0}, {450.0, 600.0}));
  for (const double T : {260.0, 300.0, 330.0, 390.0, 420.0})
  {
    const double h = 1e-3;
    const double fd = (kinked.value(T + h) - kinked.value(T - h)) / (2 * h);
    EXPECT_NEAR(fd, kinked.heat_capacity(T), 1e-7 * kinked.heat_capacity(T)) << T;
  }
}

TEST(Enthalpy, FormulasAndConstants)
{
  // rho c = 1000 (1 + 0.001 (T - 300)): ∫_{300}^{T} = 1000 s + 0.5 s^2, also beyond the
  // sample temperatures (panels of at most 10 K).
  const kiln::Enthalpy H(formula("1000*(1 + 0.001*(T - 300))", {300.0, 400.0}),
                         kiln::TemperatureFunction::constant(1.0));
  for (const double T : {250.0, 300.0, 333.3, 400.0, 520.0})
  {
    const double s = T - 300.0;
    EXPECT_NEAR(H.value(T) - H.value(300.0), 1000 * s + 0.5 * s * s, 1e-9 * H.value(T)) << T;
  }
  const kiln::Enthalpy smooth(formula("2e6*exp(-(T - 300)/200)", {250.0, 450.0}),
                              kiln::TemperatureFunction::constant(1.0));
  for (const double T : {255.0, 301.0, 449.0, 470.0})
  {
    const double exact =
        2e6 * 200.0 * (std::exp(-(250.0 - 300) / 200) - std::exp(-(T - 300) / 200));
    EXPECT_NEAR(smooth.value(T) - smooth.value(250.0), exact, 1e-11 * std::abs(smooth.value(T)))
        << T;
  }
  // A constant rho c: H = rho c T, linear.
  const kiln::Enthalpy constant = kiln::Enthalpy::constant(2.43e6);
  EXPECT_TRUE(constant.is_linear());
  EXPECT_EQ(constant.value(300.0), 2.43e6 * 300.0);
}

class BlockHeatConductionKernelCapacity : public ::testing::TestWithParam<Capacity>
{
};

TEST_P(BlockHeatConductionKernelCapacity, JacobianMatchesFiniteDifferencesOnTwoBlocks)
{
  const Capacity capacity = GetParam();
  // Two cells, of blocks 7 and 3, of materials A and B.
  kiln::Mesh mesh;
  mesh.block_id = {7, 3};
  const kiln::BlockHeatConductionKernel kernel(mesh, {material_a(capacity), material_b(capacity)},
                                               {{7, 0}, {3, 1}});
  EXPECT_FALSE(kernel.constant_jacobian());
  EXPECT_TRUE(kernel.needs_temperature_history());
  kiln::ElementValues fe;
  const kiln::HexNodes x = parallelepiped(skew_edges, skew_origin);
  kiln_test::reinit(fe, x);
  // Temperatures in (290, 335) K, across breakpoints of the tables (320, 340 K): the
  // slopes at the points are then those of one interval unless a point sits on a
  // breakpoint (not here); finite differences of 1e-4 K stay within the interval.
  NodalValues T{}, T_n{}, T_n1{};
  for (int i = 0; i < 8; ++i)
  {
    T[i] = 312.0 + 8.0 * (x[i][0] - skew_origin[0]) - 6.0 * (x[i][2] - skew_origin[2]) +
           5.0 * std::sin(1.3 * i + 0.4);
    T_n[i] = T[i] - 3.0 + std::cos(0.7 * i);
    T_n1[i] = T_n[i] - 2.5;
  }
  // Backward Euler (h = 0.1 s) and BDF2 (h = k = 0.1 s).
  const double h = 0.1;
  struct Method
  {
    std::string name;
    double a;
    kiln::TemperatureHistory history;
  };
  std::vector<Method> methods(2);
  methods[0].name = "backward Euler";
  methods[0].a = 1.0 / h;
  methods[0].history.n = 1;
  methods[0].history.weights = {-1.0 / h, 0.0};
  methods[0].history.T_past = {T_n.data(), nullptr};
  methods[1].name = "BDF2";
  methods[1].a = 1.5 / h;
  methods[1].history.n = 2;
  methods[1].history.weights = {-2.0 / h, 0.5 / h};
  methods[1].history.T_past = {T_n.data(), T_n1.data()};
  for (const Method &method : methods)
    for (const int cell : {0, 1})
    {
      kiln::LocalSystem local(8, 1);
      residual_of(kernel, fe, cell, T, method.a, method.history, true, &local);
      const Dense J = local_jacobian(local);
      const auto residual = [&](const std::vector<double> &Tv)
      {
        NodalValues Tn{};
        std::copy(Tv.begin(), Tv.end(), Tn.begin());
        return residual_of(kernel, fe, cell, Tn, method.a, method.history, false);
      };
      const Dense fd =
          finite_difference_jacobian(residual, std::vector<double>(T.begin(), T.end()), 1e-4);
      const double scale = max_abs(J);
      const double difference = max_difference(J, fd);
      EXPECT_LT(difference, 1e-7 * scale) << method.name << ", cell " << cell;
      std::cout << method.name << ", cell " << cell << " (block " << mesh.block_id[cell]
                << "): max |J - J_fd| / max |J| = " << difference / scale << "\n";
    }
}

TEST_P(BlockHeatConductionKernelCapacity, CapacityTermIsTheChangeOfEnthalpy)
{
  // A uniform cell (no conduction): Σ_i R_i = V (H(T) - H(T_n)) / h with backward Euler, for
  // either capacity; the two blocks' materials give their own H.
  const Capacity capacity = GetParam();
  kiln::Mesh mesh;
  mesh.block_id = {1, 2};
  const kiln::BlockHeatConductionKernel kernel(mesh, {material_a(capacity), material_b(capacity)},
                                               {{1, 0}, {2, 1}});
  kiln::ElementValues fe;
  kiln_test::reinit(fe, parallelepiped(skew_edges, skew_origin));
  NodalValues T{}, T_n{};
  T.fill(335.0);
  T_n.fill(301.0);
  const double h = 2.0;
  kiln::TemperatureHistory history;
  history.n = 1;
  history.weights = {-1.0 / h, 0.0};
  history.T_past = {T_n.data(), nullptr};
  for (const int cell : {0, 1})
  {
    const std::vector<double> R = residual_of(kernel, fe, cell, T, 1.0 / h, history, false);
    double sum = 0.0;
    for (const double r : R)
      sum += r;
    const kiln::Enthalpy &H = kernel.of_cell(cell).enthalpy();
    const double expected = volume(skew_edges) * (H.value(335.0) - H.value(301.0)) / h;
    EXPECT_NEAR(sum, expected, 1e-12 * std::abs(expected)) << cell;
  }
}

INSTANTIATE_TEST_SUITE_P(ConsistentAndLumped, BlockHeatConductionKernelCapacity,
                         ::testing::Values(Capacity::consistent, Capacity::lumped));

TEST(BlockHeatConductionKernel, ConstantMaterialKeepsTheConstantPath)
{
  // One constant material: the kernel is rho c Tdot (no history needed), bit for bit the
  // kernel of a number rho c.
  kiln::Mesh mesh;
  mesh.block_id = {1};
  const kiln::HeatConductionKernel by_number(2.43e6, kiln::ConductivityModel::constant(240.0),
                                             Capacity::lumped);
  const kiln::BlockHeatConductionKernel blocks(
      mesh,
      {kiln::HeatConductionKernel(kiln::Enthalpy(kiln::TemperatureFunction::constant(2700.0),
                                                 kiln::TemperatureFunction::constant(900.0)),
                                  kiln::ConductivityModel::constant(240.0), Capacity::lumped)},
      {{1, 0}});
  EXPECT_TRUE(blocks.constant_jacobian());
  EXPECT_FALSE(blocks.needs_temperature_history());
  kiln::ElementValues fe;
  kiln_test::reinit(fe, parallelepiped(skew_edges, skew_origin));
  NodalValues T{};
  for (int i = 0; i < 8; ++i)
    T[i] = 300.0 + 3.0 * i;
  NodalValues T_n = T;
  for (double &t : T_n)
    t -= 0.5;
  kiln::TemperatureHistory none;
  none.n = 1;
  none.weights = {-4.0, 0.0};
  none.T_past = {T_n.data(), nullptr};
  kiln::LocalSystem a(8, 1), b(8, 1);
  residual_of(blocks, fe, 0, T, 4.0, none, true, &a);
  residual_of(by_number, fe, 0, T, 4.0, none, true, &b);
  EXPECT_EQ(a.residual_values(), b.residual_values());
  EXPECT_EQ(max_difference(local_jacobian(a), local_jacobian(b)), 0.0);
}
