// Tests src/discretization/dof_manager.cpp: ownership of nodes and unknowns on the split
// contact box, the twins across the gap, the owned and overlap Tpetra maps (with and without
// the twin closure of contact), and the importer and exporter between them.
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
    // Independently of the code: the ranks whose cells touch each node. The owners are
    // node_owners' (tested in metis_partitioner_test.cpp), each one of those ranks.
    node_ranks.resize(mesh.n_nodes());
    for (int c = 0; c < mesh.n_cells(); ++c)
      for (const int n : mesh.cell_nodes(c))
        node_ranks[n].insert(cell_rank[c]);
    node_owner = kiln::node_owners(mesh, cell_rank);
    for (int n = 0; n < mesh.n_nodes(); ++n)
      EXPECT_EQ(node_ranks[n].count(node_owner[n]), 1u) << "node " << n;
    // The twins, from the pairs.
    twins.assign(mesh.n_nodes(), -1);
    for (const auto &pair : mesh.gap_pairs)
    {
      twins[pair.node_a] = pair.node_b;
      twins[pair.node_b] = pair.node_a;
    }
    // The ranks that hold each node in their overlap (default layout, with contact).
    overlap_ranks.resize(mesh.n_nodes());
    for (int r = 0; r < np; ++r)
      for (const int n : expected_overlap(cell_rank, r, kiln::DofLayout{}))
        overlap_ranks[n].insert(r);
  }

  Teuchos::RCP<const Teuchos::Comm<int>> comm;
  int rank, np;
  Mesh mesh;
  std::vector<int> cell_rank;
  kiln::DofManager dofs;
  std::vector<std::set<int>> node_ranks;
  std::vector<int> node_owner;
  std::vector<int> twins;
  std::vector<std::set<int>> overlap_ranks;

  int owner(const int node) const { return node_owner[node]; }
  bool touched_here(const int node) const { return overlap_ranks[node].count(rank) > 0; }
  std::vector<GO> node_dofs(const int node) const
  {
    return {4 * GO(node), 4 * GO(node) + 1, 4 * GO(node) + 2, 4 * GO(node) + 3};
  }

  /// Cells dealt round-robin to the ranks: unlike the METIS partition on two ranks (which
  /// gives each rank both sides of its part of the gap), the twins of some touched gap
  /// nodes are then on other ranks, so the twin closure changes the overlap.
  std::vector<int> round_robin() const
  {
    std::vector<int> ranks(mesh.n_cells());
    for (int c = 0; c < mesh.n_cells(); ++c)
      ranks[c] = c % np;
    return ranks;
  }

  /// Under `partition`: the nodes of rank r's cells and, for every gap face whose side-a
  /// cell r owns, the face's side-b nodes (and with contact and displacement all nodes of
  /// its side-b cell).
  std::set<int> cell_and_gap_nodes(const std::vector<int> &partition, const int r,
                                   const kiln::DofLayout &layout) const
  {
    std::set<int> nodes;
    for (int c = 0; c < mesh.n_cells(); ++c)
      if (partition[c] == r)
        nodes.insert(mesh.cell_nodes(c).begin(), mesh.cell_nodes(c).end());
    for (const auto &face : mesh.gap_faces)
      if (partition[face.cell_a] == r)
      {
        nodes.insert(face.node_b.begin(), face.node_b.end());
        if (layout.contact && layout.displacement)
          nodes.insert(mesh.cell_nodes(face.cell_b).begin(), mesh.cell_nodes(face.cell_b).end());
      }
    return nodes;
  }

  /// The same, closed once under twins.
  std::set<int> with_twins(const std::set<int> &nodes) const
  {
    std::set<int> closed = nodes;
    for (const int n : nodes)
      if (twins[n] >= 0)
        closed.insert(twins[n]);
    return closed;
  }

  /// The overlap nodes of rank r under `partition`: the above and, with contact, the
  /// twins of those nodes.
  std::set<int> expected_overlap(const std::vector<int> &partition, const int r,
                                 const kiln::DofLayout &layout) const
  {
    const std::set<int> base = cell_and_gap_nodes(partition, r, layout);
    return layout.contact ? with_twins(base) : base;
  }

  /// The owner of each node under `partition` (node_owners, tested in
  /// metis_partitioner_test.cpp).
  std::vector<int> owners(const std::vector<int> &partition) const
  {
    return kiln::node_owners(mesh, partition);
  }

  /// The number of nodes, summed over ranks, that the twin closure adds to the overlap
  /// without contact under `partition`.
  int closure_size(const std::vector<int> &partition, const kiln::DofLayout &layout) const
  {
    const std::set<int> base = cell_and_gap_nodes(partition, rank, layout);
    const int local = static_cast<int>(with_twins(base).size() - base.size());
    int sum = 0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(sum));
    return sum;
  }
};

