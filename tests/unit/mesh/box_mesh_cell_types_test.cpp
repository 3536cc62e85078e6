// Tests the "Cell Type" of src/mesh/box_mesh_generator.cpp: for every type, the cells' volumes
// sum to the box's, every cell is positive, the mesh passes check_mesh, the mesh is
// conforming (each interior face shared by exactly two cells, the boundary faces exactly
// those of side sets 1-6), and every side set (1-6, the gap 10, the mid-planes 11 and 12) lists
// faces on its plane with the outward normal and the plane's area.
// KILN_TEST_NP: 1
#include "mesh/box_mesh_generator.hpp"

#include "mesh/hex_geometry.hpp"
#include "mesh/mesh_checks.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>

namespace
{
using kiln::Mesh;
using kiln::Point;

struct Case
{
  std::string type;
  int cells_per_hex; // 0: MIXED (11 in its pyramid layer, 1 or 6 elsewhere)
  int nodes;         // for a 2 x 2 x 2 grid
};

Mesh generate(const std::string &type, const std::array<int, 3> &cells,
              const std::array<double, 3> &size, const double phi, const double theta,
              const bool mid = false)
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  p.set("Cells", Teuchos::Array<int>(Teuchos::tuple(cells[0], cells[1], cells[2])));
  p.set("Size", Teuchos::Array<double>(Teuchos::tuple(size[0], size[1], size[2])));
  p.set("Phi", phi);
  p.set("Theta", theta);
  p.set("Translation", Teuchos::Array<double>(Teuchos::tuple(0.1, -0.2, 0.3)));
  p.set("Cell Type", type);
  p.validateParameters(kiln::BoxMeshGenerator::valid_parameters());
  return kiln::BoxMeshGenerator(p, "test/Box").generate(mid, mid);
}

/// The face's nodal area vectors and their sum (the face's area vector).
Point face_area_vector(const Mesh &mesh, const int c, const int f, double *area)
{
  const kiln::FaceNodalAreas a = kiln::face_nodal_areas(mesh, c, f);
  Point sum{0, 0, 0};
  *area = 0;
  for (std::size_t i = 0; i < a.area.size(); ++i)
  {
    *area += a.area[i];
    for (int d = 0; d < 3; ++d)
      sum[d] += a.area_vector[i][d];
  }
  return sum;
}

/// The volume of cell c by the divergence theorem, 1/3 sum over faces of sum_i x_i . int N_i n
/// (exact: the geometry is interpolated by the face's basis, the faces are planar).
double cell_volume(const Mesh &mesh, const int c)
{
  double v = 0;
  for (int f = 0; f < mesh.reference_cell(c).n_faces(); ++f)
  {
    const kiln::FaceNodalAreas a = kiln::face_nodal_areas(mesh, c, f);
    const std::vector<int> nodes = mesh.face_nodes(c, f);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      v += kiln::dot(mesh.coordinates[nodes[i]], a.area_vector[i]) / 3;
  }
  return v;
}

