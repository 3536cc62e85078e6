// Tests src/physics/heat/{heat_conduction,convection,heat_flux,gap_conductance}_kernel.cpp on
// one cell or one face against values computed here by hand: for affine (parallelepiped) cells
// and faces every integral is a product of the 1D integrals of linear functions, so the
// expected residuals and Jacobians are closed forms in the edge vectors. The Jacobians are
// also checked against central finite differences of the residual (with a k(T) table for the
// conduction kernel, so that the k'(T) term counts).
// KILN_TEST_NP: 1
#include "physics/heat/convection_kernel.hpp"
#include "physics/heat/gap_conductance_kernel.hpp"
#include "physics/heat/heat_conduction_kernel.hpp"
#include "physics/heat/heat_flux_kernel.hpp"

#include "base/parameters.hpp"
#include "discretization/element_values.hpp"
#include "discretization/face_values.hpp"
#include "discretization/local_system.hpp"
#include "mesh/hex_geometry.hpp"
#include "physics/materials/conductivity_model.hpp"
#include "support/jacobian_check.hpp"
#include "support/reference_cells.hpp"

#include <Teuchos_Array.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <vector>

namespace
{
using namespace kiln_test;
using kiln::Point;

/// ∫ ∇φ_i dΩ = det(A) A^{-T} ∫ ∇_ξ φ̂_i dξ = (1/4) Σ_d sign_d cof_d on a parallelepiped.
Point integral_of_gradient(const Edges &a, const int i)
{
  const Edges c = cofactor_columns(a);
  Point g{0, 0, 0};
  for (int d = 0; d < 3; ++d)
    for (int e = 0; e < 3; ++e)
      g[e] += 0.25 * sign(hex_corner[i][d]) * c[d][e];
  return g;
}

/// Consistent mass matrix ∫ φ_i φ_j dΩ of a parallelepiped: V Π_d mass_1d.
Dense mass_matrix(const Edges &a)
{
  Dense m(8, std::vector<double>(8));
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      m[i][j] = volume(a) * mass_1d(hex_corner[i][0], hex_corner[j][0]) *
                mass_1d(hex_corner[i][1], hex_corner[j][1]) *
                mass_1d(hex_corner[i][2], hex_corner[j][2]);
  return m;
}

/// Stiffness matrix ∫ ∇φ_i·∇φ_j dΩ of a parallelepiped: with ∇φ = A^{-T} ∇_ξ φ̂ and
/// A^{-T} = cof(A) / V, K_ij = (1/V) Σ_{d,e} (cof_d·cof_e) ∫ ∂_d φ̂_i ∂_e φ̂_j dξ.
Dense stiffness_matrix(const Edges &a)
{
  const Edges c = cofactor_columns(a);
  Dense k(8, std::vector<double>(8, 0.0));
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      for (int d = 0; d < 3; ++d)
        for (int e = 0; e < 3; ++e)
          k[i][j] += dot(c[d], c[e]) * reference_grad_grad(i, d, j, e) / volume(a);
  return k;
}

/// Consistent mass matrix ∫ φ_i φ_j dΓ of a parallelogram of area `area`.
Dense face_mass_matrix(const double area)
{
  Dense m(4, std::vector<double>(4));
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      m[i][j] = area * mass_1d(quad_corner[i][0], quad_corner[j][0]) *
                mass_1d(quad_corner[i][1], quad_corner[j][1]);
  return m;
}

/// k = 100 W/(m K) at 250 K, 300 at 350 K, 150 at 450 K: slope 2 W/(m K^2) on (250, 350).
kiln::ConductivityModel table_conductivity()
{
  Teuchos::ParameterList user;
  user.set("Type", "Table");
  user.set("Temperatures", Teuchos::Array<double>({250.0, 350.0, 450.0}));
  user.set("Values", Teuchos::Array<double>({100.0, 300.0, 150.0}));
  const Teuchos::ParameterList p = kiln::validated(
      user, kiln::ConductivityModel::valid_parameters(), "test.xml", "Kiln/Material");
  return kiln::ConductivityModel(p, "test.xml: Kiln/Material/Conductivity");
}

const Edges unit_edges = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

/// An orthonormal pair (e1 x e2 = (2, -2, 1)/3) for rotated faces.
const Point u1{1.0 / 3, 2.0 / 3, 2.0 / 3};
const Point u2{2.0 / 3, 1.0 / 3, -2.0 / 3};

using NodalValues = std::array<double, 8>;
constexpr auto consistent = kiln::HeatConductionKernel::Capacity::consistent;
constexpr auto lumped = kiln::HeatConductionKernel::Capacity::lumped;

std::vector<double> conduction_residual(const kiln::HeatConductionKernel &kernel,
                                        const kiln::ElementValues &fe, const NodalValues &T,
                                        const NodalValues &T_dot, const double a)
{
  kiln::LocalSystem local(8, 1);
  kernel.evaluate(fe, T, T_dot, a, local);
  return local.residual_values();
}
} // namespace

