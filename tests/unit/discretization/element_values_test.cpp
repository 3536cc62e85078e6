// Tests src/discretization/element_values.cpp: partition of unity, exact volumes of affine and
// non-affine cells, exact gradients of linear fields on a distorted cell, the Q1 stiffness
// matrix of the unit cube, the error on an inverted cell, and the HEX8 path's bits equal to
// the general sums.
// KILN_TEST_NP: 1
#include "discretization/element_values.hpp"

#include "base/errors.hpp"
#include "mesh/hex_geometry.hpp"
#include "support/reference_cells.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

namespace
{
using kiln::ElementValues;
using kiln::HexNodes;
using kiln::Point;
using kiln_test::dot;
using kiln_test::mapped;
using kiln_test::multiply;
using kiln_test::unit_cube;
using Matrix = kiln_test::Matrix3;

/// A non-affine cell: the unit cube with its top face stretched to [0,2] x [0,1] (volume 1.5,
/// see hex_geometry_test), then every node moved by a different small amount, then rotated.
HexNodes distorted_cell()
{
  HexNodes x = unit_cube();
  x[5][0] = 2;
  x[6][0] = 2;
  const double shifts[8][3] = {{0.05, -0.03, 0.02},  {-0.04, 0.06, 0.01}, {0.03, 0.02, -0.05},
                               {-0.02, -0.04, 0.03}, {0.01, 0.05, -0.02}, {0.06, -0.01, 0.04},
                               {-0.05, 0.03, 0.02},  {0.02, -0.06, -0.03}};
  for (int i = 0; i < 8; ++i)
    for (int d = 0; d < 3; ++d)
      x[i][d] += shifts[i][d];
  return mapped(x, kiln::rotation_matrix(45, -30), {0.3, -1.0, 2.0});
}

TEST(ElementValues, PartitionOfUnityAtEveryPoint)
{
  ElementValues fe;
  kiln_test::reinit(fe, distorted_cell());
  ASSERT_EQ(fe.n_qpoints(), 8);
  ASSERT_EQ(fe.n_shape(), 8);
  for (int q = 0; q < fe.n_qpoints(); ++q)
  {
    double sum = 0.0;
    Point grad_sum{0, 0, 0};
    for (int i = 0; i < fe.n_shape(); ++i)
    {
      sum += fe.shape(i, q);
      for (int d = 0; d < 3; ++d)
        grad_sum[d] += fe.grad(i, q)[d];
    }
    EXPECT_NEAR(sum, 1.0, 1e-15) << "q = " << q;
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(grad_sum[d], 0.0, 1e-14) << "q = " << q << ", d = " << d;
  }
}

TEST(ElementValues, ShapeValuesAtGaussPoints)
{
  // At the Gauss point nearest node i, N_i = ((1 + g)/2)^3 with g = 1/sqrt(3); at the one
  // nearest the opposite node ((1 - g)/2)^3. hex_gauss_points() lists the points in node order.
  ElementValues fe;
  kiln_test::reinit(fe, unit_cube());
  const double g = 1 / std::sqrt(3.0), a = (1 + g) / 2, b = (1 - g) / 2;
  const int opposite[8] = {6, 7, 4, 5, 2, 3, 0, 1};
  for (int i = 0; i < 8; ++i)
  {
    EXPECT_NEAR(fe.shape(i, i), a * a * a, 1e-15) << "node " << i;
    EXPECT_NEAR(fe.shape(i, opposite[i]), b * b * b, 1e-15) << "node " << i;
  }
  // The Gauss points of the unit cube are (1 +- g)/2 in each direction.
  for (int q = 0; q < 8; ++q)
  {
    const Point r = kiln::hex_reference_node(q);
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(fe.quadrature_point(q)[d], (1 + r[d] * g) / 2, 1e-15);
  }
}

TEST(ElementValues, VolumeOfRotatedShearedCell)
{
  // Scale (2, 3, 0.5), shear, rotation: volume = 1 * 1 * 3, det = 3/8 at each point.
  const Matrix scale = {{{2, 0, 0}, {0, 3, 0}, {0, 0, 0.5}}};
  const Matrix shear = {{{1, 0.7, 0.2}, {0, 1, 0}, {0, 0, 1}}};
  const Matrix M = multiply(kiln::rotation_matrix(45, -30), multiply(shear, scale));
  ElementValues fe;
  kiln_test::reinit(fe, mapped(unit_cube(), M, {0.1, -2.0, 5.0}));
  double volume = 0.0;
  for (int q = 0; q < fe.n_qpoints(); ++q)
  {
    EXPECT_NEAR(fe.JxW(q), 3.0 / 8, 1e-14);
    volume += fe.JxW(q);
  }
  EXPECT_NEAR(volume, 3.0, 1e-14);
}

TEST(ElementValues, VolumeOfRotatedNonAffineCell)
{
  // The cube with its top face stretched to [0,2] x [0,1]: volume 1.5, then rotated.
  HexNodes x = unit_cube();
  x[5][0] = 2;
  x[6][0] = 2;
  ElementValues fe;
  kiln_test::reinit(fe, mapped(x, kiln::rotation_matrix(45, -30), {1.0, 2.0, 3.0}));
  double volume = 0.0;
  for (int q = 0; q < fe.n_qpoints(); ++q)
    volume += fe.JxW(q);
  EXPECT_NEAR(volume, 1.5, 1e-14);

  // A general distorted cell: 2x2x2 Gauss integrates det(J) (degree 2 in each variable)
  // exactly, as hex_volume does.
  const HexNodes y = distorted_cell();
  kiln_test::reinit(fe, y);
  volume = 0.0;
  for (int q = 0; q < fe.n_qpoints(); ++q)
    volume += fe.JxW(q);
  EXPECT_NEAR(volume, kiln::hex_volume(y), 1e-14);
}

TEST(ElementValues, GradientOfLinearFieldIsExactOnDistortedCell)
{
  // u = a . x + c is in the Q1 space of any cell: its interpolant has gradient a everywhere.
  const Point a{1.5, -2.0, 0.25};
  const double c = 7.0;
  const HexNodes x = distorted_cell();
  ElementValues fe;
  kiln_test::reinit(fe, x);
  for (int q = 0; q < fe.n_qpoints(); ++q)
  {
    Point grad_u{0, 0, 0};
    double u = 0.0;
    for (int i = 0; i < fe.n_shape(); ++i)
    {
      const double u_i = dot(a, x[i]) + c;
      u += u_i * fe.shape(i, q);
      for (int d = 0; d < 3; ++d)
        grad_u[d] += u_i * fe.grad(i, q)[d];
    }
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(grad_u[d], a[d], 1e-13) << "q = " << q << ", d = " << d;
    // The value at the quadrature point is the field there.
    EXPECT_NEAR(u, dot(a, fe.quadrature_point(q)) + c, 1e-13) << "q = " << q;
  }
}

TEST(ElementValues, StiffnessMatrixOfUnitCube)
{
  // K_ij = int grad N_i . grad N_j over [0,1]^3 (2x2x2 Gauss is exact for it): 1/3 on the
  // diagonal, 0 for nodes sharing an edge, -1/12 for nodes across a face diagonal and -1/12
  // across the body diagonal.
  ElementValues fe;
  kiln_test::reinit(fe, unit_cube());
  const HexNodes x = unit_cube();
  for (int i = 0; i < 8; ++i)
  {
    double row_sum = 0.0;
    for (int j = 0; j < 8; ++j)
    {
      double K = 0.0;
      for (int q = 0; q < fe.n_qpoints(); ++q)
        K += dot(fe.grad(i, q), fe.grad(j, q)) * fe.JxW(q);
      int differing = 0; // coordinates in which nodes i and j differ
      for (int d = 0; d < 3; ++d)
        differing += x[i][d] != x[j][d];
      const double expected[4] = {1.0 / 3, 0.0, -1.0 / 12, -1.0 / 12};
      EXPECT_NEAR(K, expected[differing], 1e-15) << "K(" << i << "," << j << ")";
      row_sum += K;
    }
    EXPECT_NEAR(row_sum, 0.0, 1e-15) << "row " << i;
  }
}

TEST(ElementValues, InvertedCellThrows)
{
  const HexNodes cube = unit_cube();
  const HexNodes mirrored = kiln_test::mirrored_cell(cube);
  ElementValues fe;
  EXPECT_THROW(kiln_test::reinit(fe, mirrored), kiln::InternalError);
  HexNodes flat = cube;
  for (int i = 4; i < 8; ++i)
    flat[i][2] = 0.0;
  EXPECT_THROW(kiln_test::reinit(fe, flat), kiln::InternalError);
}

/// x_q, JxW and the gradients of a HEX8 by the general scalar sums (ElementValues::map()'s
/// order, from the shared ReferenceValues): the vectorised HEX8 path must give these bits.
void expect_same_bits_as_general_sums(const HexNodes &x, const ElementValues &fe)
{
  const kiln::ReferenceValues &ref = kiln::ReferenceValues::of(kiln::CellType::hex8);
  for (int q = 0; q < 8; ++q)
  {
    double J[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    Point xq{0, 0, 0};
    for (int i = 0; i < 8; ++i)
      for (int d = 0; d < 3; ++d)
      {
        xq[d] += ref.shape[q * 8 + i] * x[i][d];
        for (int r = 0; r < 3; ++r)
          J[d][r] += x[i][d] * ref.grad[q * 8 + i][r];
      }
    const double C[3][3] = {
        {J[1][1] * J[2][2] - J[1][2] * J[2][1], J[1][2] * J[2][0] - J[1][0] * J[2][2],
         J[1][0] * J[2][1] - J[1][1] * J[2][0]},
        {J[0][2] * J[2][1] - J[0][1] * J[2][2], J[0][0] * J[2][2] - J[0][2] * J[2][0],
         J[0][1] * J[2][0] - J[0][0] * J[2][1]},
        {J[0][1] * J[1][2] - J[0][2] * J[1][1], J[0][2] * J[1][0] - J[0][0] * J[1][2],
         J[0][0] * J[1][1] - J[0][1] * J[1][0]}};
    const double det = J[0][0] * C[0][0] + J[0][1] * C[0][1] + J[0][2] * C[0][2];
    const double inv_det = 1.0 / det;
    EXPECT_EQ(fe.JxW(q), det * ref.weights[q]) << "q = " << q;
    for (int d = 0; d < 3; ++d)
      EXPECT_EQ(fe.quadrature_point(q)[d], xq[d]) << "q = " << q << ", d = " << d;
    for (int i = 0; i < 8; ++i)
    {
      const Point &g = ref.grad[q * 8 + i];
      for (int d = 0; d < 3; ++d)
        EXPECT_EQ(fe.grad(i, q)[d], (C[d][0] * g[0] + C[d][1] * g[1] + C[d][2] * g[2]) * inv_det)
            << "q = " << q << ", i = " << i << ", d = " << d;
      EXPECT_EQ(fe.shape(i, q), ref.shape[q * 8 + i]);
    }
  }
}

// The HEX8 path (vector registers, its own table) sums in the general path's order: the same
// bits, so that the gold files of every HEX8 deck stay as they are.
TEST(ElementValues, Hex8PathHasTheBitsOfTheGeneralSums)
{
  ElementValues fe;
  kiln_test::reinit(fe, distorted_cell());
  expect_same_bits_as_general_sums(distorted_cell(), fe);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> shift(-0.2, 0.2);
  for (int cell = 0; cell < 50; ++cell)
  {
    HexNodes x = unit_cube();
    for (Point &p : x)
      for (double &v : p)
        v = 1e-3 * (v + shift(random)) + 0.05;
    const HexNodes moved = mapped(x, kiln::rotation_matrix(20.0 * cell, 7.0 - cell), {0.3, -1, 2});
    kiln_test::reinit(fe, moved);
    expect_same_bits_as_general_sums(moved, fe);
  }
}
} // namespace
