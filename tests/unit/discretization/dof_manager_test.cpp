// Tests src/discretization/dof_manager.cpp: ownership of nodes, pairs and unknowns on the split
// contact box, the owned and overlap Tpetra maps, and the importer and exporter between them.
// KILN_TEST_NP: 1 2 3
#include "discretization/dof_manager.hpp"

#include "mesh/box_mesh_generator.hpp"
#include "mesh/gap_splitter.hpp"
#include "mesh/metis_partitioner.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_Tuple.hpp>
#include <Tpetra_Vector.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <set>
#include <vector>

namespace
{
using kiln::GO;
using kiln::Mesh;

constexpr int n_nodes = 150, n_pairs = 25;

/// The contact box, 4 x 4 x 4, rotated, split at side set 10.
Mesh split_box()
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  p.set("Phi", 45.0);
  p.set("Theta", -30.0);
  Mesh mesh = kiln::BoxMeshGenerator(p, "test/Box").generate();
  kiln::split_gap(mesh, 10, "test");
  return mesh;
}

class DofManagerTest : public testing::Test
{
protected:
  DofManagerTest()
      : comm(Teuchos::DefaultComm<int>::getComm()), rank(comm->getRank()), np(comm->getSize()),
        mesh(split_box()), cell_rank(kiln::partition_cells(mesh, *comm, "test")),
        dofs(mesh, cell_rank, comm)
  {
    // Independently of the code: the ranks whose cells touch each node, and the owner (lowest).
    node_ranks.resize(mesh.n_nodes());
    for (int c = 0; c < mesh.n_cells(); ++c)
      for (const int n : mesh.connectivity[c])
        node_ranks[n].insert(cell_rank[c]);
    // The ranks that hold each node in their overlap: those of its cells, the
    // rank of each gap face's side-a cell (for the twins), and the owner of
    // each pair's node_a (for node_b).
    overlap_ranks = node_ranks;
    for (const auto &face : mesh.gap_faces)
      for (const int n : face.node_b)
        overlap_ranks[n].insert(cell_rank[face.cell_a]);
    for (const auto &pair : mesh.gap_pairs)
      overlap_ranks[pair.node_b].insert(owner(pair.node_a));
  }

  Teuchos::RCP<const Teuchos::Comm<int>> comm;
  int rank, np;
  Mesh mesh;
  std::vector<int> cell_rank;
  kiln::DofManager dofs;
  std::vector<std::set<int>> node_ranks;
  std::vector<std::set<int>> overlap_ranks;

  int owner(const int node) const { return *node_ranks[node].begin(); }
  bool touched_here(const int node) const { return overlap_ranks[node].count(rank) > 0; }
  std::vector<GO> node_dofs(const int node) const
  {
    return {4 * GO(node), 4 * GO(node) + 1, 4 * GO(node) + 2, 4 * GO(node) + 3};
  }
};

TEST_F(DofManagerTest, DofNumbering)
{
  ASSERT_EQ(mesh.n_nodes(), n_nodes);
  ASSERT_EQ(static_cast<int>(mesh.gap_pairs.size()), n_pairs);
  EXPECT_EQ(dofs.dof(0, kiln::Field::T), 0);
  EXPECT_EQ(dofs.dof(7, kiln::Field::ux), 29);
  EXPECT_EQ(dofs.dof(7, kiln::Field::uy), 30);
  EXPECT_EQ(dofs.dof(149, kiln::Field::uz), 599);
  EXPECT_EQ(dofs.contact_dof(0), 600);
  EXPECT_EQ(dofs.contact_dof(24), 624);
}

TEST_F(DofManagerTest, OwnedCellsNodesAndPairs)
{
  std::vector<int> cells, nodes, overlap, pairs;
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (cell_rank[c] == rank)
      cells.push_back(c);
  for (int n = 0; n < mesh.n_nodes(); ++n)
  {
    if (owner(n) == rank)
      nodes.push_back(n);
    if (touched_here(n))
      overlap.push_back(n);
  }
  for (int k = 0; k < n_pairs; ++k)
    if (owner(mesh.gap_pairs[k].node_a) == rank)
      pairs.push_back(k);
  EXPECT_EQ(dofs.owned_cells(), cells);
  EXPECT_EQ(dofs.owned_nodes(), nodes);
  EXPECT_EQ(dofs.overlap_nodes(), overlap);
  EXPECT_EQ(dofs.owned_pairs(), pairs);
  for (int n = 0; n < mesh.n_nodes(); ++n)
    EXPECT_EQ(dofs.node_owner()[n], owner(n)) << "node " << n;
}

TEST_F(DofManagerTest, OwnedDofMap)
{
  const auto owned = dofs.owned_dof_map();
  EXPECT_EQ(dofs.n_global_dofs(), 4 * n_nodes + n_pairs);
  EXPECT_EQ(owned->getGlobalNumElements(), static_cast<Tpetra::global_size_t>(4 * 150 + 25));
  EXPECT_TRUE(owned->isOneToOne());
  EXPECT_EQ(owned->getIndexBase(), 0);
  EXPECT_EQ(owned->getMinAllGlobalIndex(), 0);
  EXPECT_EQ(owned->getMaxAllGlobalIndex(), 4 * n_nodes + n_pairs - 1);

  // The owned counts add up to the global count.
  const long local = static_cast<long>(dofs.n_owned_dofs());
  long sum = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(sum));
  EXPECT_EQ(sum, 4 * n_nodes + n_pairs);

  // Exactly the owned nodes' 4 unknowns and the owned pairs' contact unknowns.
  std::set<GO> expected;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (owner(n) == rank)
      for (const GO g : node_dofs(n))
        expected.insert(g);
  for (int k = 0; k < n_pairs; ++k)
    if (owner(mesh.gap_pairs[k].node_a) == rank)
      expected.insert(4 * GO(n_nodes) + k);
  EXPECT_EQ(dofs.n_owned_dofs(), expected.size());
  for (const GO g : expected)
    EXPECT_TRUE(owned->isNodeGlobalElement(g)) << "unknown " << g << " not owned by " << rank;
  const auto elements = owned->getNodeElementList();
  EXPECT_EQ(std::set<GO>(elements.begin(), elements.end()), expected);
}