TEST(HeatConductionKernel, LinearFieldGivesTheBoundaryFluxIntegral)
{
  // T = T0 + g·x, T_dot = 0: R_i = ∫ k g·∇φ_i dΩ = k g·∫∇φ_i dΩ (∇T constant), which for a
  // parallelepiped is (k/4) g·Σ_d sign_d cof_d.
  const double k = 3.5, rho_c = 2.0e6;
  const kiln::HeatConductionKernel kernel(rho_c, kiln::ConductivityModel::constant(k), consistent);
  const Point g{7.0, -3.0, 11.0};
  for (const auto &[edges, origin] :
       {std::pair{unit_edges, Point{0, 0, 0}}, std::pair{skew_edges, skew_origin}})
  {
    const kiln::HexNodes x = parallelepiped(edges, origin);
    kiln::ElementValues fe;
    kiln_test::reinit(fe, x);
    NodalValues T{}, T_dot{};
    for (int i = 0; i < 8; ++i)
      T[i] = 300.0 + dot(g, x[i]);
    kiln::LocalSystem local(8, 1);
    kernel.evaluate(fe, T, T_dot, 5.0, local);
    double sum = 0.0;
    for (int i = 0; i < 8; ++i)
    {
      const double expected = k * dot(g, integral_of_gradient(edges, i));
      EXPECT_NEAR(local.residual(0, i), expected, 1e-12 * k * std::sqrt(dot(g, g))) << "node " << i;
      sum += local.residual(0, i);
    }
    EXPECT_NEAR(sum, 0.0, 1e-12 * k * std::sqrt(dot(g, g)));
  }
  // The unit cube in words: node 6 at (1, 1, 1) gets k (g_x + g_y + g_z) / 4.
  kiln::ElementValues fe;
  kiln_test::reinit(fe, parallelepiped(unit_edges, {0, 0, 0}));
  NodalValues T{}, T_dot{};
  for (int i = 0; i < 8; ++i)
    T[i] = g[0] * hex_corner[i][0] + g[1] * hex_corner[i][1] + g[2] * hex_corner[i][2];
  kiln::LocalSystem local(8, 1);
  kernel.evaluate(fe, T, T_dot, 0.0, local);
  EXPECT_NEAR(local.residual(0, 6), k * (7.0 - 3.0 + 11.0) / 4, 1e-12);
  EXPECT_NEAR(local.residual(0, 0), -k * (7.0 - 3.0 + 11.0) / 4, 1e-12);
}

TEST(HeatConductionKernel, MassTermIntegratesTheRateOfChange)
{
  const double rho_c = 2.43e6;
  const kiln::HeatConductionKernel kernel(rho_c, kiln::ConductivityModel::constant(240.0),
                                          consistent);
  const double V = volume(skew_edges);
  ASSERT_GT(V, 0.5);
  kiln::ElementValues fe;
  kiln_test::reinit(fe, parallelepiped(skew_edges, skew_origin));

  // T = 0, T_dot = 1: R_i = rho_c ∫φ_i = rho_c V / 8, Σ R_i = rho_c V.
  NodalValues T{}, T_dot{};
  T_dot.fill(1.0);
  kiln::LocalSystem local(8, 1);
  kernel.evaluate(fe, T, T_dot, 0.0, local);
  double sum = 0.0;
  for (int i = 0; i < 8; ++i)
  {
    EXPECT_NEAR(local.residual(0, i), rho_c * V / 8, 1e-12 * rho_c * V) << "node " << i;
    sum += local.residual(0, i);
  }
  EXPECT_NEAR(sum, rho_c * V, 1e-12 * rho_c * V);

  // A varying T_dot: R_i = rho_c Σ_j M_ij T_dot_j with the consistent mass matrix.
  const Dense M = mass_matrix(skew_edges);
  for (int i = 0; i < 8; ++i)
    T_dot[i] = 1.0 + 0.5 * i - 0.1 * i * i;
  local.clear();
  kernel.evaluate(fe, T, T_dot, 0.0, local);
  for (int i = 0; i < 8; ++i)
  {
    double expected = 0.0;
    for (int j = 0; j < 8; ++j)
      expected += rho_c * M[i][j] * T_dot[j];
    EXPECT_NEAR(local.residual(0, i), expected, 1e-12 * rho_c * V) << "node " << i;
  }
}

