// Tests the box generator's halves meshed apart (src/mesh/box_mesh_generator.cpp, "Second Half
// Cells", "Gap Width"; issue 30): counts, blocks, no node shared by the halves, the side sets
// (1..6 on both halves, 10 and 20 the cut faces, their areas and outward normals), the cut
// faces on x = 0 and x = Gap Width of the box's own frame after the rotation, other cell types,
// and the input errors (a count list of the wrong size, a gap width with one mesh, a gap side
// set with the halves apart, through Mesh).
// KILN_TEST_NP: 1
#include "mesh/box_mesh_generator.hpp"

#include "base/parameters.hpp"
#include "mesh/contact_surface.hpp"
#include "mesh/mesh_factory.hpp"
#include "support/parameter_lists.hpp"
#include "support/two_body_mesh.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace
{
using kiln::Mesh;
using kiln::Point;
using testing::HasSubstr;

constexpr double phi = 45.0, theta = -30.0, L = 0.04;

/// The contact box (0.04 m, rotated by phi, theta) with halves 4x4x4 and 5x3x6, apart by
/// `gap`, of `type`.
Teuchos::ParameterList halves(const double gap, const std::string &type = "HEX8")
{
  return kiln_test::box_halves_parameters(gap, type);
}

/// The point in the box's own frame (the rotation undone).
Point own_frame(const Point &y)
{
  return kiln_test::rotated(y, phi, theta, true);
}

std::set<int> nodes_of_block(const Mesh &mesh, const int block)
{
  std::set<int> nodes;
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (mesh.block_id[c] == block)
      for (const int n : mesh.cell_nodes(c))
        nodes.insert(n);
  return nodes;
}

/// The coordinate along axis `d` (own frame) of every node of side set `id`'s faces, in [lo,
/// hi] when `all`, and the side set's total area vector.
void expect_on_plane(const Mesh &mesh, const int id, const int d, const double at,
                     const Point &outward, const double area)
{
  SCOPED_TRACE("side set " + std::to_string(id));
  const kiln::SideSet *set = mesh.find_side_set(id);
  ASSERT_NE(set, nullptr);
  for (int s = 0; s < set->n_sides(); ++s)
    for (const int n : mesh.face_nodes(set->cells[s], set->faces[s]))
      EXPECT_NEAR(own_frame(mesh.coordinates[n])[d], at, 1e-15);
  const kiln::ContactSurface surface(mesh, id, "test");
  Point sum{0, 0, 0};
  for (int f = 0; f < surface.n_faces(); ++f)
    for (int i = 0; i < 3; ++i)
      sum[i] += surface.face_area_vector(f)[i];
  const Point own = own_frame(sum);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(own[i], area * outward[i], 1e-17);
}
} // namespace

TEST(BoxMeshHalves, CountsBlocksAndNoSharedNodes)
{
  const kiln::BoxMeshGenerator generator(halves(0.0), "test/Box");
  EXPECT_TRUE(generator.separate_halves());
  const Mesh mesh = generator.generate();
  // 5 x 5 x 5 and 6 x 4 x 7 nodes; 64 and 90 cells.
  EXPECT_EQ(mesh.n_nodes(), 125 + 168);
  EXPECT_EQ(mesh.n_cells(), 64 + 90);
  EXPECT_EQ(generator.n_nodes(), mesh.n_nodes());
  EXPECT_EQ(generator.n_cells(), mesh.n_cells());
  for (int c = 0; c < mesh.n_cells(); ++c)
    EXPECT_EQ(mesh.block_id[c], c < 64 ? 1 : 2) << "cell " << c;
  const std::set<int> one = nodes_of_block(mesh, 1), two = nodes_of_block(mesh, 2);
  EXPECT_EQ(one.size(), 125u);
  EXPECT_EQ(two.size(), 168u);
  EXPECT_EQ(*one.rbegin(), 124); // block 1's nodes first
  EXPECT_EQ(*two.begin(), 125);
  // Each half inside its own part of the box.
  for (const int n : one)
    EXPECT_LE(own_frame(mesh.coordinates[n])[0], 1e-15);
  for (const int n : two)
    EXPECT_GE(own_frame(mesh.coordinates[n])[0], -1e-15);
}