TEST_F(DofManagerTest, DofNumbering)
{
  ASSERT_EQ(mesh.n_nodes(), n_nodes);
  ASSERT_EQ(static_cast<int>(mesh.gap_pairs.size()), n_pairs);
  EXPECT_EQ(dofs.n_node_fields(), 4);
  EXPECT_EQ(dofs.dof(0, kiln::Field::T), 0);
  EXPECT_EQ(dofs.dof(7, kiln::Field::ux), 29);
  EXPECT_EQ(dofs.dof(7, kiln::Field::uy), 30);
  EXPECT_EQ(dofs.dof(149, kiln::Field::uz), 599);
  for (int n = 0; n < mesh.n_nodes(); ++n)
    for (int s = 0; s < 4; ++s)
      EXPECT_EQ(dofs.node_dof(n, s), 4 * GO(n) + s) << "node " << n << " slot " << s;
  // No unknowns beyond the nodes' (no contact unknowns).
  EXPECT_EQ(dofs.n_global_dofs(), 4 * n_nodes);
}

/// The single twin of a node on one plane gap, or -1.
int the_twin(const kiln::DofManager &dofs, const int n)
{
  const auto [begin, end] = dofs.partners(n);
  EXPECT_LE(end - begin, 1) << "node " << n << " has more than one twin on one plane gap";
  return begin == end ? -1 : *begin;
}

TEST_F(DofManagerTest, Twins)
{
  // Every gap pair, both ways.
  std::set<int> gap_nodes;
  for (const auto &pair : mesh.gap_pairs)
  {
    EXPECT_EQ(the_twin(dofs, pair.node_a), pair.node_b) << "node " << pair.node_a;
    EXPECT_EQ(the_twin(dofs, pair.node_b), pair.node_a) << "node " << pair.node_b;
    gap_nodes.insert(pair.node_a);
    gap_nodes.insert(pair.node_b);
  }
  EXPECT_EQ(gap_nodes.size(), static_cast<std::size_t>(2 * n_pairs)) << "pairs are disjoint";
  // -1 for every other node.
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (gap_nodes.count(n) == 0)
    {
      EXPECT_EQ(the_twin(dofs, n), -1) << "node " << n;
    }
  // The side-b nodes of every gap face are the twins of its side-a cell's face nodes.
  for (const auto &face : mesh.gap_faces)
    for (const int nb : face.node_b)
    {
      const int na = the_twin(dofs, nb);
      ASSERT_GE(na, 0) << "side-b node " << nb << " has a twin";
      const auto &cell = mesh.cell_nodes(face.cell_a);
      EXPECT_NE(std::find(cell.begin(), cell.end(), na), cell.end())
          << "twin " << na << " of " << nb << " in side-a cell " << face.cell_a;
    }
}

TEST_F(DofManagerTest, OwnedCellsAndNodes)
{
  std::vector<int> cells, nodes;
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (cell_rank[c] == rank)
      cells.push_back(c);
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (owner(n) == rank)
      nodes.push_back(n);
  EXPECT_EQ(dofs.owned_cells(), cells);
  EXPECT_EQ(dofs.owned_nodes(), nodes);
  for (int n = 0; n < mesh.n_nodes(); ++n)
    EXPECT_EQ(dofs.node_owner()[n], owner(n)) << "node " << n;
}

TEST_F(DofManagerTest, OverlapNodes)
{
  const std::set<int> expected = expected_overlap(cell_rank, rank, kiln::DofLayout{});
  EXPECT_EQ(dofs.overlap_nodes(), std::vector<int>(expected.begin(), expected.end()));
  // Closed under twins: a touched gap node comes with its twin.
  for (const int n : dofs.overlap_nodes())
    if (the_twin(dofs, n) >= 0)
    {
      EXPECT_TRUE(std::binary_search(dofs.overlap_nodes().begin(), dofs.overlap_nodes().end(),
                                     the_twin(dofs, n)))
          << "twin " << the_twin(dofs, n) << " of overlap node " << n;
    }
  // Every owned node is in the overlap too.
  for (const int n : dofs.owned_nodes())
    EXPECT_TRUE(touched_here(n)) << "owned node " << n;
  // Every node is in its owner's overlap.
  for (int n = 0; n < mesh.n_nodes(); ++n)
    EXPECT_GT(overlap_ranks[n].count(owner(n)), 0u) << "node " << n;

  // Round-robin cells, where the twin closure adds nodes on several ranks.
  const std::vector<int> partition = round_robin();
  const kiln::DofManager rr(mesh, partition, comm);
  const std::set<int> rr_expected = expected_overlap(partition, rank, kiln::DofLayout{});
  EXPECT_EQ(rr.overlap_nodes(), std::vector<int>(rr_expected.begin(), rr_expected.end()));
  EXPECT_EQ(closure_size(partition, kiln::DofLayout{}) > 0, np > 1);
}