TEST(HeatConductionKernel, JacobianOfConstantConductivityIsMassPlusStiffness)
{
  // J = rho_c a M + k K: symmetric, rows summing to rho_c a ∫φ_i = rho_c a V / 8 (the
  // conduction rows sum to zero), and equal to the closed-form matrices of an affine cell.
  const double rho_c = 1.5e3, k = 40.0, a = 12.0;
  const kiln::HeatConductionKernel kernel(rho_c, kiln::ConductivityModel::constant(k), consistent);
  for (const auto &[edges, origin] :
       {std::pair{unit_edges, Point{0, 0, 0}}, std::pair{skew_edges, skew_origin}})
  {
    kiln::ElementValues fe;
    kiln_test::reinit(fe, parallelepiped(edges, origin));
    NodalValues T{}, T_dot{};
    for (int i = 0; i < 8; ++i)
    {
      T[i] = 300 + 3 * i;
      T_dot[i] = 1 - 0.2 * i;
    }
    kiln::LocalSystem local(8, 1);
    kernel.evaluate(fe, T, T_dot, a, local);
    const Dense J = local_jacobian(local);
    const Dense M = mass_matrix(edges), K = stiffness_matrix(edges);
    const double V = volume(edges), scale = max_abs(J);
    ASSERT_GT(scale, 0.0);
    for (int i = 0; i < 8; ++i)
    {
      double row_sum = 0.0;
      for (int j = 0; j < 8; ++j)
      {
        EXPECT_NEAR(J[i][j], J[j][i], 1e-14 * scale) << "(" << i << ", " << j << ")";
        EXPECT_NEAR(J[i][j], rho_c * a * M[i][j] + k * K[i][j], 1e-13 * scale)
            << "(" << i << ", " << j << ")";
        row_sum += J[i][j];
      }
      EXPECT_NEAR(row_sum, rho_c * a * V / 8, 1e-13 * scale) << "row " << i;
    }
  }
  // The unit cube's diagonal: rho_c a / 27 + k / 3.
  kiln::ElementValues fe;
  kiln_test::reinit(fe, parallelepiped(unit_edges, {0, 0, 0}));
  NodalValues T{}, T_dot{};
  kiln::LocalSystem local(8, 1);
  kernel.evaluate(fe, T, T_dot, a, local);
  EXPECT_NEAR(local.jacobian(0, 3, 0, 3), rho_c * a / 27 + k / 3, 1e-12 * rho_c * a);
}

class HeatConductionKernelCapacity
    : public ::testing::TestWithParam<kiln::HeatConductionKernel::Capacity>
{
};