TEST(BoxMeshHalves, SideSetsTouching)
{
  const Mesh mesh = kiln::BoxMeshGenerator(halves(0.0), "test/Box").generate();
  std::vector<int> ids;
  for (const kiln::SideSet &set : mesh.side_sets)
    ids.push_back(set.id);
  EXPECT_EQ(ids, (std::vector<int>{1, 2, 3, 4, 5, 6, 10, 20}));
  // x_min on block 1 (4 x 4), x_max on block 2 (3 x 6), the others on both.
  const std::vector<int> sizes = {16, 18, 16 + 30, 16 + 30, 16 + 15, 16 + 15, 16, 18};
  for (std::size_t s = 0; s < sizes.size(); ++s)
    EXPECT_EQ(mesh.side_sets[s].n_sides(), sizes[s]) << "side set " << ids[s];
  EXPECT_EQ(mesh.find_side_set(10)->name, "cut_1");
  EXPECT_EQ(mesh.find_side_set(20)->name, "cut_2");
  for (int s = 0; s < mesh.find_side_set(10)->n_sides(); ++s)
    EXPECT_EQ(mesh.block_id[mesh.find_side_set(10)->cells[s]], 1);
  for (int s = 0; s < mesh.find_side_set(20)->n_sides(); ++s)
    EXPECT_EQ(mesh.block_id[mesh.find_side_set(20)->cells[s]], 2);
  const double area = L * L;
  expect_on_plane(mesh, 10, 0, 0.0, {1, 0, 0}, area);
  expect_on_plane(mesh, 20, 0, 0.0, {-1, 0, 0}, area);
  expect_on_plane(mesh, 1, 0, -L / 2, {-1, 0, 0}, area);
  expect_on_plane(mesh, 2, 0, L / 2, {1, 0, 0}, area);
  expect_on_plane(mesh, 3, 1, -L / 2, {0, -1, 0}, L * L);
  expect_on_plane(mesh, 6, 2, L / 2, {0, 0, 1}, L * L);
}

TEST(BoxMeshHalves, GapWidthMovesTheSecondHalf)
{
  const double g = 2e-6;
  const Mesh mesh = kiln::BoxMeshGenerator(halves(g), "test/Box").generate();
  expect_on_plane(mesh, 10, 0, 0.0, {1, 0, 0}, L * L);
  expect_on_plane(mesh, 20, 0, g, {-1, 0, 0}, L * L);
  expect_on_plane(mesh, 2, 0, L / 2 + g, {1, 0, 0}, L * L);
  expect_on_plane(mesh, 1, 0, -L / 2, {-1, 0, 0}, L * L);
}

TEST(BoxMeshHalves, Tetrahedra)
{
  const kiln::BoxMeshGenerator generator(halves(0.0, "TETRA4"), "test/Box");
  const Mesh mesh = generator.generate();
  EXPECT_EQ(mesh.n_nodes(), 125 + 168);
  EXPECT_EQ(mesh.n_cells(), 6 * (64 + 90));
  EXPECT_EQ(generator.n_cells(), mesh.n_cells());
  EXPECT_EQ(mesh.find_side_set(10)->n_sides(), 32);
  EXPECT_EQ(mesh.find_side_set(20)->n_sides(), 36);
  expect_on_plane(mesh, 20, 0, 0.0, {-1, 0, 0}, L * L);
}

