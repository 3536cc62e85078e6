#include "discretization/dof_manager.hpp"

#include "mesh/metis_partitioner.hpp"

#include <Teuchos_OrdinalTraits.hpp>

#include <algorithm>

namespace kiln
{
Teuchos::RCP<const Map> make_map(const std::vector<GO> &gids,
                                 const Teuchos::RCP<const Teuchos::Comm<int>> &comm)
{
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  return Teuchos::rcp(
      new Map(invalid, Teuchos::ArrayView<const GO>(gids.data(), gids.size()), 0, comm));
}

DofManager::DofManager(const Mesh &mesh, const std::vector<int> &cell_rank,
                       const Teuchos::RCP<const Teuchos::Comm<int>> &comm, const DofLayout layout,
                       const std::vector<std::pair<int, int>> &partner_links)
    : layout_(layout), n_node_fields_(layout.n_node_fields())
{
  const int rank = comm->getRank();
  node_owner_ = node_owners(mesh, cell_rank);

  std::vector<char> touched(mesh.n_nodes(), 0);
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (cell_rank[c] == rank)
    {
      owned_cells_.push_back(c);
      for (const int n : mesh.cell_nodes(c))
        touched[n] = 1;
    }
  // Gap faces are assembled by the owner of their side-a cell: it needs the twins.
  // With contact and displacement, it needs all nodes of the side-b cell (whose stress
  // gives the contact pressure of the gap conductance; Assembler::gap_face_nodes).
  for (const GapFace &face : mesh.gap_faces)
    if (cell_rank[face.cell_a] == rank)
    {
      for (const int n : face.node_b)
        touched[n] = 1;
      if (layout_.contact && layout_.displacement)
        for (const int n : mesh.cell_nodes(face.cell_b))
          touched[n] = 1;
    }
  // The links (j, k): a split gap's (b, a), then the pairings' rows'.
  std::vector<std::pair<int, int>> links;
  links.reserve(mesh.gap_pairs.size() + partner_links.size());
  for (const GapPair &p : mesh.gap_pairs)
    links.emplace_back(p.node_b, p.node_a);
  links.insert(links.end(), partner_links.begin(), partner_links.end());
  twin_offsets_.assign(mesh.n_nodes() + 1, 0);
  for (const auto &[j, k] : links)
  {
    ++twin_offsets_[k + 1];
    ++twin_offsets_[j + 1];
  }
  for (int n = 0; n < mesh.n_nodes(); ++n)
    twin_offsets_[n + 1] += twin_offsets_[n];
  twin_nodes_.resize(twin_offsets_.back());
  {
    std::vector<int> next(twin_offsets_.begin(), twin_offsets_.end() - 1);
    for (const auto &[j, k] : links)
    {
      twin_nodes_[next[k]++] = j;
      twin_nodes_[next[j]++] = k;
    }
  }
  // With contact, a local system that holds a gap node holds its twins too; the overlap holds
  // the whole row of a touched node j or partner k (a row is decided from all its partners).
  if (layout_.contact)
  {
    const std::vector<char> touched_before = touched;
    for (const auto &[j, k] : links)
      if (touched_before[j] || touched_before[k])
        touched[j] = touched[k] = 1;
    for (const auto &[j, k] : partner_links)
      if (touched[j])
        touched[k] = 1;
  }
  for (int n = 0; n < mesh.n_nodes(); ++n)
  {
    if (node_owner_[n] == rank)
      owned_nodes_.push_back(n);
    if (touched[n])
      overlap_nodes_.push_back(n);
  }

  const auto node_gids = [](const std::vector<int> &nodes)
  { return std::vector<GO>(nodes.begin(), nodes.end()); };
  const auto dof_gids = [&](const std::vector<int> &nodes)
  {
    std::vector<GO> gids;
    gids.reserve(nodes.size() * n_node_fields_);
    for (const int n : nodes)
      for (int s = 0; s < n_node_fields_; ++s)
        gids.push_back(node_dof(n, s));
    return gids;
  };
  owned_node_map_ = make_map(node_gids(owned_nodes_), comm);
  overlap_node_map_ = make_map(node_gids(overlap_nodes_), comm);
  owned_dof_map_ = make_map(dof_gids(owned_nodes_), comm);
  overlap_dof_map_ = make_map(dof_gids(overlap_nodes_), comm);
  dof_importer_ = Teuchos::rcp(new Tpetra::Import<>(owned_dof_map_, overlap_dof_map_));
  dof_exporter_ = Teuchos::rcp(new Tpetra::Export<>(overlap_dof_map_, owned_dof_map_));
}

GO DofManager::n_global_dofs() const
{
  return static_cast<GO>(owned_dof_map_->getGlobalNumElements());
}

std::size_t DofManager::n_owned_dofs() const
{
  return owned_dof_map_->getNodeNumElements();
}
} // namespace kiln