TEST_F(DofManagerTest, NodeMaps)
{
  const auto owned = dofs.owned_node_map();
  EXPECT_TRUE(owned->isOneToOne());
  EXPECT_EQ(owned->getGlobalNumElements(), static_cast<Tpetra::global_size_t>(n_nodes));
  for (int n = 0; n < mesh.n_nodes(); ++n)
  {
    EXPECT_EQ(owned->isNodeGlobalElement(n), owner(n) == rank) << "node " << n;
    EXPECT_EQ(dofs.overlap_node_map()->isNodeGlobalElement(n), touched_here(n)) << "node " << n;
  }
}

TEST_F(DofManagerTest, OverlapDofMap)
{
  const auto overlap = dofs.overlap_dof_map();
  // Every unknown of every node of an owned cell.
  for (const int c : dofs.owned_cells())
    for (const int n : mesh.connectivity[c])
      for (const GO g : node_dofs(n))
        EXPECT_TRUE(overlap->isNodeGlobalElement(g)) << "cell " << c << " unknown " << g;
  // The contact unknown of every pair one of whose nodes is touched, and nothing else.
  std::set<GO> expected;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (touched_here(n))
      for (const GO g : node_dofs(n))
        expected.insert(g);
  for (int k = 0; k < n_pairs; ++k)
  {
    const kiln::GapPair &pair = mesh.gap_pairs[k];
    if (touched_here(pair.node_a) || touched_here(pair.node_b))
      expected.insert(4 * GO(n_nodes) + k);
  }
  const auto elements = overlap->getNodeElementList();
  EXPECT_EQ(std::set<GO>(elements.begin(), elements.end()), expected);
  EXPECT_EQ(elements.size(), expected.size()) << "no unknown listed twice";
  // The owned unknowns are in the overlap map too.
  for (const GO g : dofs.owned_dof_map()->getNodeElementList())
    EXPECT_TRUE(overlap->isNodeGlobalElement(g)) << "owned unknown " << g;
}

TEST_F(DofManagerTest, ImportGathersOwnedValues)
{
  using Vector = Tpetra::Vector<>;
  Vector owned(dofs.owned_dof_map());
  {
    auto values = owned.getDataNonConst();
    const auto map = dofs.owned_dof_map();
    for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
      values[i] = static_cast<double>(map->getGlobalElement(static_cast<kiln::LO>(i)));
  }
  Vector overlap(dofs.overlap_dof_map());
  overlap.putScalar(-1.0);
  overlap.doImport(owned, *dofs.dof_importer(), Tpetra::INSERT);
  const auto map = dofs.overlap_dof_map();
  const auto values = overlap.getData();
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
    EXPECT_EQ(values[i], static_cast<double>(map->getGlobalElement(static_cast<kiln::LO>(i))))
        << "overlap entry " << i;
}

TEST_F(DofManagerTest, ExportSumsOverRanks)
{
  using Vector = Tpetra::Vector<>;
  Vector overlap(dofs.overlap_dof_map());
  overlap.putScalar(1.0);
  Vector owned(dofs.owned_dof_map());
  owned.putScalar(0.0);
  owned.doExport(overlap, *dofs.dof_exporter(), Tpetra::ADD);

  const auto map = dofs.owned_dof_map();
  const auto values = owned.getData();
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
  {
    const GO g = map->getGlobalElement(static_cast<kiln::LO>(i));
    double expected = 0;
    if (g < 4 * GO(n_nodes))
      expected = static_cast<double>(overlap_ranks[g / 4].size());
    else
    {
      // A contact unknown is in the overlap of every rank touching either node of its pair.
      const kiln::GapPair &pair = mesh.gap_pairs[g - 4 * GO(n_nodes)];
      std::set<int> ranks = overlap_ranks[pair.node_a];
      ranks.insert(overlap_ranks[pair.node_b].begin(), overlap_ranks[pair.node_b].end());
      expected = static_cast<double>(ranks.size());
    }
    EXPECT_EQ(values[i], expected) << "unknown " << g;
  }
  // The sum over all owned entries is the global size of the overlap.
  const double local_sum = std::accumulate(values.begin(), values.end(), 0.0);
  double sum = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, local_sum, Teuchos::outArg(sum));
  const double local_overlap = static_cast<double>(dofs.overlap_dof_map()->getNodeNumElements());
  double overlap_total = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, local_overlap, Teuchos::outArg(overlap_total));
  EXPECT_EQ(sum, overlap_total);
  // On several ranks some unknowns are shared, so the test sees sums above 1.
  const double local_max = values.size() > 0 ? *std::max_element(values.begin(), values.end()) : 0;
  double max = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, local_max, Teuchos::outArg(max));
  EXPECT_EQ(max > 1, np > 1);
}
} // namespace
