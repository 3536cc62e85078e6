// Tests src/mesh/mesh_quality.cpp: the corner edges of every volume type, and the Jacobian and
// aspect ratios of cells whose values are known by hand, by block and element type.
// KILN_TEST_NP: 1
#include "mesh/mesh_quality.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace
{
using kiln::CellType;
using kiln::Mesh;

Mesh cells()
{
  Mesh mesh;
  // A unit cube (block 1), a 2 x 1 x 1 box (block 1), a tapered hex x = X (1 + z) (block 2),
  // the unit right tetrahedron (block 2).
  mesh.coordinates = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1},
                      {1, 1, 1}, {0, 1, 1}, {2, 0, 0}, {2, 1, 0}, {2, 0, 1}, {2, 1, 1}};
  mesh.add_cell(CellType::hex8, {0, 1, 2, 3, 4, 5, 6, 7}, 1);
  mesh.add_cell(CellType::hex8, {0, 8, 9, 3, 4, 10, 11, 7}, 1);
  mesh.add_cell(CellType::hex8, {0, 1, 2, 3, 4, 10, 11, 7}, 2);
  mesh.add_cell(CellType::tet4, {0, 1, 3, 4}, 2);
  return mesh;
}

TEST(MeshQuality, CornerEdgesOfEveryType)
{
  const auto edges = [](CellType t)
  { return kiln::corner_edges(kiln::ReferenceCell::of(t)).size(); };
  EXPECT_EQ(edges(CellType::hex8), 12u);
  EXPECT_EQ(edges(CellType::hex20), 12u);
  EXPECT_EQ(edges(CellType::hex27), 12u);
  EXPECT_EQ(edges(CellType::tet4), 6u);
  EXPECT_EQ(edges(CellType::tet10), 6u);
  EXPECT_EQ(edges(CellType::wedge6), 9u);
  EXPECT_EQ(edges(CellType::pyramid5), 8u);
}

TEST(MeshQuality, CellsOfKnownQuality)
{
  const Mesh mesh = cells();
  EXPECT_NEAR(kiln::cell_quality(mesh, 0).jacobian_ratio, 1.0, 1e-14);
  EXPECT_NEAR(kiln::cell_quality(mesh, 0).aspect_ratio, 1.0, 1e-14);
  EXPECT_NEAR(kiln::cell_quality(mesh, 1).jacobian_ratio, 1.0, 1e-14);
  EXPECT_NEAR(kiln::cell_quality(mesh, 1).aspect_ratio, 2.0, 1e-14);
  // det J is proportional to 1 + z: at the 2x2x2 Gauss points z = 1/2 -+ 1/(2 sqrt 3).
  const double g = 0.5 / std::sqrt(3.0);
  EXPECT_NEAR(kiln::cell_quality(mesh, 2).jacobian_ratio, (1.5 - g) / (1.5 + g), 1e-14);
  EXPECT_NEAR(kiln::cell_quality(mesh, 2).aspect_ratio, 2.0, 1e-14);
  EXPECT_NEAR(kiln::cell_quality(mesh, 3).jacobian_ratio, 1.0, 1e-14);
  EXPECT_NEAR(kiln::cell_quality(mesh, 3).aspect_ratio, std::sqrt(2.0), 1e-14);
}

TEST(MeshQuality, RangesByBlockAndType)
{
  const auto quality = kiln::mesh_quality(cells());
  ASSERT_EQ(quality.size(), 3u);
  EXPECT_EQ(quality[0].block, 1);
  EXPECT_EQ(quality[0].type, CellType::hex8);
  EXPECT_EQ(quality[0].n_cells, 2);
  EXPECT_NEAR(quality[0].min_aspect_ratio, 1.0, 1e-14);
  EXPECT_NEAR(quality[0].max_aspect_ratio, 2.0, 1e-14);
  EXPECT_NEAR(quality[0].min_jacobian_ratio, 1.0, 1e-14);
  EXPECT_EQ(quality[1].block, 2);
  EXPECT_EQ(quality[1].type, CellType::hex8);
  EXPECT_EQ(quality[1].n_cells, 1);
  EXPECT_LT(quality[1].min_jacobian_ratio, 0.7);
  EXPECT_EQ(quality[2].block, 2);
  EXPECT_EQ(quality[2].type, CellType::tet4);
  EXPECT_EQ(quality[2].n_cells, 1);
  std::ostringstream out;
  kiln::print_mesh_quality(quality, out);
  EXPECT_EQ(out.str(), "mesh quality (Jacobian ratio: min / max det J over a cell's "
                       "quadrature points; aspect ratio: longest / shortest corner edge):\n"
                       "  block 1: HEX8, 2 cells, Jacobian ratio 1 to 1, aspect ratio 1 to 2\n"
                       "  block 2: HEX8, 1 cell, Jacobian ratio 0.677 to 0.677, aspect ratio 2 "
                       "to 2\n"
                       "  block 2: TETRA4, 1 cell, Jacobian ratio 1 to 1, aspect ratio 1.41 to "
                       "1.41\n");
}
} // namespace
