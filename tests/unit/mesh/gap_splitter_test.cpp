// Tests src/mesh/gap_splitter.cpp: splitting the contact box (generated and the Cubit file) at
// side set 10 into coincident node pairs with areas and normals, and the InputErrors for side
// sets that cannot split the mesh.
// KILN_TEST_NP: 1
#include "mesh/gap_splitter.hpp"

#include "base/errors.hpp"
#include "mesh/box_mesh_generator.hpp"
#include "mesh/exodus_io.hpp"
#include "support/parameter_lists.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

namespace
{
using kiln::Mesh;
using kiln::Point;
using testing::HasSubstr;

constexpr double cm = 0.01;

/// The contact box: 4 x 4 x 4 cells of 1 cm, phi = 45, theta = -30.
Mesh contact_box()
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  p.set("Cells", Teuchos::Array<int>(Teuchos::tuple(4, 4, 4)));
  p.set("Size", Teuchos::Array<double>(Teuchos::tuple(4 * cm, 4 * cm, 4 * cm)));
  p.set("Phi", 45.0);
  p.set("Theta", -30.0);
  return kiln::BoxMeshGenerator(p, "test/Box").generate();
}

/// A (1, 0, 0) rotated by phi = 45 about y then theta = -30 about x, by hand:
/// Ry(45) e_x = (c, 0, -c) with c = sqrt(1/2); Rx(-30) (a, b, d) = (a, b cos30 + d/2, -b/2 + d
/// cos30).
Point rotated_x()
{
  const double c = std::sqrt(0.5), c30 = std::sqrt(3.0) / 2;
  return {c, -c / 2, -c * c30};
}

/// The blocks of the cells around each node.
std::vector<std::set<int>> node_blocks(const Mesh &mesh)
{
  std::vector<std::set<int>> blocks(mesh.n_nodes());
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (const int n : mesh.cell_nodes(c))
      blocks[n].insert(mesh.block_id[c]);
  return blocks;
}

/// What a split of the contact box must give, whatever the mesh's origin.
void expect_split_contact_box(const Mesh &original, const Mesh &mesh)
{
  ASSERT_EQ(mesh.n_nodes(), 150);
  ASSERT_EQ(mesh.gap_pairs.size(), 25U);
  ASSERT_EQ(mesh.parent_node.size(), 150U);
  EXPECT_EQ(mesh.gap_side_sets, std::vector<int>{10});
  EXPECT_EQ(mesh.n_cells(), original.n_cells());
  EXPECT_EQ(mesh.block_id, original.block_id);

  // The original nodes keep their number and coordinates; each twin copies its parent.
  for (int n = 0; n < original.n_nodes(); ++n)
  {
    EXPECT_EQ(mesh.parent_node[n], n);
    EXPECT_EQ(mesh.coordinates[n], original.coordinates[n]);
  }
  for (int n = original.n_nodes(); n < mesh.n_nodes(); ++n)
  {
    const int parent = mesh.parent_node[n];
    ASSERT_TRUE(parent >= 0 && parent < original.n_nodes()) << "node " << n;
    EXPECT_EQ(mesh.coordinates[n], original.coordinates[parent]) << "node " << n;
  }
  // Each cell has the same nodes as before, up to twins.
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int i = 0; i < 8; ++i)
      EXPECT_EQ(mesh.parent_node[mesh.cell_nodes(c)[i]], original.cell_nodes(c)[i])
          << "cell " << c << " node " << i;

  const auto blocks = node_blocks(mesh);
  const auto blocks_before = node_blocks(original);
  std::set<int> node_a_set, node_b_set;
  double total_area = 0.0;
  int previous_a = -1;
  for (std::size_t k = 0; k < mesh.gap_pairs.size(); ++k)
  {
    const kiln::GapPair &pair = mesh.gap_pairs[k];
    SCOPED_TRACE("pair " + std::to_string(k));
    ASSERT_TRUE(pair.node_a >= 0 && pair.node_a < original.n_nodes());
    ASSERT_TRUE(pair.node_b >= original.n_nodes() && pair.node_b < mesh.n_nodes());
    EXPECT_GT(pair.node_a, previous_a) << "pairs in increasing node_a order";
    previous_a = pair.node_a;
    node_a_set.insert(pair.node_a);
    node_b_set.insert(pair.node_b);
    EXPECT_EQ(mesh.parent_node[pair.node_b], pair.node_a);
    EXPECT_EQ(blocks_before[pair.node_a], (std::set<int>{1, 2}))
        << "a pair's node was shared by both blocks before the split";
    EXPECT_EQ(blocks[pair.node_a], std::set<int>{1});
    EXPECT_EQ(blocks[pair.node_b], std::set<int>{2});
    EXPECT_EQ(mesh.coordinates[pair.node_a], mesh.coordinates[pair.node_b]);
    EXPECT_NEAR(std::sqrt(pair.normal[0] * pair.normal[0] + pair.normal[1] * pair.normal[1] +
                          pair.normal[2] * pair.normal[2]),
                1.0, 1e-14);
    EXPECT_GT(pair.area, 0.0);
    total_area += pair.area;
  }
  EXPECT_EQ(node_a_set.size(), 25U);
  EXPECT_EQ(node_b_set.size(), 25U);
  EXPECT_NEAR(total_area, 16 * cm * cm, 1e-15);

  // Only the pairs' nodes were split: no other node is shared between the blocks any more.
  for (int n = 0; n < mesh.n_nodes(); ++n)
    EXPECT_EQ(blocks[n].size(), 1U) << "node " << n;
  // No cell of block 2 refers to a node_a, no cell of block 1 to a node_b.
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (const int n : mesh.cell_nodes(c))
    {
      if (mesh.block_id[c] == 2)
        EXPECT_EQ(node_a_set.count(n), 0U) << "cell " << c;
      else
        EXPECT_EQ(node_b_set.count(n), 0U) << "cell " << c;
    }
}

