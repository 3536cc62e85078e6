// Tests src/mesh/mesh_bodies.cpp: the connected sets of cells of a mesh, before and after the
// contact box is split at its gap, and a node of no cell.
// KILN_TEST_NP: 1
#include "mesh/mesh_bodies.hpp"

#include "mesh/box_mesh_generator.hpp"
#include "mesh/gap_splitter.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>
#include <gtest/gtest.h>

#include <algorithm>

namespace
{
/// The contact box of 4 x 4 x 4 cells, rotated.
kiln::Mesh contact_box()
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  p.set("Cells", Teuchos::Array<int>(Teuchos::tuple(4, 4, 4)));
  p.set("Phi", 45.0);
  p.set("Theta", -30.0);
  return kiln::BoxMeshGenerator(p, "test/Box").generate();
}

TEST(MeshBodies, OneBodyBeforeTheSplit)
{
  const kiln::Mesh mesh = contact_box();
  const kiln::MeshBodies bodies = kiln::mesh_bodies(mesh);
  EXPECT_EQ(bodies.count, 1);
  ASSERT_EQ(bodies.body.size(), 125u);
  EXPECT_TRUE(std::all_of(bodies.body.begin(), bodies.body.end(), [](int b) { return b == 0; }));
}

TEST(MeshBodies, TheGapSplitsTheBoxIntoTwoBodies)
{
  kiln::Mesh mesh = contact_box();
  kiln::split_gap(mesh, 10, "test");
  const kiln::MeshBodies bodies = kiln::mesh_bodies(mesh);
  EXPECT_EQ(bodies.count, 2);
  ASSERT_EQ(bodies.body.size(), 150u); // 125 nodes and 25 twins
  // Every cell lies in one body, and the twins of every pair in different ones.
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (const int n : mesh.cell_nodes(c))
      EXPECT_EQ(bodies.body[n], bodies.body[mesh.cell_nodes(c)[0]]);
  ASSERT_EQ(mesh.gap_pairs.size(), 25u);
  for (const kiln::GapPair &pair : mesh.gap_pairs)
    EXPECT_NE(bodies.body[pair.node_a], bodies.body[pair.node_b]);
  // Half of the cube each side: 3 x 5 x 5 nodes.
  EXPECT_EQ(std::count(bodies.body.begin(), bodies.body.end(), 0), 75);
  EXPECT_EQ(std::count(bodies.body.begin(), bodies.body.end(), 1), 75);
  // Numbered in the order of their first cells.
  EXPECT_EQ(bodies.body[mesh.cell_nodes(0)[0]], 0);
}

TEST(MeshBodies, ANodeOfNoCellIsInNoBody)
{
  kiln::Mesh mesh = contact_box();
  mesh.coordinates.push_back({1.0, 1.0, 1.0});
  const kiln::MeshBodies bodies = kiln::mesh_bodies(mesh);
  EXPECT_EQ(bodies.count, 1);
  EXPECT_EQ(bodies.body.back(), -1);
}
} // namespace
