// Tests src/discretization/face_values.cpp: areas, unit outward normals (rotated faces and the
// six faces of a hexahedron), integrals of the shape functions, and the nodal areas of
// face_nodal_areas() reproduced on a non-affine face.
// KILN_TEST_NP: 1
#include "discretization/face_values.hpp"

#include "base/errors.hpp"
#include "mesh/hex_geometry.hpp"
#include "support/reference_cells.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace
{
using kiln::FaceValues;
using kiln::Point;
using kiln::QuadNodes;
using kiln_test::mapped_face;
using kiln_test::times;
using Matrix = kiln_test::Matrix3;

double total_area(const FaceValues &fe)
{
  double area = 0.0;
  for (int q = 0; q < fe.n_qpoints(); ++q)
    area += fe.JxW(q);
  return area;
}

TEST(FaceValues, RotatedRectangleAreaAndNormal)
{
  // A 3 x 2 rectangle in z = 0, counterclockwise seen from +z (normal +z), rotated and shifted.
  const Matrix A = kiln::rotation_matrix(45, -30);
  const QuadNodes x =
      mapped_face({{{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {0, 2, 0}}}, A, {1.0, 2.0, -3.0});
  FaceValues fe;
  kiln_test::reinit(fe, x);
  ASSERT_EQ(fe.n_qpoints(), 4);
  ASSERT_EQ(fe.n_shape(), 4);
  EXPECT_NEAR(total_area(fe), 6.0, 1e-14);
  // A e_z = (A02, A12, A22) = (s2, s2/2, s3 s2/2) for phi = 45, theta = -30.
  const double s2 = std::sqrt(0.5), s3 = std::sqrt(3.0);
  const Point expected{s2, s2 / 2, s3 * s2 / 2};
  for (int q = 0; q < fe.n_qpoints(); ++q)
  {
    EXPECT_NEAR(fe.JxW(q), 1.5, 1e-14);
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(fe.normal(q)[d], expected[d], 1e-15) << "q = " << q << ", d = " << d;
  }

  // The reversed node order flips the normal.
  kiln_test::reinit(fe, {x[0], x[3], x[2], x[1]});
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(fe.normal(0)[d], -expected[d], 1e-15);
}

TEST(FaceValues, ShapeIntegralsOnParallelogram)
{
  // Sides (2, 0, 0) and (0.5, 1.5, 1): area |(2,0,0) x (0.5,1.5,1)| = |(0, -2, 3)| = sqrt(13).
  // The map is affine, so each N_i integrates to a quarter of the area.
  const Point a{2, 0, 0}, b{0.5, 1.5, 1}, o{-1, 0.5, 2};
  QuadNodes x;
  for (int d = 0; d < 3; ++d)
  {
    x[0][d] = o[d];
    x[1][d] = o[d] + a[d];
    x[2][d] = o[d] + a[d] + b[d];
    x[3][d] = o[d] + b[d];
  }
  FaceValues fe;
  kiln_test::reinit(fe, x);
  const double area = std::sqrt(13.0);
  EXPECT_NEAR(total_area(fe), area, 1e-14);
  for (int i = 0; i < 4; ++i)
  {
    double integral = 0.0;
    for (int q = 0; q < fe.n_qpoints(); ++q)
      integral += fe.shape(i, q) * fe.JxW(q);
    EXPECT_NEAR(integral, area / 4, 1e-14) << "node " << i;
  }
  for (int q = 0; q < fe.n_qpoints(); ++q)
  {
    EXPECT_NEAR(fe.normal(q)[0], 0.0, 1e-15);
    EXPECT_NEAR(fe.normal(q)[1], -2 / area, 1e-15);
    EXPECT_NEAR(fe.normal(q)[2], 3 / area, 1e-15);
    // The quadrature point is the interpolated position.
    Point xq{0, 0, 0};
    double sum = 0.0;
    for (int i = 0; i < 4; ++i)
    {
      sum += fe.shape(i, q);
      for (int d = 0; d < 3; ++d)
        xq[d] += fe.shape(i, q) * x[i][d];
    }
    EXPECT_NEAR(sum, 1.0, 1e-15);
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(fe.quadrature_point(q)[d], xq[d], 1e-15);
  }
}

TEST(FaceValues, TrapezoidMatchesQuadNodalAreas)
{
  // Non-affine: bottom edge 2 long, top edge 1, height 1 (area 1.5); see hex_geometry_test.
  const QuadNodes x = {{{0, 0, 0}, {2, 0, 0}, {1.5, 1, 0}, {0.5, 1, 0}}};
  FaceValues fe;
  kiln_test::reinit(fe, x);
  EXPECT_NEAR(total_area(fe), 1.5, 1e-15);
  const kiln::FaceNodalAreas expected = kiln::face_nodal_areas(kiln::CellType::quad4, x.data());
  for (int i = 0; i < 4; ++i)
  {
    double integral = 0.0;
    for (int q = 0; q < fe.n_qpoints(); ++q)
      integral += fe.shape(i, q) * fe.JxW(q);
    EXPECT_NEAR(integral, expected.area[i], 1e-15) << "node " << i;
  }
}

TEST(FaceValues, HexFacesHaveOutwardNormals)
{
  // The unit cube, rotated: face k of hex_face_nodes has outward normal A n_k.
  const Matrix A = kiln::rotation_matrix(45, -30);
  const kiln::HexNodes cube = kiln_test::unit_cube();
  const Point outward[6] = {{0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, 0, -1}, {0, 0, 1}};
  FaceValues fe;
  for (int f = 0; f < kiln::n_hex_faces; ++f)
  {
    QuadNodes x;
    for (int i = 0; i < 4; ++i)
      x[i] = times(A, cube[kiln::hex_face_nodes[f][i]]);
    kiln_test::reinit(fe, x);
    const Point n = times(A, outward[f]);
    EXPECT_NEAR(total_area(fe), 1.0, 1e-14) << "face " << f;
    for (int q = 0; q < fe.n_qpoints(); ++q)
      for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(fe.normal(q)[d], n[d], 1e-15) << "face " << f << ", q = " << q;
  }
}

TEST(FaceValues, DegenerateFaceThrows)
{
  const QuadNodes x = {{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 0, 0}}};
  FaceValues fe;
  EXPECT_THROW(kiln_test::reinit(fe, x), kiln::InternalError);
}
} // namespace
