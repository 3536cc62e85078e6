// Tests src/physics/mechanics/{elasticity,traction}_kernel.cpp on one cell or one face: the
// Jacobian (displacement and temperature columns) against central finite differences of the
// residual on a distorted, rotated cell; the u-u block against closed-form integrals on an
// affine cell; patch tests with affine displacements (exact strain and Hooke stress, a rigid
// motion and a free thermal expansion give zero residual, a uniform stress gives the boundary
// integral of σn φ_i); the body-force and traction/pressure loads against V and A; and the
// slot arguments (3-field system without temperature, 4-field system with it).
// KILN_TEST_NP: 1
#include "physics/mechanics/elasticity_kernel.hpp"
#include "physics/mechanics/traction_kernel.hpp"

#include "discretization/element_values.hpp"
#include "discretization/face_values.hpp"
#include "discretization/local_system.hpp"
#include "mesh/hex_geometry.hpp"
#include "mesh/mesh.hpp"
#include "physics/materials/constitutive_models.hpp"
#include "physics/materials/linear_elastic_model.hpp"
#include "support/jacobian_check.hpp"
#include "support/reference_cells.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <memory>
#include <vector>

namespace
{
using namespace kiln_test;
using kiln::Point;
using Matrix = Matrix3;
using NodalDisplacements = std::array<kiln::Point, 8>;
using NodalValues = std::array<double, 8>;

/// Steel-like constants: E = 200 GPa, nu = 0.3.
const double youngs = 200.0e9, poisson = 0.3;
const double lambda = youngs * poisson / ((1 + poisson) * (1 - 2 * poisson));
const double G = youngs / (2 * (1 + poisson));
const double alpha = 1.2e-5, T_ref = 293.15;
/// β = (3λ + 2G) α = E α / (1 − 2ν) [Pa/K].
const double beta = youngs * alpha / (1 - 2 * poisson);

/// ∫ ∂_k φ_i ∂_l φ_j dΩ on a parallelepiped: with ∂_k φ = Σ_d cof_d[k] ∂_d φ̂ / V and
/// dΩ = V dξ, it is (1/V) Σ_{d,e} cof_d[k] cof_e[l] ∫ ∂_d φ̂_i ∂_e φ̂_j dξ.
double grad_grad_integral(const Edges &a, const int i, const int k, const int j, const int l)
{
  const Edges c = cofactor_columns(a);
  double value = 0.0;
  for (int d = 0; d < 3; ++d)
    for (int e = 0; e < 3; ++e)
      value += c[d][k] * c[e][l] * reference_grad_grad(i, d, j, e) / volume(a);
  return value;
}

/// ∫ φ_j ∂_k φ_i dΩ on a parallelepiped: Σ_e cof_e[k] ∫ φ̂_j ∂_e φ̂_i dξ.
double shape_grad_integral(const Edges &a, const int i, const int k, const int j)
{
  const Edges c = cofactor_columns(a);
  double value = 0.0;
  for (int e = 0; e < 3; ++e)
  {
    double reference = 1.0;
    for (int f = 0; f < 3; ++f)
      reference *=
          f == e ? 0.5 * sign(hex_corner[i][f]) : mass_1d(hex_corner[i][f], hex_corner[j][f]);
    value += c[e][k] * reference;
  }
  return value;
}

/// The skew cell with every node moved by up to ~0.1 (a non-affine, warped cell), then
/// rotated by Rx(40°) Ry(25°) and scaled to millimetres.
kiln::HexNodes distorted_cell()
{
  const kiln::HexNodes affine = parallelepiped(skew_edges, skew_origin);
  const auto rotation = kiln::rotation_matrix(25.0, 40.0);
  kiln::HexNodes x;
  for (int i = 0; i < 8; ++i)
  {
    Point moved;
    for (int d = 0; d < 3; ++d)
      moved[d] = affine[i][d] + 0.1 * std::sin(1.7 * i + 2.3 * d + 0.5);
    for (int d = 0; d < 3; ++d)
      x[i][d] = 1e-3 * dot(rotation[d], moved);
  }
  return x;
}

/// u = E x + c at the nodes.
NodalDisplacements affine_displacement(const kiln::HexNodes &x, const Matrix &E, const Point &c)
{
  NodalDisplacements u;
  for (int i = 0; i < 8; ++i)
  {
    const Point Ex = times(E, x[i]);
    for (int d = 0; d < 3; ++d)
      u[i][d] = Ex[d] + c[d];
  }
  return u;
}

/// The cell's residual in a fresh local system, its values in local-index order.
std::vector<double> residual_of(const kiln::ElasticityKernel &kernel, const kiln::ElementValues &fe,
                                const NodalDisplacements &u, const NodalValues &T, const Point &b,
                                const int u_slot, const int T_slot, const int n_fields)
{
  kiln::LocalSystem local(8, n_fields);
  kernel.evaluate(fe, u, T, b, u_slot, T_slot, local);
  return local.residual_values();
}

/// A non-symmetric displacement gradient of order 1e-3.
const Matrix gradient_E = {
    {{1.0e-3, -4.0e-4, 2.5e-4}, {6.0e-4, -7.0e-4, 3.0e-4}, {-2.0e-4, 9.0e-4, 5.0e-4}}};

/// The unknowns of the distorted cell's 8 nodes, (T, u_x, u_y, u_z) per node: T around
/// T_ref + 40 K, u a small wiggle plus `scale` times the affine gradient_E.
std::vector<double> cell_unknowns(const kiln::HexNodes &x, const double scale)
{
  std::vector<double> state(32);
  for (int i = 0; i < 8; ++i)
  {
    state[4 * i] = T_ref + 40.0 + 15.0 * std::sin(0.9 * i + 0.3);
    for (int d = 0; d < 3; ++d)
      state[4 * i + 1 + d] = 1e-6 * std::cos(1.3 * i - 0.7 * d) + scale * dot(gradient_E[d], x[i]);
  }
  return state;
}

/// The nodal u and T of cell_unknowns().
void unpack(const std::vector<double> &s, NodalDisplacements &u, NodalValues &T)
{
  for (int i = 0; i < 8; ++i)
  {
    T[i] = s[4 * i];
    for (int d = 0; d < 3; ++d)
      u[i][d] = s[4 * i + 1 + d];
  }
}

const kiln::ElasticityKernel kernel(lambda, G, alpha, T_ref);
} // namespace

