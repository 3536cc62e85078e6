// Tests src/mesh/box_mesh_generator.cpp: counts, element blocks, side sets (sizes, areas,
// outward normals) of rotated and translated generated boxes, and the odd-x-count error.
// KILN_TEST_NP: 1
#include "mesh/box_mesh_generator.hpp"

#include "base/errors.hpp"
#include "mesh/hex_geometry.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace
{
using kiln::Mesh;
using kiln::Point;
using testing::HasSubstr;
using Matrix = std::array<std::array<double, 3>, 3>;

struct Box
{
  std::array<int, 3> cells;
  std::array<double, 3> size;
  double phi;
  double theta;
  Point shift;
};

Teuchos::ParameterList box_parameters(const Box &box)
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  p.set("Cells", Teuchos::Array<int>(Teuchos::tuple(box.cells[0], box.cells[1], box.cells[2])));
  p.set("Size", Teuchos::Array<double>(Teuchos::tuple(box.size[0], box.size[1], box.size[2])));
  p.set("Phi", box.phi);
  p.set("Theta", box.theta);
  p.set("Translation",
        Teuchos::Array<double>(Teuchos::tuple(box.shift[0], box.shift[1], box.shift[2])));
  return p;
}

Mesh generate(const Box &box)
{
  return kiln::BoxMeshGenerator(box_parameters(box), "test/Box").generate();
}