TEST(BoxMeshHalves, CountsOfEveryCellType)
{
  for (const std::string type :
       {"HEX8", "TETRA4", "WEDGE6", "PYRAMID5", "HEX20", "HEX27", "TETRA10", "MIXED"})
  {
    SCOPED_TRACE(type);
    const kiln::BoxMeshGenerator generator(halves(0.0, type), "test/Box");
    const Mesh mesh = generator.generate();
    EXPECT_EQ(generator.n_nodes(), mesh.n_nodes());
    EXPECT_EQ(generator.n_cells(), mesh.n_cells());
    const std::set<int> one = nodes_of_block(mesh, 1);
    for (const int block : mesh.block_ids())
    {
      if (block == 1)
        continue;
      for (const int n : nodes_of_block(mesh, block))
        EXPECT_EQ(one.count(n), 0u) << "node " << n << " in blocks 1 and " << block;
    }
    // The cut faces cover the whole section on both sides (ContactSurface: linear faces).
    if (type.find('1') == std::string::npos && type.find('2') == std::string::npos)
    {
      expect_on_plane(mesh, 10, 0, 0.0, {1, 0, 0}, L * L);
      expect_on_plane(mesh, 20, 0, 0.0, {-1, 0, 0}, L * L);
    }
    else
    {
      EXPECT_GT(mesh.find_side_set(10)->n_sides(), 0);
      EXPECT_GT(mesh.find_side_set(20)->n_sides(), 0);
    }
  }
}

TEST(BoxMeshHalves, OneMeshByDefault)
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  const kiln::BoxMeshGenerator generator(p, "test/Box");
  EXPECT_FALSE(generator.separate_halves());
  const Mesh mesh = generator.generate();
  EXPECT_EQ(mesh.n_nodes(), 125);
  EXPECT_EQ(mesh.find_side_set(10)->n_sides(), 32); // from both sides
  EXPECT_EQ(mesh.find_side_set(20), nullptr);
}

TEST(BoxMeshHalves, WrongCountList)
{
  Teuchos::ParameterList p = halves(0.0);
  p.set("Second Half Cells", Teuchos::Array<int>(Teuchos::tuple(5, 3)));
  EXPECT_THAT(kiln_test::input_error_message([&] { kiln::BoxMeshGenerator(p, "in.xml: Box"); }),
              HasSubstr("in.xml: Box/\"Second Half Cells\": must be empty (one mesh) or three "
                        "counts > 0"));
}

TEST(BoxMeshHalves, GapWidthWithOneMesh)
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  p.set("Gap Width", 1e-6);
  EXPECT_THAT(kiln_test::input_error_message([&] { kiln::BoxMeshGenerator(p, "in.xml: Box"); }),
              HasSubstr("in.xml: Box/\"Gap Width\": is 1e-06 m, but the halves are one mesh"));
}

TEST(BoxMeshHalves, ThroughMeshNoGapUnlessAsked)
{
  Teuchos::ParameterList user("Mesh");
  user.sublist("Box").set("Cells", Teuchos::Array<int>(Teuchos::tuple(8, 4, 4)));
  user.sublist("Box").set("Second Half Cells", Teuchos::Array<int>(Teuchos::tuple(5, 3, 6)));
  const auto valid = kiln::MeshFactory::valid_parameters();
  const kiln::MeshFactory factory(kiln::validated(user, valid, "in.xml", "Kiln/Mesh"),
                                  "in.xml: Kiln/Mesh");
  EXPECT_TRUE(factory.gap_side_sets().empty()); // "Gap Side Set" 10 by default, not given
  const Mesh mesh = factory.build();
  EXPECT_EQ(mesh.n_nodes(), 125 + 168);

  user.set("Gap Side Set", 10);
  const std::string message = kiln_test::input_error_message(
      [&] {
        kiln::MeshFactory(kiln::validated(user, valid, "in.xml", "Kiln/Mesh"), "in.xml: Kiln/Mesh");
      });
  EXPECT_THAT(message, HasSubstr("in.xml: Kiln/Mesh/\"Gap Side Set\": names a gap, but "
                                 "Box/\"Second Half Cells\" meshes the halves apart"));
}
