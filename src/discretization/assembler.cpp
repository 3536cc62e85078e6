#include "discretization/assembler.hpp"

#include "base/errors.hpp"

#include <algorithm>
#include <array>

namespace kiln
{
namespace internal
{
/// The coupling blocks, as entities: node n is entity n (its F unknowns), gap pair k is
/// entity N + k (its contact unknown). A block is a cell's 8 nodes, a gap face's 8 nodes,
/// or (with contact) a pair's two nodes and the pair; every unknown of a block couples
/// with every other one. Returns, for each entity e with row[e] >= 0, the sorted entities
/// it couples with, at index row[e].
std::vector<std::vector<int>> entity_couplings(const Mesh &mesh, const DofManager &dofs,
                                               const std::vector<int> &row,
                                               const std::vector<char> &use_cell,
                                               const std::vector<char> &use_face,
                                               const std::vector<char> &use_pair, const int n_rows)
{
  std::vector<std::vector<int>> couplings(n_rows);
  std::array<int, 8> block{};
  const auto add_block = [&](const int size)
  {
    for (int i = 0; i < size; ++i)
      if (row[block[i]] >= 0)
        couplings[row[block[i]]].insert(couplings[row[block[i]]].end(), block.begin(),
                                        block.begin() + size);
  };
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (use_cell[c])
    {
      std::copy(mesh.connectivity[c].begin(), mesh.connectivity[c].end(), block.begin());
      add_block(8);
    }
  for (std::size_t k = 0; k < mesh.gap_faces.size(); ++k)
    if (use_face[k])
    {
      const GapFace &face = mesh.gap_faces[k];
      for (int i = 0; i < 4; ++i)
      {
        block[i] = mesh.connectivity[face.cell_a][hex_face_nodes[face.face_a][i]];
        block[4 + i] = face.node_b[i];
      }
      add_block(8);
    }
  if (dofs.layout().contact)
    for (std::size_t k = 0; k < mesh.gap_pairs.size(); ++k)
      if (use_pair[k])
      {
        block[0] = mesh.gap_pairs[k].node_a;
        block[1] = mesh.gap_pairs[k].node_b;
        block[2] = mesh.n_nodes() + static_cast<int>(k);
        add_block(3);
      }
  for (auto &c : couplings)
  {
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
  }
  return couplings;
}

/// A fill-complete graph on `row_map` whose rows are the unknowns of `entities` (entity e's
/// couplings at couplings[i] for entities[i]); with `col_map`, its local column ids are that
/// map's local ids.
Teuchos::RCP<Tpetra::CrsGraph<>> make_graph(const Mesh &mesh, const DofManager &dofs,
                                            const Teuchos::RCP<const Map> &row_map,
                                            const std::vector<int> &entities,
                                            const std::vector<std::vector<int>> &couplings,
                                            const Teuchos::RCP<const Map> &domain_range,
                                            const Teuchos::RCP<const Map> &col_map = Teuchos::null)
{
  const int F = dofs.n_node_fields();
  const int n_nodes = mesh.n_nodes();
  const auto n_unknowns = [&](const int e) { return e < n_nodes ? F : 1; };
  const auto first_gid = [&](const int e)
  { return e < n_nodes ? dofs.node_dof(e, 0) : dofs.contact_dof(e - n_nodes); };
  std::vector<std::size_t> counts(row_map->getNodeNumElements(), 0);
  for (std::size_t i = 0; i < entities.size(); ++i)
  {
    std::size_t count = 0;
    for (const int e : couplings[i])
      count += n_unknowns(e);
    for (int s = 0; s < n_unknowns(entities[i]); ++s)
      counts[row_map->getLocalElement(first_gid(entities[i]) + s)] = count;
  }
  const Teuchos::ArrayView<const std::size_t> row_counts(counts.data(), counts.size());
  auto graph = col_map.is_null()
                   ? Teuchos::rcp(new Tpetra::CrsGraph<>(row_map, row_counts))
                   : Teuchos::rcp(new Tpetra::CrsGraph<>(row_map, col_map, row_counts));
  std::vector<GO> columns;
  for (std::size_t i = 0; i < entities.size(); ++i)
  {
    columns.clear();
    for (const int e : couplings[i]) // sorted entities give sorted ids
      for (int s = 0; s < n_unknowns(e); ++s)
        columns.push_back(first_gid(e) + s);
    for (int s = 0; s < n_unknowns(entities[i]); ++s)
      graph->insertGlobalIndices(first_gid(entities[i]) + s,
                                 Teuchos::ArrayView<const GO>(columns.data(), columns.size()));
  }
  graph->fillComplete(domain_range, domain_range);
  return graph;
}

/// The entities (nodes, then pairs N + k) of the given nodes and pairs, and the row index of
/// every entity (-1 for the others).
std::vector<int> entity_rows(const Mesh &mesh, const std::vector<int> &nodes,
                             const std::vector<int> &pairs, std::vector<int> &row)
{
  row.assign(mesh.n_nodes() + mesh.gap_pairs.size(), -1);
  std::vector<int> entities(nodes);
  for (const int k : pairs)
    entities.push_back(mesh.n_nodes() + k);
  for (std::size_t i = 0; i < entities.size(); ++i)
    row[entities[i]] = static_cast<int>(i);
  return entities;
}
} // namespace internal

Assembler::Assembler(const Mesh &mesh, const DofManager &dofs) : mesh_(mesh), dofs_(dofs)
{
  const auto owned = dofs.owned_dof_map();
  const auto overlap = dofs.overlap_dof_map();

  // What this rank assembles: its cells, the gap faces of its side-a cells, its pairs.
  std::vector<char> my_cells(mesh.n_cells(), 0), my_faces(mesh.gap_faces.size(), 0),
      my_pairs(mesh.gap_pairs.size(), 0);
  for (const int c : dofs.owned_cells())
    my_cells[c] = 1;
  for (std::size_t k = 0; k < mesh.gap_faces.size(); ++k)
    my_faces[k] = my_cells[mesh.gap_faces[k].cell_a];
  for (const int k : dofs.owned_pairs())
    my_pairs[k] = 1;

  // The overlap rows hold what this rank assembles; the column map is the overlap map, so
  // that add() can use overlap local ids.
  std::vector<int> overlap_pairs;
  for (std::size_t k = 0; k < mesh.gap_pairs.size(); ++k)
    if (dofs.layout().contact && overlap->getLocalElement(dofs.contact_dof(static_cast<int>(k))) !=
                                     Teuchos::OrdinalTraits<LO>::invalid())
      overlap_pairs.push_back(static_cast<int>(k));
  std::vector<int> row;
  {
    const std::vector<int> entities =
        internal::entity_rows(mesh, dofs.overlap_nodes(), overlap_pairs, row);
    const auto couplings = internal::entity_couplings(mesh, dofs, row, my_cells, my_faces, my_pairs,
                                                      static_cast<int>(entities.size()));
    overlap_graph_ = internal::make_graph(mesh, dofs, overlap, entities, couplings, owned, overlap);
  }
  // The owned rows get every block that touches them, from any rank: the mesh is
  // replicated, so each rank finds its rows' columns without communication.
  {
    const std::vector<char> all_cells(mesh.n_cells(), 1), all_faces(mesh.gap_faces.size(), 1),
        all_pairs(mesh.gap_pairs.size(), 1);
    const std::vector<int> entities =
        internal::entity_rows(mesh, dofs.owned_nodes(), dofs.owned_pairs(), row);
    const auto couplings = internal::entity_couplings(mesh, dofs, row, all_cells, all_faces,
                                                      all_pairs, static_cast<int>(entities.size()));
    owned_graph_ = internal::make_graph(mesh, dofs, owned, entities, couplings, owned);
  }

  overlap_matrix_ = Teuchos::rcp(new Matrix(overlap_graph_));
  overlap_residual_ = Teuchos::rcp(new Vector(overlap));
}

void Assembler::gather(const Vector &owned, Vector &overlap) const
{
  overlap.doImport(owned, *dofs_.dof_importer(), Tpetra::INSERT);
}

Teuchos::RCP<Assembler::Vector> Assembler::make_overlap_vector() const
{
  return Teuchos::rcp(new Vector(dofs_.overlap_dof_map()));
}

void Assembler::begin(const bool residual, const bool jacobian)
{
  assembling_residual_ = residual;
  assembling_jacobian_ = jacobian;
  if (residual)
    overlap_residual_->putScalar(0.0);
  if (jacobian)
  {
    if (overlap_matrix_->isFillComplete())
      overlap_matrix_->resumeFill();
    overlap_matrix_->setAllToScalar(0.0);
  }
}

void Assembler::add(const std::vector<LO> &lids, const LocalSystem &local)
{
  KILN_ASSERT(static_cast<int>(lids.size()) == local.size(), "local system size mismatch");
  const int n = local.size();
  if (assembling_residual_)
  {
    auto f = overlap_residual_->getDataNonConst();
    for (int i = 0; i < n; ++i)
      f[lids[i]] += local.residual_values()[i];
  }
  if (assembling_jacobian_)
  {
    const auto &values = local.jacobian_values();
    for (int i = 0; i < n; ++i)
    {
      const LO count = overlap_matrix_->sumIntoLocalValues(
          lids[i], Teuchos::ArrayView<const LO>(lids.data(), n),
          Teuchos::ArrayView<const double>(values.data() + static_cast<std::size_t>(i) * n, n));
      KILN_ASSERT(count == n, "entries missing from the graph in row " << lids[i]);
      (void)count;
    }
  }
}

void Assembler::finish(Vector *f, Matrix *J)
{
  if (f != nullptr)
  {
    KILN_ASSERT(assembling_residual_, "finish(f) without begin(residual)");
    f->putScalar(0.0);
    f->doExport(*overlap_residual_, *dofs_.dof_exporter(), Tpetra::ADD);
  }
  if (J != nullptr)
  {
    KILN_ASSERT(assembling_jacobian_, "finish(J) without begin(jacobian)");
    overlap_matrix_->fillComplete(dofs_.owned_dof_map(), dofs_.owned_dof_map());
    J->resumeFill();
    J->setAllToScalar(0.0);
    J->doExport(*overlap_matrix_, *dofs_.dof_exporter(), Tpetra::ADD);
    J->fillComplete(dofs_.owned_dof_map(), dofs_.owned_dof_map());
  }
  assembling_residual_ = assembling_jacobian_ = false;
}

LO Assembler::lid(const GO gid) const
{
  const LO i = dofs_.overlap_dof_map()->getLocalElement(gid);
  KILN_ASSERT(i != Teuchos::OrdinalTraits<LO>::invalid(), "unknown " << gid << " not in overlap");
  return i;
}

std::vector<LO> Assembler::cell_lids(const int cell) const
{
  std::vector<LO> lids;
  for (const int n : mesh_.connectivity[cell])
    for (int f = 0; f < dofs_.n_node_fields(); ++f)
      lids.push_back(lid(dofs_.node_dof(n, f)));
  return lids;
}

std::vector<LO> Assembler::face_lids(const int cell, const int face) const
{
  std::vector<LO> lids;
  for (int i = 0; i < 4; ++i)
  {
    const int n = mesh_.connectivity[cell][hex_face_nodes[face][i]];
    for (int f = 0; f < dofs_.n_node_fields(); ++f)
      lids.push_back(lid(dofs_.node_dof(n, f)));
  }
  return lids;
}

std::vector<LO> Assembler::gap_face_lids(const int gap_face) const
{
  const GapFace &face = mesh_.gap_faces[gap_face];
  std::vector<LO> lids;
  const auto add = [&](const int n)
  {
    for (int f = 0; f < dofs_.n_node_fields(); ++f)
      lids.push_back(lid(dofs_.node_dof(n, f)));
  };
  for (int i = 0; i < 4; ++i)
    add(mesh_.connectivity[face.cell_a][hex_face_nodes[face.face_a][i]]);
  for (const int n : face.node_b)
    add(n);
  return lids;
}
} // namespace kiln