void expect_box(const Case &t, const std::array<int, 3> &cells, const std::array<double, 3> &L,
                const double phi, const double theta)
{
  SCOPED_TRACE(t.type);
  const Mesh mesh = generate(t.type, cells, L, phi, theta, true);
  const int n_hex = cells[0] * cells[1] * cells[2];
  if (t.cells_per_hex > 0)
  {
    ASSERT_EQ(mesh.n_cells(), n_hex * t.cells_per_hex);
    EXPECT_EQ(kiln::ReferenceCell::of(mesh.cell_type(0)).name(), t.type);
  }
  // The predicted counts are what generate() makes.
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  p.set("Cells", Teuchos::Array<int>(Teuchos::tuple(cells[0], cells[1], cells[2])));
  p.set("Cell Type", t.type);
  const kiln::BoxMeshGenerator generator(p, "test/Box");
  EXPECT_EQ(generator.n_cells(), mesh.n_cells());
  EXPECT_EQ(generator.n_nodes(), mesh.n_nodes());
  EXPECT_NO_THROW(kiln::check_mesh(mesh, "test/Box"));

  const double box_volume = L[0] * L[1] * L[2];
  double volume = 0;
  for (int c = 0; c < mesh.n_cells(); ++c)
  {
    const double v = cell_volume(mesh, c);
    EXPECT_GT(v, 0) << "cell " << c;
    volume += v;
  }
  EXPECT_NEAR(volume, box_volume, 1e-13 * box_volume);

  // Conforming: interior faces in two cells, with opposite normals; boundary faces in one.
  std::map<kiln::FaceKey, std::vector<std::pair<int, int>>> faces;
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int f = 0; f < mesh.reference_cell(c).n_faces(); ++f)
      faces[mesh.face_key(c, f)].emplace_back(c, f);
  std::set<std::pair<int, int>> boundary;
  for (const auto &[key, sides] : faces)
  {
    ASSERT_LE(sides.size(), 2u);
    if (sides.size() == 1)
      boundary.insert(sides[0]);
    else
    {
      double a0 = 0, a1 = 0;
      const Point n0 = face_area_vector(mesh, sides[0].first, sides[0].second, &a0);
      const Point n1 = face_area_vector(mesh, sides[1].first, sides[1].second, &a1);
      for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(n0[d] + n1[d], 0.0, 1e-14 * a0);
      // The two cells list the same nodes (mid-side nodes shared too).
      std::vector<int> s0 = mesh.face_nodes(sides[0].first, sides[0].second),
                       s1 = mesh.face_nodes(sides[1].first, sides[1].second);
      std::sort(s0.begin(), s0.end());
      std::sort(s1.begin(), s1.end());
      EXPECT_EQ(s0, s1);
    }
  }

  const auto A = kiln::rotation_matrix(phi, theta);
  const auto axis_normal = [&](const int axis, const double sign) {
    return Point{sign * A[0][axis], sign * A[1][axis], sign * A[2][axis]};
  };
  std::set<std::pair<int, int>> listed_outer;
  // id, axis, sign of the normal (0: the mid-planes, both signs), area of the plane, sides.
  for (const kiln::SideSet &set : mesh.side_sets)
  {
    SCOPED_TRACE("side set " + std::to_string(set.id));
    const int axis = set.id <= 6 ? (set.id - 1) / 2 : set.id == 10 ? 0 : set.id - 10;
    const double plane_area = box_volume / L[axis];
    const bool two_sided = set.id >= 10;
    double area[2] = {0, 0};
    ASSERT_EQ(set.cells.size(), set.faces.size());
    std::set<std::pair<int, int>> entries;
    for (int s = 0; s < set.n_sides(); ++s)
    {
      EXPECT_TRUE(entries.emplace(set.cells[s], set.faces[s]).second) << "listed twice";
      double a = 0;
      const Point v = face_area_vector(mesh, set.cells[s], set.faces[s], &a);
      // Outer planes: outward; two-sided: the first half +axis (the lower side), then -axis.
      const double sign = !two_sided              ? (set.id % 2 == 0 ? 1.0 : -1.0)
                          : 2 * s < set.n_sides() ? 1.0
                                                  : -1.0;
      const Point n = axis_normal(axis, sign);
      for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(v[d] / a, n[d], 1e-13) << "entry " << s;
      area[two_sided && 2 * s >= set.n_sides()] += a;
      if (!two_sided)
      {
        listed_outer.emplace(set.cells[s], set.faces[s]);
        EXPECT_EQ(boundary.count({set.cells[s], set.faces[s]}), 1u) << "entry " << s;
      }
    }
    EXPECT_NEAR(area[0], plane_area, 1e-13 * plane_area);
    if (two_sided)
    {
      EXPECT_NEAR(area[1], plane_area, 1e-13 * plane_area);
    }
  }
  EXPECT_EQ(listed_outer, boundary);
  // The gap's first half is block 1, the second block 2.
  const kiln::SideSet &gap = *mesh.find_side_set(10);
  for (int s = 0; s < gap.n_sides(); ++s)
    EXPECT_EQ(mesh.block_id[gap.cells[s]], 2 * s < gap.n_sides() ? 1 : 2) << "gap entry " << s;
}