TEST(GapSplitter, GeneratedRotatedBox)
{
  const Mesh original = contact_box();
  Mesh mesh = original;
  kiln::split_gap(mesh, 10, "test");
  expect_split_contact_box(original, mesh);

  const Point normal = rotated_x();
  // Nodes of the 4 x 4 grid of 1 cm faces: 9 interior (4 faces), 12 on edges (2), 4 corners (1).
  int n_interior = 0, n_edge = 0, n_corner = 0;
  for (const kiln::GapPair &pair : mesh.gap_pairs)
  {
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(pair.normal[d], normal[d], 1e-14) << "pair of node " << pair.node_a;
    if (std::abs(pair.area - 1e-4) < 1e-18)
      ++n_interior;
    else if (std::abs(pair.area - 0.5e-4) < 1e-18)
      ++n_edge;
    else if (std::abs(pair.area - 0.25e-4) < 1e-18)
      ++n_corner;
    else
      ADD_FAILURE() << "pair of node " << pair.node_a << " has area " << pair.area;
  }
  EXPECT_EQ(n_interior, 9);
  EXPECT_EQ(n_edge, 12);
  EXPECT_EQ(n_corner, 4);

  // In the generator's numbering node (i, j, k) is i + 5 (j + 5 k); the cut is i = 2.
  for (const kiln::GapPair &pair : mesh.gap_pairs)
  {
    const int i = pair.node_a % 5, j = pair.node_a / 5 % 5, k = pair.node_a / 25;
    EXPECT_EQ(i, 2);
    const bool j_inside = j > 0 && j<4, k_inside = k> 0 && k < 4;
    const double expected = 1e-4 * (j_inside ? 1 : 0.5) * (k_inside ? 1 : 0.5);
    EXPECT_NEAR(pair.area, expected, 1e-18) << "node (" << i << ", " << j << ", " << k << ")";
  }
}

TEST(GapSplitter, CubitRotatedCube)
{
  const Mesh original =
      kiln::read_exodus_mesh(std::string(KILN_SHARED_DIR) + "/meshes/rotated-cube.exo", cm);
  Mesh mesh = original;
  kiln::split_gap(mesh, 10, "test");
  expect_split_contact_box(original, mesh);

  // One plane: all normals equal. The file's block 1 is the x < 0 half of the spec's rotation,
  // so they also equal A (1, 0, 0), to the precision the file's coordinates carry.
  const Point &first = mesh.gap_pairs.front().normal;
  const Point normal = rotated_x();
  for (const kiln::GapPair &pair : mesh.gap_pairs)
    for (int d = 0; d < 3; ++d)
    {
      EXPECT_NEAR(pair.normal[d], first[d], 1e-12) << "pair of node " << pair.node_a;
      EXPECT_NEAR(pair.normal[d], normal[d], 1e-6) << "pair of node " << pair.node_a;
    }
}

std::string split_error(Mesh mesh, const int side_set)
{
  const std::string message =
      kiln_test::input_error_message([&] { kiln::split_gap(mesh, side_set, "in.xml: Kiln/Mesh"); });
  if (message.empty())
    ADD_FAILURE() << "no InputError for side set " << side_set;
  return message;
}