/// The rotation of the spec, A = Rx(theta) Ry(phi), written out here (not taken from the code).
Matrix rotation(const double phi_degrees, const double theta_degrees)
{
  const double pi = std::acos(-1.0);
  const double p = phi_degrees * pi / 180, t = theta_degrees * pi / 180;
  const Matrix Ry = {{{std::cos(p), 0, std::sin(p)}, {0, 1, 0}, {-std::sin(p), 0, std::cos(p)}}};
  const Matrix Rx = {{{1, 0, 0}, {0, std::cos(t), -std::sin(t)}, {0, std::sin(t), std::cos(t)}}};
  Matrix A{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        A[i][j] += Rx[i][k] * Ry[k][j];
  return A;
}

/// Column `axis` of A times `sign`: the rotated +-axis direction.
Point rotated_axis(const Matrix &A, const int axis, const double sign)
{
  return {sign * A[0][axis], sign * A[1][axis], sign * A[2][axis]};
}

/// The box's own frame: A^T (y - shift).
Point to_box_frame(const Matrix &A, const Point &shift, const Point &y)
{
  Point x{0, 0, 0};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      x[i] += A[k][i] * (y[k] - shift[k]);
  return x;
}

/// Unit normal of a quad face by the cross product of its diagonals (right-hand rule).
Point diagonal_normal(const kiln::QuadNodes &q)
{
  const Point a{q[2][0] - q[0][0], q[2][1] - q[0][1], q[2][2] - q[0][2]};
  const Point b{q[3][0] - q[1][0], q[3][1] - q[1][1], q[3][2] - q[1][2]};
  Point n{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (double &v : n)
    v /= length;
  return n;
}

void expect_box(const Box &box)
{
  SCOPED_TRACE("box " + std::to_string(box.cells[0]) + " x " + std::to_string(box.cells[1]) +
               " x " + std::to_string(box.cells[2]));
  const Mesh mesh = generate(box);
  const int nx = box.cells[0], ny = box.cells[1], nz = box.cells[2];
  const double Lx = box.size[0], Ly = box.size[1], Lz = box.size[2];
  const Matrix A = rotation(box.phi, box.theta);
  const double length_scale = std::max(
      {Lx, Ly, Lz, std::abs(box.shift[0]), std::abs(box.shift[1]), std::abs(box.shift[2])});
  const double tol = 1e-14 * length_scale;

  ASSERT_EQ(mesh.n_cells(), nx * ny * nz);
  ASSERT_EQ(mesh.n_nodes(), (nx + 1) * (ny + 1) * (nz + 1));
  ASSERT_EQ(mesh.block_id.size(), static_cast<std::size_t>(nx * ny * nz));
  EXPECT_TRUE(mesh.gap_pairs.empty());
  EXPECT_TRUE(mesh.gap_side_sets.empty());

  // Every node lies in the box (in its own frame) on the grid.
  for (int n = 0; n < mesh.n_nodes(); ++n)
  {
    const Point x = to_box_frame(A, box.shift, mesh.coordinates[n]);
    for (int d = 0; d < 3; ++d)
    {
      const double h = box.size[d] / box.cells[d];
      const double steps = (x[d] + box.size[d] / 2) / h;
      EXPECT_NEAR(steps, std::round(steps), 1e-12) << "node " << n << " axis " << d;
      EXPECT_GE(std::round(steps), 0);
      EXPECT_LE(std::round(steps), box.cells[d]);
    }
  }

  // Each cell: a positive volume hx hy hz; block 1 the x < 0 half, numbered first.
  const double cell_volume = Lx * Ly * Lz / (nx * ny * nz);
  double volume = 0.0;
  for (int c = 0; c < mesh.n_cells(); ++c)
  {
    const double v = kiln::hex_volume(kiln::cell_nodes(mesh, c));
    EXPECT_NEAR(v, cell_volume, 1e-12 * cell_volume) << "cell " << c;
    volume += v;
    Point centroid{0, 0, 0};
    for (const int n : mesh.cell_nodes(c))
      for (int d = 0; d < 3; ++d)
        centroid[d] += mesh.coordinates[n][d] / 8;
    const Point x = to_box_frame(A, box.shift, centroid);
    EXPECT_EQ(mesh.block_id[c], x[0] < 0 ? 1 : 2) << "cell " << c;
    EXPECT_EQ(mesh.block_id[c], c < mesh.n_cells() / 2 ? 1 : 2) << "cell " << c;
  }
  EXPECT_NEAR(volume, Lx * Ly * Lz, 1e-12 * Lx * Ly * Lz);
  EXPECT_EQ(mesh.block_ids(), (std::vector<int>{1, 2}));

  // Side sets 1-6: id -> axis, side, face count, face area.
  std::vector<int> ids;
  for (const auto &s : mesh.side_sets)
    ids.push_back(s.id);
  ASSERT_EQ(ids, (std::vector<int>{1, 2, 3, 4, 5, 6, 10}));
  // Named after the face of the box's own frame (the names the Exodus output shows).
  std::vector<std::string> names;
  for (const auto &s : mesh.side_sets)
    names.push_back(s.name);
  EXPECT_EQ(names, (std::vector<std::string>{"x_min", "x_max", "y_min", "y_max", "z_min", "z_max",
                                             "gap"}));
  struct Side
  {
    int id, axis;
    double sign;
    int n_faces;
    double area;
  };
  const Side sides[] = {{1, 0, -1, ny * nz, Ly * Lz}, {2, 0, +1, ny * nz, Ly * Lz},
                        {3, 1, -1, nx * nz, Lx * Lz}, {4, 1, +1, nx * nz, Lx * Lz},
                        {5, 2, -1, nx * ny, Lx * Ly}, {6, 2, +1, nx * ny, Lx * Ly}};
  for (const Side &side : sides)
  {
    SCOPED_TRACE("side set " + std::to_string(side.id));
    const kiln::SideSet &set = *mesh.find_side_set(side.id);
    ASSERT_EQ(set.n_sides(), side.n_faces);
    ASSERT_EQ(set.faces.size(), set.cells.size());
    const Point normal = rotated_axis(A, side.axis, side.sign);
    double area = 0.0;
    for (int s = 0; s < set.n_sides(); ++s)
    {
      const kiln::QuadNodes q = kiln::face_nodes(mesh, set.cells[s], set.faces[s]);
      for (const Point &p : q)
        EXPECT_NEAR(to_box_frame(A, box.shift, p)[side.axis], side.sign * box.size[side.axis] / 2,
                    tol)
            << "entry " << s;
      const Point n = diagonal_normal(q);
      for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(n[d], normal[d], 1e-14) << "entry " << s;
      const kiln::FaceNodalAreas areas = kiln::face_nodal_areas(kiln::CellType::quad4, q.data());
      area += areas.area[0] + areas.area[1] + areas.area[2] + areas.area[3];
    }
    EXPECT_NEAR(area, side.area, 1e-14 * side.area);
    // No face listed twice.
    std::vector<std::pair<int, int>> entries;
    for (int s = 0; s < set.n_sides(); ++s)
      entries.emplace_back(set.cells[s], set.faces[s]);
    std::sort(entries.begin(), entries.end());
    EXPECT_EQ(std::unique(entries.begin(), entries.end()), entries.end());
  }

  // Side set 10: the plane x = 0 from both sides, block 1's faces first.
  const kiln::SideSet &gap = *mesh.find_side_set(10);
  ASSERT_EQ(gap.n_sides(), 2 * ny * nz);
  double area[2] = {0, 0};
  for (int s = 0; s < gap.n_sides(); ++s)
  {
    const int block = mesh.block_id[gap.cells[s]];
    EXPECT_EQ(block, s < ny * nz ? 1 : 2) << "entry " << s;
    const kiln::QuadNodes q = kiln::face_nodes(mesh, gap.cells[s], gap.faces[s]);
    for (const Point &p : q)
      EXPECT_NEAR(to_box_frame(A, box.shift, p)[0], 0.0, tol) << "entry " << s;
    // Outward from its own block: +x for block 1, -x for block 2.
    const Point normal = rotated_axis(A, 0, block == 1 ? 1 : -1);
    const Point n = diagonal_normal(q);
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(n[d], normal[d], 1e-14) << "entry " << s;
    const kiln::FaceNodalAreas areas = kiln::face_nodal_areas(kiln::CellType::quad4, q.data());
    area[block - 1] += areas.area[0] + areas.area[1] + areas.area[2] + areas.area[3];
  }
  EXPECT_NEAR(area[0], Ly * Lz, 1e-14 * Ly * Lz);
  EXPECT_NEAR(area[1], Ly * Lz, 1e-14 * Ly * Lz);

  // The centre of the nodes is the translation.
  Point centre{0, 0, 0};
  for (const Point &p : mesh.coordinates)
    for (int d = 0; d < 3; ++d)
      centre[d] += p[d] / mesh.n_nodes();
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(centre[d], box.shift[d], tol);
}

TEST(BoxMeshGenerator, Rotated4x2x3BoxWithUnequalSides)
{
  expect_box({{4, 2, 3}, {0.08, 0.02, 0.03}, 45, -30, {0.02, -0.01, 0.03}});
}

TEST(BoxMeshGenerator, Rotated4x4x4ContactBox)
{
  expect_box({{4, 4, 4}, {0.04, 0.04, 0.04}, 45, -30, {0.0, 0.0, 0.0}});
  expect_box({{4, 4, 4}, {0.04, 0.04, 0.04}, 45, -30, {0.01, 0.02, -0.03}});
}

TEST(BoxMeshGenerator, OtherAnglesAndCounts)
{
  expect_box({{2, 1, 1}, {1.0, 2.0, 3.0}, 0, 0, {0, 0, 0}});
  expect_box({{6, 3, 2}, {0.3, 0.2, 0.1}, -70, 20, {0.1, 0.2, 0.3}});
}

TEST(BoxMeshGenerator, AlignedBoxCoordinates)
{
  // Unrotated: node (i, j, k) at (-Lx/2 + i hx, ...), numbered x fastest.
  const Mesh mesh = generate({{2, 1, 1}, {2.0, 4.0, 6.0}, 0, 0, {10, 0, 0}});
  ASSERT_EQ(mesh.n_nodes(), 12);
  EXPECT_EQ(mesh.coordinates[0], (Point{9.0, -2.0, -3.0}));
  EXPECT_EQ(mesh.coordinates[1], (Point{10.0, -2.0, -3.0}));
  EXPECT_EQ(mesh.coordinates[11], (Point{11.0, 2.0, 3.0}));
  EXPECT_EQ(mesh.block_id, (std::vector<int>{1, 2}));
}

TEST(BoxMeshGenerator, OddXCountIsRejected)
{
  const Teuchos::ParameterList p = box_parameters({{3, 2, 2}, {1, 1, 1}, 0, 0, {0, 0, 0}});
  try
  {
    kiln::BoxMeshGenerator generator(p, "in.xml: Kiln/Mesh/Box");
    ADD_FAILURE() << "no InputError for 3 cells in x";
  }
  catch (const kiln::InputError &e)
  {
    EXPECT_THAT(e.what(), HasSubstr("in.xml: Kiln/Mesh/Box"));
    EXPECT_THAT(e.what(), HasSubstr("even"));
    EXPECT_THAT(e.what(), HasSubstr("3"));
  }
  EXPECT_THROW(kiln::BoxMeshGenerator(box_parameters({{1, 4, 4}, {1, 1, 1}, 0, 0, {0, 0, 0}}), "w"),
               kiln::InputError);
}

std::string generator_error(const Teuchos::ParameterList &p)
{
  try
  {
    kiln::BoxMeshGenerator generator(p, "in.xml: Kiln/Mesh/Box");
  }
  catch (const kiln::InputError &e)
  {
    return e.what();
  }
  return "";
}

TEST(BoxMeshGenerator, OddXCountSuggestsValidCounts)
{
  // One cell along x was told to use "2 or 0"; 0 is not a count.
  EXPECT_THAT(generator_error(box_parameters({{1, 4, 4}, {1, 1, 1}, 0, 0, {0, 0, 0}})),
              HasSubstr("the x count is 1 but must be even, so that the plane x = 0 between the "
                        "two blocks is a cell face; use 2 (one cell on each side)"));
  EXPECT_THAT(generator_error(box_parameters({{5, 4, 4}, {1, 1, 1}, 0, 0, {0, 0, 0}})),
              HasSubstr("use 4 or 6"));
}

TEST(BoxMeshGenerator, CountsBeyondIntAreRejected)
{
  // 2000^3 cells: the node numbers overflowed int before the run ran out of memory.
  EXPECT_THAT(generator_error(box_parameters({{2000, 2000, 2000}, {1, 1, 1}, 0, 0, {0, 0, 0}})),
              HasSubstr("in.xml: Kiln/Mesh/Box/\"Cells\": {2000, 2000, 2000} gives 8e+09 cells and "
                        "8.01201e+09 nodes, more than the 2147483647 a Kiln mesh can number"));
  EXPECT_EQ(generator_error(box_parameters({{1000, 1000, 2000}, {1, 1, 1}, 0, 0, {0, 0, 0}})), "");
}
} // namespace