TEST(ElasticityKernel, ConstructorKeepsTheConstants)
{
  EXPECT_EQ(kernel.lambda(), lambda);
  EXPECT_EQ(kernel.shear_modulus(), G);
  EXPECT_EQ(kernel.alpha(), alpha);
  EXPECT_EQ(kernel.reference_temperature(), T_ref);
}

TEST(ElasticityKernel, JacobianMatchesFiniteDifferencesOnADistortedCell)
{
  // 4-field local system, T in field 0 and u in fields 1-3 as in the coupled problem. The
  // residual is linear in (u, T), so central differences are exact up to rounding.
  const kiln::HexNodes x = distorted_cell();
  kiln::ElementValues fe;
  kiln_test::reinit(fe, x);
  const std::vector<double> state = cell_unknowns(x, 1e-3);
  const Point b{1.0e4, -2.0e4, 7.8e4};
  const auto residual = [&](const std::vector<double> &s)
  {
    NodalDisplacements u;
    NodalValues T;
    unpack(s, u, T);
    return residual_of(kernel, fe, u, T, b, 1, 0, 4);
  };

  NodalDisplacements u;
  NodalValues T;
  unpack(state, u, T);
  kiln::LocalSystem local(8, 4);
  kernel.evaluate(fe, u, T, b, 1, 0, local);
  const Dense J = local_jacobian(local);
  const Dense fd = finite_difference_jacobian(
      residual, state, [](const int c) { return c % 4 == 0 ? 1e-1 : 1e-7; }); // [K] or [m]

  // Relative errors of the u-u and the u-T blocks, each against its own size; the T rows are
  // the heat kernels' and must stay zero.
  double scale_u = 0.0, scale_T = 0.0, error_u = 0.0, error_T = 0.0;
  for (int r = 0; r < 32; ++r)
    for (int c = 0; c < 32; ++c)
    {
      if (r % 4 == 0)
      {
        EXPECT_EQ(J[r][c], 0.0) << "(" << r << ", " << c << ")";
        EXPECT_EQ(fd[r][c], 0.0) << "(" << r << ", " << c << ")";
        continue;
      }
      const double difference = std::abs(J[r][c] - fd[r][c]);
      if (c % 4 == 0)
      {
        scale_T = std::max(scale_T, std::abs(J[r][c]));
        error_T = std::max(error_T, difference);
      }
      else
      {
        scale_u = std::max(scale_u, std::abs(J[r][c]));
        error_u = std::max(error_u, difference);
      }
    }
  ASSERT_GT(scale_u, 0.0);
  ASSERT_GT(scale_T, 0.0);
  EXPECT_LT(error_u, 1e-8 * scale_u);
  EXPECT_LT(error_T, 1e-8 * scale_T);
  std::cout << "ElasticityKernel: max |J - J_fd| / max |J|: u columns " << error_u / scale_u
            << ", T columns " << error_T / scale_T << "\n";

  // The u-u block is symmetric.
  double asymmetry = 0.0;
  for (int r = 0; r < 32; ++r)
    for (int c = 0; c < 32; ++c)
      if (r % 4 != 0 && c % 4 != 0)
        asymmetry = std::max(asymmetry, std::abs(J[r][c] - J[c][r]));
  EXPECT_LT(asymmetry, 1e-14 * scale_u);
}