TEST_P(HeatConductionKernelCapacity, JacobianMatchesFiniteDifferencesWithTableConductivity)
{
  const kiln::HeatConductionKernel::Capacity capacity = GetParam();
  // k(T) from a table, every quadrature-point temperature in (290, 330) K, inside the
  // interval (250, 350) where k is linear: the residual is then quadratic in T and central
  // differences are exact up to rounding.
  const double rho_c = 100.0, a = 15.0;
  const kiln::HeatConductionKernel kernel(rho_c, table_conductivity(), capacity);
  kiln::ElementValues fe;
  const kiln::HexNodes x = parallelepiped(skew_edges, skew_origin);
  kiln_test::reinit(fe, x);
  NodalValues T{}, T_dot{};
  for (int i = 0; i < 8; ++i)
  {
    T[i] = 310.0 + 8.0 * (x[i][0] - skew_origin[0]) - 6.0 * (x[i][2] - skew_origin[2]) +
           5.0 * std::sin(1.3 * i + 0.4);
    ASSERT_GT(T[i], 290.0);
    ASSERT_LT(T[i], 330.0);
    T_dot[i] = 2.0 - 0.7 * i;
  }
  kiln::LocalSystem local(8, 1);
  kernel.evaluate(fe, T, T_dot, a, local);
  const Dense J = local_jacobian(local);

  // T_dot = a T + b moves with T: keep b = T_dot - a T fixed.
  NodalValues b{};
  for (int i = 0; i < 8; ++i)
    b[i] = T_dot[i] - a * T[i];
  const auto residual = [&](const std::vector<double> &Tv)
  {
    NodalValues Tn{}, Tn_dot{};
    for (int i = 0; i < 8; ++i)
    {
      Tn[i] = Tv[i];
      Tn_dot[i] = a * Tv[i] + b[i];
    }
    return conduction_residual(kernel, fe, Tn, Tn_dot, a);
  };
  const Dense fd =
      finite_difference_jacobian(residual, std::vector<double>(T.begin(), T.end()), 1e-3);
  const double scale = max_abs(J);
  const double difference = max_difference(J, fd);
  EXPECT_LT(difference, 1e-8 * scale);
  std::cout << "HeatConductionKernel: max |J - J_fd| / max |J| = " << difference / scale << "\n";

  // The k'(T) φ_j ∇T·∇φ_i term makes J unsymmetric; it is far above the tolerance, so the
  // check above would catch it missing.
  double asymmetry = 0.0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      asymmetry = std::max(asymmetry, std::abs(J[i][j] - J[j][i]));
  EXPECT_GT(asymmetry, 1e-3 * scale);
}

INSTANTIATE_TEST_SUITE_P(ConsistentAndLumped, HeatConductionKernelCapacity,
                         ::testing::Values(consistent, lumped));

TEST(HeatConductionKernel, LumpedCapacityIsTheRowSumOfTheConsistentOne)
{
  // Lumped: R_i = rho_c T_dot_i Σ_j M_ij (= rho_c T_dot_i ∫φ_i), J = rho_c a diag(Σ_j M_ij) +
  // k K, on a skewed cell where the rows of M differ; the consistent kernel differs from it
  // (so the check could fail).
  const double rho_c = 2.43e6, k = 40.0, a = 7.0;
  const kiln::HeatConductionKernel kernel(rho_c, kiln::ConductivityModel::constant(k), lumped);
  const kiln::HeatConductionKernel full(rho_c, kiln::ConductivityModel::constant(k), consistent);
  EXPECT_EQ(kernel.capacity(), lumped);
  kiln::ElementValues fe;
  kiln_test::reinit(fe, parallelepiped(skew_edges, skew_origin));
  const Dense M = mass_matrix(skew_edges), K = stiffness_matrix(skew_edges);
  const double V = volume(skew_edges);
  NodalValues T{}, T_dot{};
  for (int i = 0; i < 8; ++i)
    T_dot[i] = 1.0 + 0.5 * i - 0.1 * i * i;
  kiln::LocalSystem local(8, 1), local_full(8, 1);
  kernel.evaluate(fe, T, T_dot, a, local);
  full.evaluate(fe, T, T_dot, a, local_full);
  const Dense J = local_jacobian(local);
  double largest_difference = 0.0;
  for (int i = 0; i < 8; ++i)
  {
    double row_sum = 0.0;
    for (int j = 0; j < 8; ++j)
      row_sum += M[i][j];
    EXPECT_NEAR(local.residual(0, i), rho_c * T_dot[i] * row_sum, 1e-12 * rho_c * V)
        << "node " << i;
    largest_difference =
        std::max(largest_difference, std::abs(local.residual(0, i) - local_full.residual(0, i)));
    for (int j = 0; j < 8; ++j)
      EXPECT_NEAR(J[i][j], (i == j ? rho_c * a * row_sum : 0.0) + k * K[i][j],
                  1e-12 * rho_c * a * V)
          << "(" << i << ", " << j << ")";
  }
  EXPECT_GT(largest_difference, 1e-3 * rho_c * V);
}