TEST(GapSplitter, AbsentSideSetListsThePresentOnes)
{
  const std::string message = split_error(contact_box(), 7);
  EXPECT_THAT(message, HasSubstr("in.xml: Kiln/Mesh"));
  EXPECT_THAT(message, HasSubstr("side set 7 is not in the mesh"));
  EXPECT_THAT(message, HasSubstr("1, 2, 3, 4, 5, 6, 10"));
}

TEST(GapSplitter, BoundarySideSetHasNoInteriorFace)
{
  for (const int id : {1, 4, 6})
  {
    const std::string message = split_error(contact_box(), id);
    EXPECT_THAT(message, HasSubstr("in.xml: Kiln/Mesh"));
    EXPECT_THAT(message, HasSubstr("side set " + std::to_string(id) + " has no interior face"));
  }
}

TEST(GapSplitter, SideSetThatDoesNotCutTheMesh)
{
  // Half of the cut plane (block 1's faces with y index 0 or 1): the two halves stay connected
  // through the other half.
  Mesh mesh = contact_box();
  const kiln::SideSet gap = *mesh.find_side_set(10);
  kiln::SideSet half;
  half.id = 11;
  for (int s = 0; s < gap.n_sides(); ++s)
  {
    // Block 1 cells are numbered i + 2 (j + 4 k) (x-fastest in a 2 x 4 x 4 half).
    const int cell = gap.cells[s];
    if (mesh.block_id[cell] == 1 && cell / 2 % 4 < 2)
    {
      half.cells.push_back(cell);
      half.faces.push_back(gap.faces[s]);
    }
  }
  ASSERT_EQ(half.n_sides(), 8);
  mesh.side_sets.push_back(half);
  const std::string message = split_error(mesh, 11);
  EXPECT_THAT(message, HasSubstr("in.xml: Kiln/Mesh"));
  EXPECT_THAT(message, HasSubstr("side set 11 does not cut the mesh"));
}

TEST(GapSplitter, SideSetFromOneSideOnlySplitsTheSame)
{
  // Block 2's faces of side set 10 only: the same cut, so the same split.
  const Mesh original = contact_box();
  Mesh both = original, one_side = original;
  kiln::SideSet &gap = one_side.side_sets.back();
  ASSERT_EQ(gap.id, 10);
  gap.cells.erase(gap.cells.begin(), gap.cells.begin() + 16);
  gap.faces.erase(gap.faces.begin(), gap.faces.begin() + 16);
  kiln::split_gap(both, 10, "test");
  kiln::split_gap(one_side, 10, "test");
  EXPECT_EQ(one_side.cell_node_ids, both.cell_node_ids);
  EXPECT_TRUE(one_side.cell_types == both.cell_types);
  EXPECT_EQ(one_side.parent_node, both.parent_node);
  ASSERT_EQ(one_side.gap_pairs.size(), both.gap_pairs.size());
  for (std::size_t k = 0; k < both.gap_pairs.size(); ++k)
  {
    EXPECT_EQ(one_side.gap_pairs[k].node_a, both.gap_pairs[k].node_a);
    EXPECT_EQ(one_side.gap_pairs[k].node_b, both.gap_pairs[k].node_b);
    EXPECT_DOUBLE_EQ(one_side.gap_pairs[k].area, both.gap_pairs[k].area);
  }
}
} // namespace

TEST(GapSplitter, GapFacesPairSideAFacesWithTheirTwins)
{
  Mesh mesh = contact_box();
  kiln::split_gap(mesh, 10, "test");
  ASSERT_EQ(mesh.gap_faces.size(), 16u); // 4 x 4 cut faces
  std::map<int, int> twin_of;
  for (const auto &p : mesh.gap_pairs)
    twin_of[p.node_a] = p.node_b;
  for (const auto &face : mesh.gap_faces)
  {
    EXPECT_EQ(mesh.block_id[face.cell_a], 1);
    EXPECT_EQ(mesh.block_id[face.cell_b], 2);
    std::set<int> b_face_nodes;
    for (int i = 0; i < 4; ++i)
      b_face_nodes.insert(mesh.face_node(face.cell_b, face.face_b, i));
    for (int i = 0; i < 4; ++i)
    {
      const int a = mesh.face_node(face.cell_a, face.face_a, i);
      ASSERT_EQ(twin_of.count(a), 1u) << "face node " << a << " is not a node_a";
      EXPECT_EQ(face.node_b[i], twin_of[a]);
      EXPECT_EQ(b_face_nodes.count(face.node_b[i]), 1u);
      EXPECT_EQ(mesh.coordinates[a], mesh.coordinates[face.node_b[i]]);
    }
  }
}