TEST(ElasticityKernel, JacobianEqualsClosedFormIntegralsOnAnAffineCell)
{
  //   dR_{i,d}/du_{j,e} = λ ∫∂_dφ_i ∂_eφ_j + G (δ_de ∫∇φ_i·∇φ_j + ∫∂_eφ_i ∂_dφ_j)
  //   dR_{i,d}/dT_j     = −β ∫ φ_j ∂_dφ_i
  // with the exact integrals of the parallelepiped (2x2x2 Gauss is exact there).
  const double V = volume(skew_edges);
  ASSERT_GT(V, 0.5);
  kiln::ElementValues fe;
  kiln_test::reinit(fe, parallelepiped(skew_edges, skew_origin));
  NodalDisplacements u{};
  NodalValues T{};
  T.fill(T_ref);
  kiln::LocalSystem local(8, 4);
  kernel.evaluate(fe, u, T, {0, 0, 0}, 1, 0, local);
  const double scale = max_abs(local_jacobian(local));
  double scale_T = 0.0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      for (int d = 0; d < 3; ++d)
      {
        for (int e = 0; e < 3; ++e)
        {
          double laplace = 0.0;
          for (int k = 0; k < 3; ++k)
            laplace += grad_grad_integral(skew_edges, i, k, j, k);
          const double expected =
              lambda * grad_grad_integral(skew_edges, i, d, j, e) +
              G * ((d == e ? laplace : 0.0) + grad_grad_integral(skew_edges, i, e, j, d));
          EXPECT_NEAR(local.jacobian(1 + d, i, 1 + e, j), expected, 1e-13 * scale)
              << "(" << i << ", " << d << "; " << j << ", " << e << ")";
        }
        const double expected_T = -beta * shape_grad_integral(skew_edges, i, d, j);
        scale_T = std::max(scale_T, std::abs(expected_T));
        EXPECT_NEAR(local.jacobian(1 + d, i, 0, j), expected_T, 1e-13 * beta * V)
            << "(" << i << ", " << d << "; T " << j << ")";
      }
  EXPECT_GT(scale_T, 0.0);

  // The unit cube's diagonal in words: (λ + G) ∫(∂_xφ)^2 + G ∫|∇φ|^2 = (λ + G)/9 + G/3.
  kiln_test::reinit(fe, parallelepiped({{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, 0}));
  kiln::LocalSystem cube(8, 3);
  kernel.evaluate(fe, u, T, {0, 0, 0}, 0, -1, cube);
  for (int i = 0; i < 8; ++i)
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(cube.jacobian(d, i, d, i), (lambda + 4 * G) / 9, 1e-13 * (lambda + 4 * G));
}

TEST(ElasticityKernel, AffineDisplacementGivesExactStrainAndHookeStress)
{
  // u = E x + c is in the Q1 space of any trilinear cell, so ε = sym(E) exactly at every
  // Gauss point; with uniform T the stress is uniform and R_{i,d} = σ_dk ∫∂_kφ_i dΩ, which
  // the divergence theorem turns into Σ_faces σ_dk ∫ φ_i n_k dA (face_nodal_areas).
  const double dT = 35.0;
  const Point c{2e-4, -1e-4, 3e-4};
  for (const kiln::HexNodes &x : {parallelepiped(skew_edges, skew_origin), distorted_cell()})
  {
    kiln::ElementValues fe;
    kiln_test::reinit(fe, x);
    const NodalDisplacements u = affine_displacement(x, gradient_E, c);
    NodalValues T;
    T.fill(T_ref + dT);
    const kiln::ElasticityKernel::CellAverages averages = kernel.cell_averages(fe, u, T);

    Matrix strain, stress;
    const double trace = gradient_E[0][0] + gradient_E[1][1] + gradient_E[2][2];
    for (int d = 0; d < 3; ++d)
      for (int k = 0; k < 3; ++k)
      {
        strain[d][k] = 0.5 * (gradient_E[d][k] + gradient_E[k][d]);
        stress[d][k] = 2 * G * strain[d][k] + (d == k ? lambda * trace - beta * dT : 0.0);
      }
    const double stress_scale = G * 1e-3;
    double strain_error = 0.0;
    for (int d = 0; d < 3; ++d)
      for (int k = d; k < 3; ++k)
      {
        const int v = voigt_index[d][k];
        strain_error = std::max(strain_error, std::abs(averages.strain[v] - strain[d][k]));
        EXPECT_NEAR(averages.stress[v], stress[d][k], 1e-12 * stress_scale) << d << k;
        EXPECT_NEAR(averages.thermal_strain[v], d == k ? alpha * dT : 0.0, 1e-15 * alpha * dT);
      }
    EXPECT_LT(strain_error, 1e-15);
    std::cout << "ElasticityKernel: affine u, max |mean strain - sym(E)| = " << strain_error
              << " (|E| ~ 1e-3)\n";

    // Independent of the Lamé form: the compliance of (E, ν) maps the stress back to the
    // mechanical strain ε − α ΔT I.
    const double mean_stress_trace = averages.stress[0] + averages.stress[1] + averages.stress[2];
    for (int d = 0; d < 3; ++d)
      for (int k = d; k < 3; ++k)
      {
        const double mechanical = ((1 + poisson) * averages.stress[voigt_index[d][k]] -
                                   (d == k ? poisson * mean_stress_trace : 0.0)) /
                                  youngs;
        EXPECT_NEAR(mechanical + (d == k ? alpha * dT : 0.0), strain[d][k], 1e-15) << d << k;
      }

    // The residual is the boundary integral of σ n φ_i.
    const std::vector<double> R = residual_of(kernel, fe, u, T, {0, 0, 0}, 0, -1, 3);
    std::array<Point, 8> boundary{};
    const kiln::ReferenceCell &hex = kiln::ReferenceCell::of(kiln::CellType::hex8);
    for (int f = 0; f < hex.n_faces(); ++f)
    {
      std::vector<Point> face;
      for (const int a : hex.face_nodes(f))
        face.push_back(x[a]);
      const kiln::FaceNodalAreas areas = kiln::face_nodal_areas(hex.face_type(f), face.data());
      for (std::size_t a = 0; a < face.size(); ++a)
        for (int d = 0; d < 3; ++d)
          boundary[hex.face_nodes(f)[a]][d] += dot(stress[d], areas.area_vector[a]);
    }
    const double R_scale = max_abs(R);
    ASSERT_GT(R_scale, 0.0);
    Point sum{0, 0, 0};
    for (int i = 0; i < 8; ++i)
      for (int d = 0; d < 3; ++d)
      {
        EXPECT_NEAR(R[3 * i + d], boundary[i][d], 1e-12 * R_scale) << "node " << i << ", " << d;
        sum[d] += R[3 * i + d];
      }
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(sum[d], 0.0, 1e-13 * R_scale);
  }
}

TEST(ElasticityKernel, RigidMotionGivesZeroStressAndResidual)
{
  // u = W x + c with W skew (an infinitesimal rotation) and T = T_ref: no strain.
  const Matrix W = {{{0.0, -3e-3, 2e-3}, {3e-3, 0.0, -1e-3}, {-2e-3, 1e-3, 0.0}}};
  const kiln::HexNodes x = distorted_cell();
  kiln::ElementValues fe;
  kiln_test::reinit(fe, x);
  const NodalDisplacements u = affine_displacement(x, W, {1e-4, 2e-4, -5e-5});
  NodalValues T;
  T.fill(T_ref);
  const std::vector<double> R = residual_of(kernel, fe, u, T, {0, 0, 0}, 0, -1, 3);
  // Scale: one displacement of the same size as a stretch instead, G |W| L^2.
  const double L = 1e-3, scale = G * 3e-3 * L * L;
  EXPECT_LT(max_abs(R), 1e-12 * scale);
  std::cout << "ElasticityKernel: rigid motion, max |R| / (G |W| L^2) = " << max_abs(R) / scale
            << "\n";
  const kiln::ElasticityKernel::CellAverages averages = kernel.cell_averages(fe, u, T);
  for (int v = 0; v < 6; ++v)
  {
    EXPECT_NEAR(averages.strain[v], 0.0, 1e-17) << v;
    EXPECT_NEAR(averages.stress[v], 0.0, 1e-12 * G * 3e-3) << v;
    EXPECT_EQ(averages.thermal_strain[v], 0.0) << v;
  }
}

TEST(ElasticityKernel, FreeThermalExpansionIsStressFree)
{
  // u = α ΔT (x − x0), T = T_ref + ΔT: ε = α ΔT I = the thermal strain, σ = 0, R = 0.
  const double dT = 120.0;
  const kiln::HexNodes x = distorted_cell();
  kiln::ElementValues fe;
  kiln_test::reinit(fe, x);
  Matrix expansion{};
  for (int d = 0; d < 3; ++d)
    expansion[d][d] = alpha * dT;
  const Point x0 = x[3];
  const NodalDisplacements u = affine_displacement(x, expansion, times(expansion, x0));
  NodalValues T;
  T.fill(T_ref + dT);
  const std::vector<double> R = residual_of(kernel, fe, u, T, {0, 0, 0}, 1, 0, 4);
  const double L = 1e-3, scale = beta * dT * L * L; // the residual of the blocked expansion
  EXPECT_LT(max_abs(R), 1e-12 * scale);
  std::cout << "ElasticityKernel: free expansion, max |R| / (β ΔT L^2) = " << max_abs(R) / scale
            << "\n";
  const kiln::ElasticityKernel::CellAverages averages = kernel.cell_averages(fe, u, T);
  for (int v = 0; v < 6; ++v)
  {
    const double expected = v < 3 ? alpha * dT : 0.0;
    EXPECT_NEAR(averages.strain[v], expected, 1e-15 * alpha * dT) << v;
    EXPECT_NEAR(averages.thermal_strain[v], expected, 1e-15 * alpha * dT) << v;
    EXPECT_NEAR(averages.stress[v], 0.0, 1e-12 * beta * dT) << v;
  }

  // The same cell with u = 0 (blocked): σ = −β ΔT I and the residual is −β ΔT ∫∇φ_i.
  const NodalDisplacements zero{};
  const kiln::ElasticityKernel::CellAverages blocked = kernel.cell_averages(fe, zero, T);
  for (int v = 0; v < 6; ++v)
    EXPECT_NEAR(blocked.stress[v], v < 3 ? -beta * dT : 0.0, 1e-13 * beta * dT) << v;
}

TEST(ElasticityKernel, ThermalStrainAverageOfAVaryingTemperature)
{
  // On a parallelepiped ∫φ_i = V/8, so the mean of α (T − T_ref) is α (mean of T_i − T_ref).
  kiln::ElementValues fe;
  kiln_test::reinit(fe, parallelepiped(skew_edges, skew_origin));
  NodalValues T;
  double mean = 0.0;
  for (int i = 0; i < 8; ++i)
  {
    T[i] = T_ref + 10.0 * i - 3.0 * i * i;
    mean += T[i] / 8;
  }
  const kiln::ElasticityKernel::CellAverages averages =
      kernel.cell_averages(fe, std::array<kiln::Point, 8>{}, T);
  for (int v = 0; v < 6; ++v)
  {
    const double expected = v < 3 ? alpha * (mean - T_ref) : 0.0;
    EXPECT_NEAR(averages.thermal_strain[v], expected, 1e-13 * alpha * 100) << v;
    EXPECT_NEAR(averages.stress[v], v < 3 ? -beta * (mean - T_ref) : 0.0, 1e-12 * beta * 100) << v;
  }
}

TEST(ElasticityKernel, BodyForceGivesMinusBTimesTheShapeIntegrals)
{
  // u = 0, T = T_ref: R_{i,d} = −b_d ∫φ_i, = −b_d V / 8 on a parallelepiped; Σ_i = −b_d V.
  const Point b{2.6e4, -9.81 * 7.8e3, 1.0e3};
  NodalValues T;
  T.fill(T_ref);
  const NodalDisplacements u{};
  {
    const double V = volume(skew_edges);
    kiln::ElementValues fe;
    kiln_test::reinit(fe, parallelepiped(skew_edges, skew_origin));
    kiln::LocalSystem local(8, 4);
    kernel.evaluate(fe, u, T, b, 1, 0, local);
    for (int i = 0; i < 8; ++i)
    {
      EXPECT_EQ(local.residual(0, i), 0.0);
      for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(local.residual(1 + d, i), -b[d] * V / 8, 1e-13 * norm(b) * V)
            << "node " << i << ", " << d;
    }
  }
  const kiln::HexNodes x = distorted_cell();
  const double V = kiln::hex_volume(x);
  kiln::ElementValues fe;
  kiln_test::reinit(fe, x);
  const std::vector<double> R = residual_of(kernel, fe, u, T, b, 0, -1, 3);
  for (int d = 0; d < 3; ++d)
  {
    double sum = 0.0;
    for (int i = 0; i < 8; ++i)
      sum += R[3 * i + d];
    EXPECT_NEAR(sum, -b[d] * V, 1e-13 * norm(b) * V) << d;
  }
}

TEST(ElasticityKernel, SlotsSelectTheFieldsWritten)
{
  // T_slot = −1, u_slot = 0: a 3-field system equal to the u rows and columns of the coupled
  // one (T_slot = 0, u_slot = 1); in a 4-field system field 3 is then left untouched.
  const kiln::HexNodes x = distorted_cell();
  kiln::ElementValues fe;
  kiln_test::reinit(fe, x);
  NodalDisplacements u = affine_displacement(x, gradient_E, {0, 0, 0});
  NodalValues T;
  for (int i = 0; i < 8; ++i)
  {
    T[i] = T_ref + 5.0 * i;
    u[i][1] += 1e-7 * i;
  }
  const Point b{1e3, 2e3, 3e3};
  kiln::LocalSystem coupled(8, 4), mechanical(8, 3), padded(8, 4);
  kernel.evaluate(fe, u, T, b, 1, 0, coupled);
  kernel.evaluate(fe, u, T, b, 0, -1, mechanical);
  kernel.evaluate(fe, u, T, b, 0, -1, padded);
  for (int i = 0; i < 8; ++i)
  {
    EXPECT_EQ(padded.residual(3, i), 0.0);
    for (int d = 0; d < 3; ++d)
    {
      EXPECT_EQ(mechanical.residual(d, i), coupled.residual(1 + d, i));
      EXPECT_EQ(padded.residual(d, i), coupled.residual(1 + d, i));
    }
    for (int j = 0; j < 8; ++j)
    {
      for (int f = 0; f < 4; ++f)
      {
        EXPECT_EQ(padded.jacobian(3, i, f, j), 0.0);
        EXPECT_EQ(padded.jacobian(f, i, 3, j), 0.0);
      }
      for (int d = 0; d < 3; ++d)
        for (int e = 0; e < 3; ++e)
        {
          EXPECT_EQ(mechanical.jacobian(d, i, e, j), coupled.jacobian(1 + d, i, 1 + e, j));
          EXPECT_EQ(padded.jacobian(d, i, e, j), coupled.jacobian(1 + d, i, 1 + e, j));
        }
    }
  }

  // T in the last slot (u_slot = 0, T_slot = 3): the same coupling block, moved.
  kiln::LocalSystem last(8, 4);
  kernel.evaluate(fe, u, T, b, 0, 3, last);
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      for (int d = 0; d < 3; ++d)
        EXPECT_EQ(last.jacobian(d, i, 3, j), coupled.jacobian(1 + d, i, 0, j));
}

TEST(TractionKernel, TotalIsMinusTractionTimesArea)
{
  // A parallelogram with sides e1 and e2: area |e1 x e2|, a quarter of −t A per node; the
  // load does not depend on u: no Jacobian. Field 0 (T) of the 4-field system stays zero.
  const Point e1{0.3, 0.0, 0.1}, e2{0.05, 0.2, -0.1};
  const double area = norm(cross(e1, e2));
  const Point t{1.0e6, -2.5e6, 4.0e5};
  kiln::FaceValues fv;
  kiln_test::reinit(fv, parallelogram(e1, e2, {0.0, 1.0, 0.0}));
  kiln::LocalSystem local(4, 4);
  kiln::TractionKernel::evaluate(fv, t, 1, local);
  Point sum{0, 0, 0};
  for (int i = 0; i < 4; ++i)
  {
    EXPECT_EQ(local.residual(0, i), 0.0);
    for (int d = 0; d < 3; ++d)
    {
      EXPECT_NEAR(local.residual(1 + d, i), -t[d] * area / 4, 1e-12 * norm(t) * area);
      sum[d] += local.residual(1 + d, i);
    }
  }
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(sum[d], -t[d] * area, 1e-12 * norm(t) * area);
  for (const double v : local.jacobian_values())
    EXPECT_EQ(v, 0.0);
}

TEST(TractionKernel, PressurePushesAgainstTheOutwardNormal)
{
  // Flat face: t = −p n, so Σ_i R_i = −(−p n) A = p n A with n = e1 x e2 / |e1 x e2|.
  const double p = 3.0e7;
  const Point e1{0.3, 0.0, 0.1}, e2{0.05, 0.2, -0.1};
  const Point area_vector = cross(e1, e2);
  const double area = norm(area_vector);
  kiln::FaceValues fv;
  kiln_test::reinit(fv, parallelogram(e1, e2, {0.0, 1.0, 0.0}));
  kiln::LocalSystem local(4, 3);
  kiln::TractionKernel::evaluate_pressure(fv, p, 0, local);
  for (int d = 0; d < 3; ++d)
  {
    double sum = 0.0;
    for (int i = 0; i < 4; ++i)
    {
      EXPECT_NEAR(local.residual(d, i), p * area_vector[d] / 4, 1e-12 * p * area);
      sum += local.residual(d, i);
    }
    EXPECT_NEAR(sum, p * area_vector[d], 1e-12 * p * area) << d;
  }
  for (const double v : local.jacobian_values())
    EXPECT_EQ(v, 0.0);

  // A warped face: per node R_i = p ∫ φ_i n dA, the node's share of the area vector.
  const kiln::QuadNodes warped{
      {{0.0, 0.0, 0.0}, {1.0, 0.1, 0.2}, {1.2, 0.9, -0.1}, {-0.1, 1.0, 0.3}}};
  kiln_test::reinit(fv, warped);
  const kiln::FaceNodalAreas shares = kiln::face_nodal_areas(kiln::CellType::quad4, warped.data());
  kiln::LocalSystem bent(4, 3);
  kiln::TractionKernel::evaluate_pressure(fv, p, 0, bent);
  for (int i = 0; i < 4; ++i)
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(bent.residual(d, i), p * shares.area_vector[i][d], 1e-12 * p)
          << "node " << i << ", " << d;
}

namespace
{
/// Isotropic elasticity with E(T) = E0 (1 + c (T − T_ref)), ν constant and the secant
/// thermal strain α(T) (T − T_ref), α(T) = α0 (1 + a (T − T_ref)) (doc/materials.md): not
/// constant_linear(), so the kernel takes its general path.
class TemperatureDependentElasticity final : public kiln::ConstitutiveModel
{
public:
  /// With `isotropic_form` the tangent is also given in isotropic form (λ_t, μ_t vary with T).
  explicit TemperatureDependentElasticity(const bool isotropic_form = false)
      : isotropic_form_(isotropic_form)
  {
  }
  double thermal_strain(const double temperature) const override
  {
    const double dT = temperature - T_ref;
    return alpha * (1.0 + 1e-3 * dT) * dT;
  }
  void evaluate(const kiln::PointInput &in, const double *, double *,
                kiln::PointResponse &out) const override
  {
    const double dT = in.temperature - T_ref;
    const double scale = 1.0 + 2e-3 * dT, dscale = 2e-3;
    const double a = alpha * (1.0 + 1e-3 * dT), thermal = a * dT;
    const double dthermal = alpha * (1.0 + 2e-3 * dT);
    kiln::Voigt e = in.strain;
    for (int I = 0; I < 3; ++I)
      e[I] -= thermal;
    const double trace = e[0] + e[1] + e[2];
    for (int I = 0; I < 6; ++I)
    {
      const double base = (I < 3 ? lambda * trace : 0.0) + 2.0 * G * e[I];
      out.stress[I] = scale * base;
      // d/dT: dscale * base + scale * (−(3λ + 2G) dthermal on the diagonal).
      out.stress_temperature_derivative[I] =
          dscale * base - (I < 3 ? scale * (3.0 * lambda + 2.0 * G) * dthermal : 0.0);
      for (int J = 0; J < 6; ++J)
        out.tangent[I][J] = scale * ((I < 3 && J < 3 ? lambda : 0.0) + (I == J ? 2.0 * G : 0.0));
    }
    out.isotropic.valid = isotropic_form_;
    out.isotropic.lambda = scale * lambda;
    out.isotropic.shear = scale * G;
  }

private:
  bool isotropic_form_;
};

/// `model` with the isotropic form of its tangent withheld at one evaluation in `period` (1: at
/// every point, so the kernel contracts the 6x6 tangent, the general contraction; 2: at every
/// other point, so at some points of a cell). Where it withholds the form it gives the 6x6
/// tangent; where it gives the form to a caller that asks for no full tangent, it leaves the
/// 6x6 tangent unset (zeros), which the kernel must then build from the form.
class IsotropicFormWithheld final : public kiln::ConstitutiveModel
{
public:
  IsotropicFormWithheld(std::shared_ptr<const kiln::ConstitutiveModel> model, const int period)
      : model_(std::move(model)), period_(period)
  {
  }
  int n_state() const override { return model_->n_state(); }
  void initial_state(double *state) const override { model_->initial_state(state); }
  double thermal_strain(const double temperature) const override
  {
    return model_->thermal_strain(temperature);
  }
  void evaluate(const kiln::PointInput &in, const double *old_state, double *new_state,
                kiln::PointResponse &out) const override
  {
    const bool withheld = (calls_++ % period_) == period_ - 1;
    kiln::PointInput asked = in;
    asked.full_tangent = in.full_tangent || withheld;
    model_->evaluate(asked, old_state, new_state, out);
    if (withheld)
      out.isotropic.valid = false;
    else if (!in.full_tangent)
      out.tangent = kiln::VoigtMatrix{}; // not to be read
  }

private:
  std::shared_ptr<const kiln::ConstitutiveModel> model_;
  int period_;
  mutable int calls_ = 0; // a serial test
};

/// A Power Law viscoplastic model of the steel-like constants, rate A σ^n exp(−Q/(R T)).
std::shared_ptr<const kiln::ConstitutiveModel> power_law_model(const double A, const double n,
                                                               const double Q)
{
  Teuchos::ParameterList p;
  p.set("Type", std::string("Power Law"));
  p.set("Lame Lambda", lambda);
  p.set("Shear Modulus", G);
  p.set("Thermal Expansion", alpha);
  p.set("Reference Temperature", T_ref);
  p.set("Power Law A", A);
  p.set("Power Law n", n);
  p.set("Power Law Q", Q);
  p.set("Local Tolerance", 1e-14);
  return kiln::create_constitutive_model(p, "test", "Model");
}

/// The general path's Jacobian against central differences on the distorted cell, for u
/// (strain ~1e-3) and T columns, with `history` fixed (the state at t_n).
void check_general_jacobian(const kiln::ElasticityKernel &general,
                            const kiln::ElasticityKernel::PointHistory &history,
                            const double tolerance)
{
  ASSERT_TRUE(general.general());
  EXPECT_FALSE(general.constant_jacobian());
  const kiln::HexNodes x = distorted_cell();
  kiln::ElementValues fe;
  kiln_test::reinit(fe, x);
  const std::vector<double> state = cell_unknowns(x, 1.0);
  const Point b{1.0e4, -2.0e4, 7.8e4};
  const auto residual_and_jacobian = [&](const std::vector<double> &s, kiln::LocalSystem &local)
  {
    NodalDisplacements u;
    NodalValues T;
    unpack(s, u, T);
    general.evaluate(fe, u, T, history, b, 1, 0, local);
  };
  const auto residual = [&](const std::vector<double> &s)
  {
    kiln::LocalSystem local(8, 4);
    residual_and_jacobian(s, local);
    return local.residual_values();
  };
  kiln::LocalSystem local(8, 4);
  residual_and_jacobian(state, local);
  const Dense J = local_jacobian(local);
  const Dense fd = finite_difference_jacobian(residual, state,
                                              [](const int c) { return c % 4 == 0 ? 1e-3 : 1e-9; });
  double scale_u = 0.0, scale_T = 0.0, error_u = 0.0, error_T = 0.0;
  for (int r = 0; r < 32; ++r)
    for (int c = 0; c < 32; ++c)
    {
      if (r % 4 == 0)
      {
        EXPECT_EQ(J[r][c], 0.0);
        continue;
      }
      const double difference = std::abs(J[r][c] - fd[r][c]);
      double &scale = c % 4 == 0 ? scale_T : scale_u;
      double &error = c % 4 == 0 ? error_T : error_u;
      scale = std::max(scale, std::abs(J[r][c]));
      error = std::max(error, difference);
    }
  ASSERT_GT(scale_u, 0.0);
  ASSERT_GT(scale_T, 0.0);
  EXPECT_LT(error_u, tolerance * scale_u);
  EXPECT_LT(error_T, tolerance * scale_T);
  std::cout << "general path: max |J - J_fd| / max |J|: u columns " << error_u / scale_u
            << ", T columns " << error_T / scale_T << "\n";
}
/// The distorted cell under an affine displacement and a temperature varying over its nodes.
struct AffineCell
{
  AffineCell()
  {
    const kiln::HexNodes x = distorted_cell();
    kiln_test::reinit(fe, x);
    u = affine_displacement(x, gradient_E, Point{1e-4, 0.0, -2e-4});
    for (int i = 0; i < 8; ++i)
      T[i] = T_ref + 3.0 * i;
  }
  kiln::ElementValues fe;
  NodalDisplacements u;
  NodalValues T;
};
} // namespace

TEST(ElasticityKernel, ConstantLinearModelTakesTheFastPathBitIdentically)
{
  const kiln::ElasticityKernel from_model(
      std::make_shared<kiln::LinearElasticModel>(lambda, G, alpha, T_ref), Point{1.0, 2.0, 3.0});
  EXPECT_FALSE(from_model.general());
  EXPECT_TRUE(from_model.constant_jacobian());
  const AffineCell cell;
  const kiln::ElementValues &fe = cell.fe;
  const NodalDisplacements &u = cell.u;
  const NodalValues &T = cell.T;
  kiln::LocalSystem a(8, 4), b(8, 4);
  from_model.evaluate(fe, u, T, Point{1.0, 2.0, 3.0}, 1, 0, a);
  kernel.evaluate(fe, u, T, Point{1.0, 2.0, 3.0}, 1, 0, b);
  EXPECT_EQ(a.residual_values(), b.residual_values());
  EXPECT_EQ(local_jacobian(a), local_jacobian(b));
}

TEST(ElasticityKernel, GeneralPathOfAConstantModelEqualsTheFastPath)
{
  // The Power Law model with A = 0 is elastic but not constant_linear(): the general path
  // must then give the fast path's residual and Jacobian up to rounding.
  const kiln::ElasticityKernel general(power_law_model(0.0, 1.0, 0.0), Point{});
  ASSERT_TRUE(general.general());
  const AffineCell cell;
  const kiln::ElementValues &fe = cell.fe;
  const NodalDisplacements &u = cell.u;
  const NodalValues &T = cell.T;
  kiln::LocalSystem a(8, 4), b(8, 4);
  general.evaluate(fe, u, T, kiln::ElasticityKernel::PointHistory{}, Point{1, 2, 3}, 1, 0, a);
  kernel.evaluate(fe, u, T, Point{1, 2, 3}, 1, 0, b);
  const Dense Ja = local_jacobian(a), Jb = local_jacobian(b);
  EXPECT_LT(max_difference(Ja, Jb), 1e-12 * max_abs(Jb));
  const std::vector<double> ra = a.residual_values(), rb = b.residual_values();
  double error = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < ra.size(); ++i)
  {
    error = std::max(error, std::abs(ra[i] - rb[i]));
    scale = std::max(scale, std::abs(rb[i]));
  }
  EXPECT_LT(error, 1e-12 * scale);
}

