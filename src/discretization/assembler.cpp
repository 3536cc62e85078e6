#include "discretization/assembler.hpp"

#include "base/errors.hpp"

#include <algorithm>

namespace kiln
{
namespace internal
{
/// The global ids of each coupling block: the unknowns of a cell's nodes, of a
/// gap face's 8 nodes, and of a gap pair's 2 nodes plus its contact unknown.
/// Every unknown of a block couples with every other one.
template <typename Callback>
void for_each_block(const Mesh &mesh, const DofManager &dofs, const std::vector<char> &use_cell,
                    const std::vector<char> &use_face, const std::vector<char> &use_pair,
                    Callback &&callback)
{
  const int F = dofs.n_node_fields();
  std::vector<GO> gids;
  const auto add_node = [&](const int n)
  {
    for (int f = 0; f < F; ++f)
      gids.push_back(dofs.node_dof(n, f));
  };
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (use_cell[c])
    {
      gids.clear();
      for (const int n : mesh.connectivity[c])
        add_node(n);
      callback(gids);
    }
  for (std::size_t k = 0; k < mesh.gap_faces.size(); ++k)
    if (use_face[k])
    {
      const GapFace &face = mesh.gap_faces[k];
      gids.clear();
      for (int i = 0; i < 4; ++i)
        add_node(mesh.connectivity[face.cell_a][hex_face_nodes[face.face_a][i]]);
      for (const int n : face.node_b)
        add_node(n);
      callback(gids);
    }
  if (!dofs.layout().contact)
    return;
  for (std::size_t k = 0; k < mesh.gap_pairs.size(); ++k)
    if (use_pair[k])
    {
      gids.clear();
      add_node(mesh.gap_pairs[k].node_a);
      add_node(mesh.gap_pairs[k].node_b);
      gids.push_back(dofs.contact_dof(static_cast<int>(k)));
      callback(gids);
    }
}

/// A fill-complete graph with `rows[i]` (global column ids) in row i of `row_map`;
/// with `col_map`, local column ids are that map's local ids.
Teuchos::RCP<Tpetra::CrsGraph<>> make_graph(const Teuchos::RCP<const Map> &row_map,
                                            std::vector<std::vector<GO>> &rows,
                                            const Teuchos::RCP<const Map> &domain_range,
                                            const Teuchos::RCP<const Map> &col_map = Teuchos::null)
{
  std::vector<std::size_t> counts(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i)
  {
    std::sort(rows[i].begin(), rows[i].end());
    rows[i].erase(std::unique(rows[i].begin(), rows[i].end()), rows[i].end());
    counts[i] = rows[i].size();
  }
  const Teuchos::ArrayView<const std::size_t> row_counts(counts.data(), counts.size());
  auto graph = col_map.is_null()
                   ? Teuchos::rcp(new Tpetra::CrsGraph<>(row_map, row_counts))
                   : Teuchos::rcp(new Tpetra::CrsGraph<>(row_map, col_map, row_counts));
  for (std::size_t i = 0; i < rows.size(); ++i)
    graph->insertGlobalIndices(row_map->getGlobalElement(static_cast<LO>(i)),
                               Teuchos::ArrayView<const GO>(rows[i].data(), rows[i].size()));
  graph->fillComplete(domain_range, domain_range);
  return graph;
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

  std::vector<std::vector<GO>> overlap_rows(overlap->getNodeNumElements());
  internal::for_each_block(mesh, dofs, my_cells, my_faces, my_pairs,
                           [&](const auto &gids)
                           {
                             for (const GO row : gids)
                               overlap_rows[overlap->getLocalElement(row)].insert(
                                   overlap_rows[overlap->getLocalElement(row)].end(), gids.begin(),
                                   gids.end());
                           });
  // Its column map is the overlap map, so add() can use overlap local ids.
  overlap_graph_ = internal::make_graph(overlap, overlap_rows, owned, overlap);

  // The owned rows get every block that touches them, from any rank: the mesh
  // is replicated, so each rank finds its rows' columns without communication.
  std::vector<char> all_cells(mesh.n_cells(), 1), all_faces(mesh.gap_faces.size(), 1),
      all_pairs(mesh.gap_pairs.size(), 1);
  std::vector<std::vector<GO>> owned_rows(owned->getNodeNumElements());
  internal::for_each_block(mesh, dofs, all_cells, all_faces, all_pairs,
                           [&](const auto &gids)
                           {
                             for (const GO row : gids)
                             {
                               const LO i = owned->getLocalElement(row);
                               if (i != Teuchos::OrdinalTraits<LO>::invalid())
                                 owned_rows[i].insert(owned_rows[i].end(), gids.begin(),
                                                      gids.end());
                             }
                           });
  owned_graph_ = internal::make_graph(owned, owned_rows, owned);

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