TEST(ConvectionKernel, RectangleAtUniformTemperature)
{
  // An a x b rectangle in a rotated plane; h (T0 - T_amb) a b in total, a quarter per node.
  const double a = 2.0, b = 0.5, h = 25.0, T0 = 350.0, T_amb = 300.0;
  kiln::FaceValues fv;
  kiln_test::reinit(fv, parallelogram(scaled(a, u1), scaled(b, u2), {1.0, -2.0, 0.5}));
  const kiln::ConvectionKernel kernel(h);
  kiln::LocalSystem local(4, 1);
  kernel.evaluate(fv, std::array<double, 4>{T0, T0, T0, T0}, T_amb, local);
  double sum = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    EXPECT_NEAR(local.residual(0, i), h * (T0 - T_amb) * a * b / 4, 1e-12 * h * T0 * a * b);
    sum += local.residual(0, i);
  }
  EXPECT_NEAR(sum, h * (T0 - T_amb) * a * b, 1e-12 * h * T0 * a * b);

  // Jacobian = h times the face mass matrix (diagonal ab/9, edge ab/18, across ab/36).
  const Dense J = local_jacobian(local), M = face_mass_matrix(a * b);
  double total = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
    {
      EXPECT_NEAR(J[i][j], h * M[i][j], 1e-13 * h * a * b) << "(" << i << ", " << j << ")";
      total += J[i][j];
    }
  EXPECT_NEAR(total, h * a * b, 1e-12 * h * a * b);
  EXPECT_NEAR(J[0][0], h * a * b / 9, 1e-13 * h * a * b);
  EXPECT_NEAR(J[0][2], h * a * b / 36, 1e-13 * h * a * b);

  // A varying T: R_i = h Σ_j M_ij (T_j - T_amb).
  const std::array<double, 4> T{310.0, 340.0, 295.0, 305.0};
  local.clear();
  kernel.evaluate(fv, T, T_amb, local);
  for (int i = 0; i < 4; ++i)
  {
    double expected = 0.0;
    for (int j = 0; j < 4; ++j)
      expected += h * M[i][j] * (T[j] - T_amb);
    EXPECT_NEAR(local.residual(0, i), expected, 1e-12 * h * T0 * a * b) << "node " << i;
  }
}

TEST(HeatFluxKernel, TotalIsMinusFluxTimesArea)
{
  // A parallelogram with sides e1 and e2: area |e1 x e2|, a quarter of -q A per node.
  const Point e1{0.3, 0.0, 0.1}, e2{0.05, 0.2, -0.1};
  const double area = std::sqrt(dot(cross(e1, e2), cross(e1, e2)));
  const double q = 1.5e4;
  kiln::FaceValues fv;
  kiln_test::reinit(fv, parallelogram(e1, e2, {0.0, 1.0, 0.0}));
  kiln::LocalSystem local(4, 1);
  kiln::HeatFluxKernel::evaluate(fv, q, local);
  double sum = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    EXPECT_NEAR(local.residual(0, i), -q * area / 4, 1e-12 * q * area) << "node " << i;
    sum += local.residual(0, i);
  }
  EXPECT_NEAR(sum, -q * area, 1e-12 * q * area);
  for (const double v : local.jacobian_values())
    EXPECT_EQ(v, 0.0);
}

TEST(HeatFluxKernel, FluxVaryingInSpaceIsIntegratedAtTheGaussPoints)
{
  // q = a + b.x on a unit square in the plane z = 0: ∫ q φ_i is exact at 2x2 Gauss points
  // (a bilinear integrand), ∫ q φ_0 over [0,1]^2 with φ_0 = (1-x)(1-y):
  // a/4 + b_x/12 + b_y/12; the total is a + (b_x + b_y)/2.
  Teuchos::ParameterList user;
  user.set("Type", "Expression");
  user.set("Expression", "100 + 12*x - 24*y");
  const kiln::TimeFunction q(
      kiln::validated(user, kiln::TimeFunction::valid_parameters(), "in.xml", "Kiln/q"),
      "in.xml: Kiln/q");
  kiln::FaceValues fv;
  kiln_test::reinit(fv, parallelogram({1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 0.0}));
  kiln::LocalSystem local(4, 1);
  kiln::HeatFluxKernel::evaluate(fv, kiln::ValueAt(q, 0.0), local);
  double sum = 0.0;
  for (int i = 0; i < 4; ++i)
    sum += local.residual(0, i);
  EXPECT_NEAR(sum, -(100.0 + (12.0 - 24.0) / 2), 1e-12);
  // Each node (X, Y) in {0, 1}^2: ∫ q φ = a/4 + b_x (1 + X)/12 + b_y (1 + Y)/12.
  for (int i = 0; i < 4; ++i)
  {
    const double X = quad_corner[i][0], Y = quad_corner[i][1];
    EXPECT_NEAR(local.residual(0, i), -(100.0 / 4 + 12.0 * (1 + X) / 12 - 24.0 * (1 + Y) / 12),
                1e-12)
        << "node " << i;
  }
}

