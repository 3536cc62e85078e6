// Tests src/mesh/hex_geometry.cpp: the rotation matrix of the contact-box spec, HEX8 Jacobian
// determinants and volumes, and the nodal area vectors of bilinear quad faces.
// KILN_TEST_NP: 1
#include "mesh/hex_geometry.hpp"

#include "support/reference_cells.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace
{
using kiln::HexNodes;
using kiln::Point;
using kiln::QuadNodes;
using kiln_test::cross;
using kiln_test::determinant;
using kiln_test::mapped;
using kiln_test::multiply;
using kiln_test::norm;
using kiln_test::times;
using kiln_test::unit_cube;
using Matrix = kiln_test::Matrix3;

TEST(HexGeometry, RotationMatrixIsRxThetaTimesRyPhi)
{
  const double pi = std::acos(-1.0);
  const double phi = 45 * pi / 180, theta = -30 * pi / 180;
  // The spec's matrices, written out.
  const Matrix Ry = {
      {{std::cos(phi), 0, std::sin(phi)}, {0, 1, 0}, {-std::sin(phi), 0, std::cos(phi)}}};
  const Matrix Rx = {
      {{1, 0, 0}, {0, std::cos(theta), -std::sin(theta)}, {0, std::sin(theta), std::cos(theta)}}};
  const Matrix expected = multiply(Rx, Ry);
  // The same product by hand with cos 45 = sin 45 = s2, cos(-30) = s3/2, sin(-30) = -1/2.
  const double s2 = std::sqrt(0.5), s3 = std::sqrt(3.0);
  const Matrix by_hand = {
      {{s2, 0, s2}, {-s2 / 2, s3 / 2, s2 / 2}, {-s3 * s2 / 2, -0.5, s3 * s2 / 2}}};

  const Matrix A = kiln::rotation_matrix(45, -30);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
    {
      EXPECT_NEAR(A[i][j], expected[i][j], 1e-15) << "A(" << i << "," << j << ")";
      EXPECT_NEAR(A[i][j], by_hand[i][j], 1e-15) << "A(" << i << "," << j << ")";
    }

  // Orthogonal with determinant +1 (a rotation, not a reflection).
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
    {
      double dot = 0.0;
      for (int k = 0; k < 3; ++k)
        dot += A[i][k] * A[j][k];
      EXPECT_NEAR(dot, i == j ? 1.0 : 0.0, 1e-15) << "row " << i << " . row " << j;
    }
  EXPECT_NEAR(determinant(A), 1.0, 1e-15);
}

TEST(HexGeometry, RotationMatrixOfSingleAxisRotations)
{
  // phi = 90 about y takes x to -z and z to x; theta = 90 about x takes y to z.
  const Matrix Ay = kiln::rotation_matrix(90, 0);
  const Point x_image = times(Ay, {1, 0, 0}), z_image = times(Ay, {0, 0, 1});
  EXPECT_NEAR(x_image[2], -1.0, 1e-15);
  EXPECT_NEAR(z_image[0], 1.0, 1e-15);
  const Matrix Ax = kiln::rotation_matrix(0, 90);
  EXPECT_NEAR(times(Ax, {0, 1, 0})[2], 1.0, 1e-15);
  const Matrix I = kiln::rotation_matrix(0, 0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_EQ(I[i][j], i == j ? 1.0 : 0.0);
}

TEST(HexGeometry, ReferenceNodesAndGaussPoints)
{
  const HexNodes cube = unit_cube();
  for (int i = 0; i < 8; ++i)
  {
    const Point r = kiln::hex_reference_node(i);
    for (int d = 0; d < 3; ++d)
      EXPECT_EQ(r[d], 2 * cube[i][d] - 1) << "node " << i;
  }
  const double g = 1 / std::sqrt(3.0);
  for (const Point &xi : kiln::hex_gauss_points())
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(std::abs(xi[d]), g, 1e-16);
}

TEST(HexGeometry, UnitCubeJacobianAndVolume)
{
  const HexNodes cube = unit_cube();
  // x = (xi + 1) / 2 in each direction: det = 1/8 everywhere.
  for (const Point xi : {Point{0, 0, 0}, Point{0.3, -0.7, 0.9}, Point{-1, -1, -1}})
    EXPECT_NEAR(kiln::hex_jacobian_determinant(cube, xi), 0.125, 1e-15);
  EXPECT_NEAR(kiln::hex_volume(cube), 1.0, 1e-15);
}

TEST(HexGeometry, VolumeOfShearedRotatedScaledCube)
{
  // Scale (2, 3, 0.5), a shear x += 0.7 y + 0.2 z, then the contact-box rotation, then a shift.
  const Matrix scale = {{{2, 0, 0}, {0, 3, 0}, {0, 0, 0.5}}};
  const Matrix shear = {{{1, 0.7, 0.2}, {0, 1, 0}, {0, 0, 1}}};
  const Matrix M = multiply(kiln::rotation_matrix(45, -30), multiply(shear, scale));
  const HexNodes x = mapped(unit_cube(), M, {0.1, -2.0, 5.0});
  // Volume = det(R) det(shear) det(scale) = 1 * 1 * 3.
  EXPECT_NEAR(kiln::hex_volume(x), 3.0, 1e-14);
  for (const Point &xi : kiln::hex_gauss_points())
    EXPECT_NEAR(kiln::hex_jacobian_determinant(x, xi), 3.0 / 8, 1e-14);
}

TEST(HexGeometry, VolumeOfNonAffineHexIsExact)
{
  // Bottom face the unit square at z = 0, top face [0,2] x [0,1] at z = 1: the cross-section at
  // height z is (1 + z) x 1, so the volume is 1.5. The map is trilinear, not affine.
  HexNodes x = unit_cube();
  x[5][0] = 2;
  x[6][0] = 2;
  EXPECT_NEAR(kiln::hex_volume(x), 1.5, 1e-15);
  // dx/dxi = (1 + z)/2 with z = (zeta + 1)/2: det = (1 + z)/8.
  EXPECT_NEAR(kiln::hex_jacobian_determinant(x, {0, 0, -1}), 1.0 / 8, 1e-15);
  EXPECT_NEAR(kiln::hex_jacobian_determinant(x, {0.5, -0.2, 1}), 2.0 / 8, 1e-15);
}

TEST(HexGeometry, MirroredNodeOrderHasNegativeJacobian)
{
  // Top and bottom faces exchanged: a reflection in z.
  const HexNodes cube = unit_cube();
  const HexNodes mirrored = kiln_test::mirrored_cell(cube);
  for (const Point &xi : kiln::hex_gauss_points())
    EXPECT_NEAR(kiln::hex_jacobian_determinant(mirrored, xi), -0.125, 1e-15);
  EXPECT_NEAR(kiln::hex_volume(mirrored), -1.0, 1e-15);
}

TEST(HexGeometry, QuadNodalAreasOfRotatedSquare)
{
  // A 3 x 2 rectangle in the plane z = 0 (normal +z by the right-hand rule), rotated and shifted.
  const Matrix A = kiln::rotation_matrix(45, -30);
  const Point shift{1.0, 2.0, -3.0};
  const QuadNodes flat = {{{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {0, 2, 0}}};
  QuadNodes x;
  for (int i = 0; i < 4; ++i)
  {
    x[i] = times(A, flat[i]);
    for (int d = 0; d < 3; ++d)
      x[i][d] += shift[d];
  }
  const Point normal = times(A, {0, 0, 1});
  const kiln::FaceNodalAreas a = kiln::face_nodal_areas(kiln::CellType::quad4, x.data());
  double total = 0.0;
  Point total_vector{0, 0, 0};
  for (int i = 0; i < 4; ++i)
  {
    EXPECT_NEAR(a.area[i], 6.0 / 4, 1e-14) << "node " << i;
    EXPECT_NEAR(norm(a.area_vector[i]), 6.0 / 4, 1e-14) << "node " << i;
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(a.area_vector[i][d], 1.5 * normal[d], 1e-14) << "node " << i;
    total += a.area[i];
    for (int d = 0; d < 3; ++d)
      total_vector[d] += a.area_vector[i][d];
  }
  EXPECT_NEAR(total, 6.0, 1e-14);
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(total_vector[d], 6.0 * normal[d], 1e-14);

  // The reversed node order flips the area vectors, not the areas.
  const QuadNodes reversed = {x[0], x[3], x[2], x[1]};
  const kiln::FaceNodalAreas b = kiln::face_nodal_areas(kiln::CellType::quad4, reversed.data());
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(b.area_vector[0][d], -1.5 * normal[d], 1e-14);
  EXPECT_NEAR(b.area[0], 1.5, 1e-14);
}

TEST(HexGeometry, QuadNodalAreasOfTrapezoid)
{
  // A planar trapezoid in z = 0: bottom edge 2 long, top edge 1 long, height 1 (area 1.5).
  // Its bilinear map has width (3 - t)/2 at height t, so dA = (3 - t)/8 ds dt, and the
  // nodes of the long edge take more of the area than those of the short one.
  const QuadNodes x = {{{0, 0, 0}, {2, 0, 0}, {1.5, 1, 0}, {0.5, 1, 0}}};
  // int_{-1}^{1} (1-t)(3-t) dt = int 3 - 4t + t^2 = 6 + 2/3; (1+t)(3-t) = 3 + 2t - t^2 -> 6 - 2/3.
  // int_{-1}^{1} (1 -+ s) ds = 2. So N0, N1 shares = 2 (6 + 2/3) / 32, N2, N3 = 2 (6 - 2/3) / 32.
  const double bottom = 2 * (6 + 2.0 / 3) / 32, top = 2 * (6 - 2.0 / 3) / 32;
  const kiln::FaceNodalAreas a = kiln::face_nodal_areas(kiln::CellType::quad4, x.data());
  const double expected[4] = {bottom, bottom, top, top};
  for (int i = 0; i < 4; ++i)
  {
    EXPECT_NEAR(a.area[i], expected[i], 1e-15) << "node " << i;
    EXPECT_NEAR(a.area_vector[i][2], expected[i], 1e-15) << "node " << i;
    EXPECT_NEAR(a.area_vector[i][0], 0.0, 1e-15);
    EXPECT_NEAR(a.area_vector[i][1], 0.0, 1e-15);
  }
  EXPECT_NEAR(a.area[0] + a.area[1] + a.area[2] + a.area[3], 1.5, 1e-15);
}

TEST(HexGeometry, QuadNodalAreasOfWarpedQuad)
{
  // The saddle z = c x y over [-1,1]^2 (its bilinear interpolant is itself).
  const double c = 0.1;
  const QuadNodes x = {{{-1, -1, c}, {1, -1, -c}, {1, 1, c}, {-1, 1, -c}}};
  const kiln::FaceNodalAreas a = kiln::face_nodal_areas(kiln::CellType::quad4, x.data());

  // The total area vector of any bilinear quad is half the cross product of its diagonals.
  Point d1, d2;
  for (int d = 0; d < 3; ++d)
  {
    d1[d] = x[2][d] - x[0][d];
    d2[d] = x[3][d] - x[1][d];
  }
  const Point diagonal_cross = cross(d1, d2);
  Point total_vector{0, 0, 0};
  for (int i = 0; i < 4; ++i)
    for (int d = 0; d < 3; ++d)
      total_vector[d] += a.area_vector[i][d];
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(total_vector[d], 0.5 * diagonal_cross[d], 1e-14);

  // The true area, int sqrt(1 + c^2 (x^2 + y^2)) dx dy, by a fine midpoint rule. 2x2 Gauss is
  // not exact for it, but its error is of order c^4 (the quartic term of the expansion).
  const int n = 400;
  double area = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      const double px = -1 + (i + 0.5) * 2.0 / n, py = -1 + (j + 0.5) * 2.0 / n;
      area += std::sqrt(1 + c * c * (px * px + py * py)) * (2.0 / n) * (2.0 / n);
    }
  const double total = a.area[0] + a.area[1] + a.area[2] + a.area[3];
  // 2x2 Gauss misses the quartic term of the expansion: about 9e-6 here (c = 0.1), while an
  // error in the c^2 term would be of order 1e-2.
  EXPECT_NEAR(total, area, 2e-5);
  EXPECT_GT(total, 4.0); // larger than its flat projection
  // By symmetry every node gets a quarter.
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(a.area[i], total / 4, 1e-15);
}
} // namespace