TEST(ElasticityKernel, GeneralPathJacobianOfTemperatureDependentElasticity)
{
  for (const bool isotropic_form : {false, true})
  {
    const kiln::ElasticityKernel general(
        std::make_shared<TemperatureDependentElasticity>(isotropic_form), Point{});
    check_general_jacobian(general, kiln::ElasticityKernel::PointHistory{}, 1e-7);
  }
}

TEST(ElasticityKernel, GeneralPathJacobianOfAViscoplasticStep)
{
  // A rate that depends on T (Q > 0): ~1e-4 of plastic strain against 1e-3 elastic in 1 s.
  const auto model = power_law_model(4e-28, 3.0, 1.0e4);
  ASSERT_GT(model->n_state(), 0);
  const kiln::ElasticityKernel general(model, Point{});
  kiln::ElementValues fe;
  kiln_test::reinit(fe, distorted_cell());
  const int size = model->n_state() * fe.n_qpoints();
  std::vector<double> old_state(size), new_state(size);
  for (int q = 0; q < fe.n_qpoints(); ++q)
    model->initial_state(old_state.data() + q * model->n_state());
  NodalValues T_old;
  T_old.fill(T_ref + 30.0);
  kiln::ElasticityKernel::PointHistory history;
  history.T_old = T_old;
  history.time_step = 1.0;
  history.old_state = old_state.data();
  history.new_state = new_state.data();
  check_general_jacobian(general, history, 1e-5);
  // The step flowed: some plastic strain at every point.
  for (int q = 0; q < fe.n_qpoints(); ++q)
    EXPECT_GT(model->equivalent_plastic_strain(new_state.data() + q * model->n_state()), 0.0);
}