TEST(GapConductanceKernel, EqualTemperaturesGiveExactlyZero)
{
  kiln::FaceValues fv;
  kiln_test::reinit(fv, parallelogram(scaled(0.02, u1), scaled(0.01, u2), {0.0, 0.0, 0.0}));
  const kiln::GapConductanceKernel kernel(1.0e4);
  const std::array<double, 4> T{301.3, 288.7, 315.2, 296.1};
  kiln::LocalSystem local(8, 1);
  kernel.evaluate(fv, T, T, local);
  for (int i = 0; i < 8; ++i)
    EXPECT_EQ(local.residual(0, i), 0.0) << "node " << i;
}

TEST(GapConductanceKernel, UniformJumpGivesOppositeFluxes)
{
  const double a = 0.02, b = 0.01, h = 1.0e4, jump = 7.5;
  kiln::FaceValues fv;
  kiln_test::reinit(fv, parallelogram(scaled(a, u1), scaled(b, u2), {0.1, 0.2, 0.3}));
  const kiln::GapConductanceKernel kernel(h);
  kiln::LocalSystem local(8, 1);
  kernel.evaluate(fv, std::array<double, 4>{300 + jump, 300 + jump, 300 + jump, 300 + jump},
                  std::array<double, 4>{300, 300, 300, 300}, local);
  const double total = h * jump * a * b;
  double side_a = 0.0, side_b = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    EXPECT_NEAR(local.residual(0, i), total / 4, 1e-12 * total) << "node " << i;
    EXPECT_NEAR(local.residual(0, 4 + i), -total / 4, 1e-12 * total) << "twin " << i;
    side_a += local.residual(0, i);
    side_b += local.residual(0, 4 + i);
  }
  EXPECT_NEAR(side_a, total, 1e-12 * total);
  EXPECT_NEAR(side_b, -total, 1e-12 * total);
}

TEST(GapConductanceKernel, ConservativeAndJacobianMatchesFiniteDifferences)
{
  const double a = 0.02, b = 0.01, h = 1.0e4;
  kiln::FaceValues fv;
  kiln_test::reinit(fv, parallelogram(scaled(a, u1), scaled(b, u2), {0.1, 0.2, 0.3}));
  const kiln::GapConductanceKernel kernel(h);
  const auto residual = [&](const std::vector<double> &T)
  {
    kiln::LocalSystem local(8, 1);
    kernel.evaluate(fv, std::array<double, 4>{T[0], T[1], T[2], T[3]},
                    std::array<double, 4>{T[4], T[5], T[6], T[7]}, local);
    return local.residual_values();
  };
  const std::vector<double> T{305.0, 298.0, 311.0, 300.5, 299.0, 301.0, 290.0, 303.0};
  const std::vector<double> R = residual(T);
  double sum = 0.0, size = 0.0;
  for (const double r : R)
  {
    sum += r;
    size = std::max(size, std::abs(r));
  }
  ASSERT_GT(size, 0.0);
  EXPECT_NEAR(sum, 0.0, 1e-13 * size);

  kiln::LocalSystem local(8, 1);
  kernel.evaluate(fv, std::array<double, 4>{T[0], T[1], T[2], T[3]},
                  std::array<double, 4>{T[4], T[5], T[6], T[7]}, local);
  const Dense J = local_jacobian(local);
  const Dense fd = finite_difference_jacobian(residual, T, 1e-3);
  const double scale = max_abs(J);
  EXPECT_LT(max_difference(J, fd), 1e-8 * scale);

  // In closed form: h [M -M; -M M] with the face mass matrix M.
  const Dense M = face_mass_matrix(a * b);
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
    {
      const double s = (i < 4) == (j < 4) ? 1.0 : -1.0;
      EXPECT_NEAR(J[i][j], s * h * M[i % 4][j % 4], 1e-13 * scale) << "(" << i << ", " << j << ")";
    }
}
