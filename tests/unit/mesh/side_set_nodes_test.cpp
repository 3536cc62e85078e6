// Tests mesh/side_set_nodes: the nodes of a side set's faces, increasing and each once, on the
// generated 4^3 box (a face of 5 x 5 nodes; the gap plane's nodes on both of its sides before
// the split) and on HEX27 (9 nodes a face, 9 x 9 on the box's face).
#include "mesh/side_set_nodes.hpp"

#include "mesh/box_mesh_generator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace
{
kiln::Mesh box(const std::string &cell_type)
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  p.set("Cell Type", cell_type);
  return kiln::BoxMeshGenerator(p, "test/Box").generate();
}

/// Every node of the faces of `set`, from the cells, as a set.
std::set<int> face_nodes(const kiln::Mesh &mesh, const kiln::SideSet &set)
{
  std::set<int> nodes;
  for (int s = 0; s < set.n_sides(); ++s)
    for (const int n : mesh.face_nodes(set.cells[s], set.faces[s]))
      nodes.insert(n);
  return nodes;
}
} // namespace

TEST(SideSetNodes, IncreasingEachOnceEveryFaceNode)
{
  for (const auto &[type, per_edge] : {std::pair<std::string, int>{"HEX8", 5}, {"HEX27", 9}})
    for (const kiln::Mesh &mesh : {box(type)})
    {
      ASSERT_FALSE(mesh.side_sets.empty());
      for (const kiln::SideSet &set : mesh.side_sets)
      {
        const std::vector<int> nodes = kiln::side_set_nodes(mesh, set);
        EXPECT_TRUE(std::adjacent_find(nodes.begin(), nodes.end(), std::greater_equal<int>()) ==
                    nodes.end())
            << type << ", side set " << set.id << ": increasing, each once";
        const std::set<int> expected = face_nodes(mesh, set);
        EXPECT_EQ(std::vector<int>(expected.begin(), expected.end()), nodes)
            << type << ", side set " << set.id;
        if (set.id >= 1 && set.id <= 6)
        {
          EXPECT_EQ(nodes.size(), static_cast<std::size_t>(per_edge * per_edge))
              << type << ", box face " << set.id;
        }
      }
    }
}

TEST(SideSetNodes, EmptySideSetHasNoNodes)
{
  const kiln::Mesh mesh = box("HEX8");
  EXPECT_TRUE(kiln::side_set_nodes(mesh, kiln::SideSet{99, "none", {}, {}}).empty());
}