TEST_F(DofManagerTest, OwnedDofMap)
{
  const auto owned = dofs.owned_dof_map();
  EXPECT_EQ(dofs.n_global_dofs(), 4 * n_nodes);
  EXPECT_EQ(owned->getGlobalNumElements(), static_cast<Tpetra::global_size_t>(4 * n_nodes));
  EXPECT_TRUE(owned->isOneToOne());
  EXPECT_EQ(owned->getIndexBase(), 0);
  EXPECT_EQ(owned->getMinAllGlobalIndex(), 0);
  EXPECT_EQ(owned->getMaxAllGlobalIndex(), 4 * n_nodes - 1);

  // The owned counts add up to the global count.
  const long local = static_cast<long>(dofs.n_owned_dofs());
  long sum = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(sum));
  EXPECT_EQ(sum, 4 * n_nodes);

  // Exactly the owned nodes' 4 unknowns.
  std::set<GO> expected;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (owner(n) == rank)
      for (const GO g : node_dofs(n))
        expected.insert(g);
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
    for (const int n : mesh.cell_nodes(c))
      for (const GO g : node_dofs(n))
        EXPECT_TRUE(overlap->isNodeGlobalElement(g)) << "cell " << c << " unknown " << g;
  // The 4 unknowns of every overlap node, and nothing else.
  std::set<GO> expected;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (touched_here(n))
      for (const GO g : node_dofs(n))
        expected.insert(g);
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
    ASSERT_LT(g, 4 * GO(n_nodes));
    // The number of ranks whose overlap holds the node.
    EXPECT_EQ(values[i], static_cast<double>(overlap_ranks[g / 4].size())) << "unknown " << g;
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

TEST_F(DofManagerTest, WithoutContactNoTwinClosure)
{
  // Temperature only, no contact: one unknown per node, and the overlap is the cell nodes
  // and the side-b nodes of the owned side-a gap faces, without the twins. Checked under
  // the METIS partition and under round-robin cells (where the closure would add nodes).
  const kiln::DofLayout layout{true, false, false};
  for (const std::vector<int> &partition : {cell_rank, round_robin()})
  {
    const kiln::DofManager heat(mesh, partition, comm, layout);
    EXPECT_EQ(heat.n_node_fields(), 1);
    EXPECT_EQ(heat.n_global_dofs(), n_nodes);
    for (int n = 0; n < mesh.n_nodes(); ++n)
      EXPECT_EQ(heat.dof(n, kiln::Field::T), n) << "node " << n;
    const std::vector<int> owner_of = owners(partition);
    std::vector<int> owned;
    for (int n = 0; n < mesh.n_nodes(); ++n)
      if (owner_of[n] == rank)
        owned.push_back(n);
    EXPECT_EQ(heat.owned_nodes(), owned);
    for (const auto &pair : mesh.gap_pairs)
    {
      EXPECT_EQ(the_twin(heat, pair.node_a), pair.node_b);
      EXPECT_EQ(the_twin(heat, pair.node_b), pair.node_a);
    }

    const std::set<int> expected = cell_and_gap_nodes(partition, rank, layout);
    EXPECT_EQ(heat.overlap_nodes(), std::vector<int>(expected.begin(), expected.end()));
    const auto elements = heat.overlap_dof_map()->getNodeElementList();
    EXPECT_EQ(std::set<GO>(elements.begin(), elements.end()),
              std::set<GO>(expected.begin(), expected.end()));
    EXPECT_EQ(elements.size(), expected.size());
    // The twins the closure would add are not there.
    for (const int n : with_twins(expected))
      if (expected.count(n) == 0)
      {
        EXPECT_FALSE(heat.overlap_node_map()->isNodeGlobalElement(n))
            << "twin " << n << " of a touched node in the overlap without contact";
      }

    // The export sums count the ranks whose overlap (without closure) holds the node.
    std::vector<int> holders(mesh.n_nodes(), 0);
    for (int r = 0; r < np; ++r)
      for (const int n : cell_and_gap_nodes(partition, r, layout))
        ++holders[n];
    using Vector = Tpetra::Vector<>;
    Vector overlap(heat.overlap_dof_map());
    overlap.putScalar(1.0);
    Vector owned_sums(heat.owned_dof_map());
    owned_sums.putScalar(0.0);
    owned_sums.doExport(overlap, *heat.dof_exporter(), Tpetra::ADD);
    const auto map = heat.owned_dof_map();
    const auto values = owned_sums.getData();
    for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
    {
      const GO g = map->getGlobalElement(static_cast<kiln::LO>(i));
      EXPECT_EQ(values[i], static_cast<double>(holders[g])) << "node " << g;
    }
  }
  // Under round-robin cells on several ranks the closure would have added nodes, so the
  // check above tells a closed overlap from an open one.
  EXPECT_EQ(closure_size(round_robin(), layout) > 0, np > 1);
}
} // namespace