namespace
{
/// `a` and `b`, the same cell's systems from the isotropic and the general contraction: the
/// residuals equal (the contraction is the Jacobian's only), the Jacobians to rounding.
void expect_same_system(const kiln::LocalSystem &a, const kiln::LocalSystem &b)
{
  EXPECT_EQ(a.residual_values(), b.residual_values());
  const Dense Ja = local_jacobian(a), Jb = local_jacobian(b);
  ASSERT_GT(max_abs(Jb), 0.0);
  EXPECT_LT(max_difference(Ja, Jb), 1e-13 * max_abs(Jb));
  std::cout << "isotropic against general contraction: max |difference| / max |J| "
            << max_difference(Ja, Jb) / max_abs(Jb) << "\n";
}
} // namespace

// The isotropic contraction (a tangent λ_t 1⊗1 + 2 μ_t 𝕀 + γ n⊗n, IsotropicTangent) against the
// general 6x6 one of the same model, on the distorted cell: flowing viscoplastic points
// (λ_t, μ_t, γ vary over the cell), elastic ones at Δt = 0 (a uniform cell: the geometric
// sums alone) and E(T) with T varying over the cell (γ = 0, λ_t and μ_t varying).
TEST(ElasticityKernel, IsotropicTangentContractionEqualsTheGeneralContraction)
{
  const AffineCell cell;
  const auto model = power_law_model(4e-28, 3.0, 1.0e4);
  const kiln::ElasticityKernel isotropic(model, Point{1, 2, 3});
  const kiln::ElasticityKernel general(std::make_shared<IsotropicFormWithheld>(model, 1),
                                       Point{1, 2, 3});
  const kiln::ElasticityKernel mixed(std::make_shared<IsotropicFormWithheld>(model, 2),
                                     Point{1, 2, 3});
  const int size = model->n_state() * cell.fe.n_qpoints();
  std::vector<double> old_state(size), new_state(size);
  for (int q = 0; q < cell.fe.n_qpoints(); ++q)
    model->initial_state(old_state.data() + q * model->n_state());
  NodalValues T_old;
  T_old.fill(T_ref + 30.0);
  kiln::ElasticityKernel::PointHistory history;
  history.T_old = T_old;
  history.old_state = old_state.data();
  history.new_state = new_state.data();
  for (const double time_step : {1.0, 0.0})
  {
    history.time_step = time_step;
    kiln::LocalSystem a(8, 4), b(8, 4), c(8, 4);
    // Each from the same new state on entry (the local solves' start), so that the residuals
    // are the same to the bit.
    const auto from_zeros = [&](const kiln::ElasticityKernel &kernel, kiln::LocalSystem &local)
    {
      std::fill(new_state.begin(), new_state.end(), 0.0);
      kernel.evaluate(cell.fe, cell.u, cell.T, history, Point{1, 2, 3}, 1, 0, local);
    };
    from_zeros(isotropic, a);
    from_zeros(general, b);
    expect_same_system(a, b);
    from_zeros(mixed, c);
    expect_same_system(c, b);
    if (time_step > 0.0) // the points flowed: the rank-one term is there
    {
      for (int q = 0; q < cell.fe.n_qpoints(); ++q)
        EXPECT_GT(model->equivalent_plastic_strain(new_state.data() + q * model->n_state()), 0.0);
    }
  }
  const kiln::ElasticityKernel with_form(std::make_shared<TemperatureDependentElasticity>(true),
                                         Point{});
  const kiln::ElasticityKernel without_form(std::make_shared<TemperatureDependentElasticity>(false),
                                            Point{});
  kiln::LocalSystem a(8, 4), b(8, 4);
  with_form.evaluate(cell.fe, cell.u, cell.T, kiln::ElasticityKernel::PointHistory{}, Point{}, 1, 0,
                     a);
  without_form.evaluate(cell.fe, cell.u, cell.T, kiln::ElasticityKernel::PointHistory{}, Point{}, 1,
                        0, b);
  expect_same_system(a, b);
}