// PYRAMID5: the corners and one centre per hexahedron; MIXED (2 x 2 x 2: one layer of hexahedra,
// one of pyramids and tets): the corners and the layer's 4 centres.
const Case cases[] = {{"HEX8", 1, 27},  {"TETRA4", 6, 27}, {"WEDGE6", 2, 27},   {"PYRAMID5", 6, 35},
                      {"HEX20", 1, 81}, {"HEX27", 1, 125}, {"TETRA10", 6, 125}, {"MIXED", 0, 31}};

TEST(BoxMeshCellTypes, RotatedBoxOfEachType)
{
  for (const Case &t : cases)
    expect_box(t, {4, 2, 2}, {0.08, 0.03, 0.05}, 45, -30);
}

TEST(BoxMeshCellTypes, UnevenCountsOfEachType)
{
  for (const Case &t : cases)
    expect_box(t, {2, 4, 6}, {1.0, 2.0, 3.0}, -70, 20);
}

TEST(BoxMeshCellTypes, NodeCountsOfA2x2x2Grid)
{
  for (const Case &t : cases)
    EXPECT_EQ(generate(t.type, {2, 2, 2}, {1, 1, 1}, 0, 0).n_nodes(), t.nodes) << t.type;
}

TEST(BoxMeshCellTypes, MixedHasHexahedraPyramidsAndTetrahedraByBlock)
{
  // 6 x 1 x 2: 3 hexahedra per row for x < 0, then a layer of 1 pyramid and 10 tets each, then
  // 2 hexahedra of 6 Kuhn tets each.
  const Mesh mesh = generate("MIXED", {6, 1, 2}, {3.0, 0.5, 1.0}, 0, 0);
  std::map<int, std::map<std::string, int>> by_block;
  for (int c = 0; c < mesh.n_cells(); ++c)
    ++by_block[mesh.block_id[c]][kiln::ReferenceCell::of(mesh.cell_type(c)).name()];
  const std::map<int, std::map<std::string, int>> expected = {
      {1, {{"HEX8", 6}}}, {2, {{"PYRAMID5", 2}}}, {3, {{"TETRA4", 2 * 10 + 4 * 6}}}};
  EXPECT_EQ(by_block, expected);
  // Blocks in order, as the Exodus writer wants them.
  for (int c = 1; c < mesh.n_cells(); ++c)
    EXPECT_LE(mesh.block_id[c - 1], mesh.block_id[c]);
  // The pyramids stand on the plane x = 0 (the gap's second half), apex towards +x.
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (mesh.cell_type(c) == kiln::CellType::pyramid5)
    {
      const kiln::Span<const int> nodes = mesh.cell_nodes(c);
      for (int n = 0; n < 4; ++n)
        EXPECT_NEAR(mesh.coordinates[nodes[n]][0], 0.1, 1e-15);
      EXPECT_NEAR(mesh.coordinates[nodes[4]][0], 0.35, 1e-15);
    }
}

TEST(BoxMeshCellTypes, Hex8IsTheDefault)
{
  const Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  EXPECT_EQ(p.get<std::string>("Cell Type"), "HEX8");
  const Mesh mesh = kiln::BoxMeshGenerator(p, "test/Box").generate();
  EXPECT_EQ(mesh.types(), std::vector<kiln::CellType>{kiln::CellType::hex8});
}

TEST(BoxMeshCellTypes, OtherTypesAreRejectedByTheValidator)
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  EXPECT_ANY_THROW({
    p.set("Cell Type", "PYRAMID13");
    p.validateParameters(kiln::BoxMeshGenerator::valid_parameters());
  });
}
} // namespace
