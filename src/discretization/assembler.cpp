#include "discretization/assembler.hpp"

#include "base/errors.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <utility>

namespace kiln
{
namespace internal
{
/// The coupling blocks: a cell's 8 nodes, and a gap face's nodes (Assembler::gap_face_nodes);
/// with Couplings::partners, each block also holds the partners of its contact nodes. Every unknown
/// of a block couples with every other one. Returns, for each node n with row[n] >= 0, the sorted
/// nodes it couples with, at index row[n].
std::vector<std::vector<int>> node_couplings(const Assembler &assembler, const Mesh &mesh,
                                             const std::vector<int> &row,
                                             const std::vector<char> &use_cell,
                                             const std::vector<char> &use_face, const int n_rows)
{
  std::vector<std::vector<int>> couplings(n_rows);
  const auto add_block = [&](const std::vector<int> &block)
  {
    for (const int n : block)
      if (row[n] >= 0)
        couplings[row[n]].insert(couplings[row[n]].end(), block.begin(), block.end());
  };
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (use_cell[c])
    {
      const Span<const int> nodes = mesh.cell_nodes(c);
      add_block(assembler.with_partners(std::vector<int>(nodes.begin(), nodes.end())));
    }
  for (std::size_t k = 0; k < use_face.size(); ++k)
    if (use_face[k])
      add_block(assembler.gap_face_nodes(static_cast<int>(k)));
  for (const auto &[cell, block] : assembler.couplings().cell_blocks)
    if (use_cell[cell])
      add_block(block);
  for (auto &c : couplings)
  {
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
  }
  return couplings;
}

/// The column map Tpetra's fillComplete would make for a graph whose columns are the
/// unknowns (slots `used`) of the nodes marked in `coupled`, with `domain` as its domain
/// map: the domain map's unknowns that are columns first, in its order; then the others,
/// ordered by owning rank and global id (Tpetra::Details::makeColMap). On one rank with
/// every unknown a column, the domain map itself. The mesh is replicated, so the owners come
/// from the DofManager without communication.
Teuchos::RCP<const Map> column_map(const DofManager &dofs, const std::vector<char> &coupled,
                                   const std::vector<char> &used,
                                   const Teuchos::RCP<const Map> &domain)
{
  const int F = dofs.n_node_fields();
  const int rank = domain->getComm()->getRank();
  const auto is_column = [&](const GO gid)
  { return coupled[static_cast<std::size_t>(gid / F)] && used[static_cast<std::size_t>(gid % F)]; };
  std::vector<GO> gids;
  for (const GO gid : domain->getNodeElementList())
    if (is_column(gid))
      gids.push_back(gid);
  if (domain->getComm()->getSize() == 1 && gids.size() == domain->getNodeNumElements())
    return domain;
  std::vector<std::pair<int, GO>> remote; // (owner, gid)
  for (std::size_t n = 0; n < coupled.size(); ++n)
    if (coupled[n] && dofs.node_owner()[n] != rank)
      for (int t = 0; t < F; ++t)
        if (used[t])
          remote.emplace_back(dofs.node_owner()[n], dofs.node_dof(static_cast<int>(n), t));
  std::sort(remote.begin(), remote.end());
  for (const auto &r : remote)
    gids.push_back(r.second);
  return make_map(gids, domain->getComm());
}

/// A fill-complete graph on `row_map` whose rows are the unknowns of `nodes` (node n's
/// couplings at couplings[i] for nodes[i]); with `col_map`, its local column ids are that
/// map's local ids, without it the map column_map() makes. Built from local indices: the
/// same graph as inserting the global ids and letting fillComplete make the column map, in
/// a fraction of the time.
Teuchos::RCP<Tpetra::CrsGraph<>>
make_graph(const DofManager &dofs, const Teuchos::RCP<const Map> &row_map,
           const std::vector<int> &nodes, const std::vector<std::vector<int>> &couplings,
           const std::vector<char> &pattern, const Teuchos::RCP<const Map> &domain_range,
           Teuchos::RCP<const Map> col_map = Teuchos::null)
{
  const int F = dofs.n_node_fields();
  std::vector<char> used(F, 0); // slots that are a column of some row
  for (int s = 0; s < F; ++s)
    for (int t = 0; t < F; ++t)
      used[t] = used[t] || pattern[s * F + t];
  const std::size_t n_mesh_nodes = dofs.node_owner().size();
  std::vector<char> coupled(n_mesh_nodes, 0);
  for (const auto &c : couplings)
    for (const int n : c)
      coupled[n] = 1;
  if (col_map.is_null())
    col_map = column_map(dofs, coupled, used, domain_range);

  // The local column id of every (node, slot) that is a column.
  const LO invalid = Teuchos::OrdinalTraits<LO>::invalid();
  std::vector<LO> column(n_mesh_nodes * F, invalid);
  for (std::size_t n = 0; n < n_mesh_nodes; ++n)
    if (coupled[n])
      for (int t = 0; t < F; ++t)
        if (used[t])
        {
          column[n * F + t] = col_map->getLocalElement(dofs.node_dof(static_cast<int>(n), t));
          KILN_ASSERT(column[n * F + t] != invalid,
                      "make_graph: a coupled unknown is not in the column map");
        }

  // Rows in row-map order: counts, offsets, then each row's sorted local columns.
  const std::size_t n_rows = row_map->getNodeNumElements();
  std::vector<LO> row_of(nodes.size() * F);
  Teuchos::ArrayRCP<std::size_t> offsets(n_rows + 1, 0);
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (int s = 0; s < F; ++s)
    {
      const LO row = row_map->getLocalElement(dofs.node_dof(nodes[i], s));
      KILN_ASSERT(row != invalid, "make_graph: a node's unknown is not in the row map");
      row_of[i * F + s] = row;
      std::size_t count = 0;
      for (int t = 0; t < F; ++t)
        count += pattern[s * F + t] ? couplings[i].size() : 0;
      offsets[row + 1] = count;
    }
  for (std::size_t r = 0; r < n_rows; ++r)
    offsets[r + 1] += offsets[r];
  Teuchos::ArrayRCP<LO> indices(offsets[n_rows]);
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (int s = 0; s < F; ++s)
    {
      const LO row = row_of[i * F + s];
      LO *out = indices.getRawPtr() + offsets[row];
      LO *const begin = out;
      for (const int n : couplings[i])
        for (int t = 0; t < F; ++t)
          if (pattern[s * F + t])
            *out++ = column[static_cast<std::size_t>(n) * F + t];
      std::sort(begin, out);
    }
  auto graph = Teuchos::rcp(new Tpetra::CrsGraph<>(row_map, col_map, offsets, indices));
  graph->fillComplete(domain_range, domain_range);
  return graph;
}

/// The row index of every node of `nodes` (-1 for the others).
std::vector<int> node_rows(const Mesh &mesh, const std::vector<int> &nodes)
{
  std::vector<int> row(mesh.n_nodes(), -1);
  for (std::size_t i = 0; i < nodes.size(); ++i)
    row[nodes[i]] = static_cast<int>(i);
  return row;
}
} // namespace internal

Couplings Couplings::gap_faces(const Mesh &mesh)
{
  Couplings c;
  c.gap_face_nodes = [&mesh](const int k)
  {
    const GapFace &face = mesh.gap_faces[k];
    std::vector<int> nodes = mesh.face_nodes(face.cell_a, face.face_a);
    nodes.insert(nodes.end(), face.node_b.begin(), face.node_b.end());
    return nodes;
  };
  return c;
}

Assembler::Assembler(const Mesh &mesh, const DofManager &dofs)
    : Assembler(mesh, dofs, Couplings::gap_faces(mesh))
{
}

Assembler::Assembler(const Mesh &mesh, const DofManager &dofs, Couplings couplings)
    : mesh_(mesh), dofs_(dofs), couplings_(std::move(couplings))
{
  const auto owned = dofs.owned_dof_map();
  const auto overlap = dofs.overlap_dof_map();

  // Which fields of a node's block couple: all, but T-u without a heat term in u.
  const int F = dofs.n_node_fields();
  pattern_.assign(static_cast<std::size_t>(F * F), 1);
  const int T = dofs.layout().slot(Field::T);
  if (!couplings_.temperature_depends_on_displacement && T >= 0)
    for (int t = 0; t < F; ++t)
      pattern_[T * F + t] = t == T;

  // What this rank assembles: its cells and the gap faces of its side-a cells.
  const std::size_t n_faces = couplings_.gap_face_nodes ? mesh.gap_faces.size() : 0;
  std::vector<char> my_cells(mesh.n_cells(), 0), my_faces(n_faces, 0);
  for (const int c : dofs.owned_cells())
    my_cells[c] = 1;
  for (std::size_t k = 0; k < n_faces; ++k)
    my_faces[k] = my_cells[mesh.gap_faces[k].cell_a];

  // The rows of other ranks' nodes that this rank assembles into (its cells reach them) are
  // summed in a ghost matrix and exported; its column map is the overlap map, so that add()
  // can use overlap local ids.
  {
    const int rank = owned->getComm()->getRank();
    std::vector<int> nodes;
    std::vector<GO> gids;
    for (const int n : dofs.overlap_nodes())
      if (dofs.node_owner()[n] != rank)
      {
        nodes.push_back(n);
        for (int s = 0; s < F; ++s)
          gids.push_back(dofs.node_dof(n, s));
      }
    const auto ghost_map = make_map(gids, owned->getComm());
    const auto links = internal::node_couplings(*this, mesh, internal::node_rows(mesh, nodes),
                                                my_cells, my_faces, static_cast<int>(nodes.size()));
    ghost_graph_ = internal::make_graph(dofs, ghost_map, nodes, links, pattern_, owned, overlap);
    ghost_exporter_ = Teuchos::rcp(new Tpetra::Export<>(ghost_map, owned));
  }
  // The owned rows get every block that touches them, from any rank: the mesh is
  // replicated, so each rank finds its rows' columns without communication.
  {
    const std::vector<char> all_cells(mesh.n_cells(), 1), all_faces(n_faces, 1);
    const std::vector<int> &nodes = dofs.owned_nodes();
    const auto links =
        internal::node_couplings(*this, mesh, internal::node_rows(mesh, nodes), all_cells,
                                 all_faces, static_cast<int>(nodes.size()));
    owned_graph_ = internal::make_graph(dofs, owned, nodes, links, pattern_, owned);
  }

  // Overlap local id -> the owned Jacobian's row, or the ghost matrix's; -> the column of
  // the owned Jacobian (invalid where no owned row has that column).
  const LO invalid = Teuchos::OrdinalTraits<LO>::invalid();
  const auto n_overlap = overlap->getNodeNumElements();
  owned_row_.assign(n_overlap, invalid);
  ghost_row_.assign(n_overlap, invalid);
  owned_column_.assign(n_overlap, invalid);
  for (std::size_t i = 0; i < n_overlap; ++i)
  {
    const GO gid = overlap->getGlobalElement(static_cast<LO>(i));
    owned_row_[i] = owned->getLocalElement(gid);
    ghost_row_[i] = ghost_graph_->getRowMap()->getLocalElement(gid);
    owned_column_[i] = owned_graph_->getColMap()->getLocalElement(gid);
  }
  overlap_lid_.assign(static_cast<std::size_t>(mesh.n_nodes()) * dofs.n_node_fields(), invalid);
  for (std::size_t i = 0; i < n_overlap; ++i)
    overlap_lid_[static_cast<std::size_t>(overlap->getGlobalElement(static_cast<LO>(i)))] =
        static_cast<LO>(i);
  ghost_matrix_ = Teuchos::rcp(new Matrix(ghost_graph_));
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

void Assembler::begin(const bool residual, Matrix *J)
{
  assembling_residual_ = residual;
  J_ = J;
  residual_values_ = Teuchos::null;
  if (residual)
  {
    overlap_residual_->putScalar(0.0);
    residual_values_ = overlap_residual_->getDataNonConst();
  }
  if (J != nullptr)
  {
    KILN_ASSERT(J->getCrsGraph().get() == owned_graph_.get() ||
                    J->getCrsGraph()->getColMap()->isSameAs(*owned_graph_->getColMap()),
                "the Jacobian must be built on owned_graph()");
    J->resumeFill();
    J->setAllToScalar(0.0);
    KILN_ASSERT(J->getCrsGraph()->isSorted(), "the Jacobian's rows must have sorted columns");
    local_J_ = J->getLocalMatrixHost();
    if (ghost_matrix_->isFillComplete())
      ghost_matrix_->resumeFill();
    ghost_matrix_->setAllToScalar(0.0);
  }
}

void Assembler::add_row(const LO lid, const LO *columns, const double *values, const LO n)
{
  // Not atomic: one thread assembles.
  if (const LO row = owned_row_[lid]; row != Teuchos::OrdinalTraits<LO>::invalid())
  {
    // What sumIntoLocalValues does, on the local rows held since begin(): each column is
    // looked for after the last one found (a cell's columns come in runs), else by bisection
    // of the row's sorted columns. The sums are the same, in the same order.
    const LO *const row_columns = local_J_.graph.entries.data();
    double *const row_values = local_J_.values.data();
    const std::size_t first = local_J_.graph.row_map(row), end = local_J_.graph.row_map(row + 1);
    std::size_t next = first;
    for (LO j = 0; j < n; ++j)
    {
      const LO column = owned_column_[columns[j]];
      std::size_t k = next;
      if (k >= end || row_columns[k] != column)
      {
        k = static_cast<std::size_t>(
            std::lower_bound(row_columns + first, row_columns + end, column) - row_columns);
        if (k == end || row_columns[k] != column)
          throw std::logic_error("Assembler::add: an entry missing from the graph in owned row " +
                                 std::to_string(row));
      }
      row_values[k] += values[j];
      next = k + 1;
    }
    return;
  }
  const LO count = ghost_matrix_->sumIntoLocalValues(ghost_row_[lid], n, values, columns, false);
  KILN_ASSERT(count == n, "entries missing from the graph in ghost row " << ghost_row_[lid]);
  (void)count;
}

void Assembler::add(const std::vector<LO> &lids, const LocalSystem &local)
{
  KILN_ASSERT(static_cast<int>(lids.size()) == local.size(), "local system size mismatch");
  const int n = local.size();
  if (assembling_residual_)
  {
    double *f = residual_values_.getRawPtr();
    for (int i = 0; i < n; ++i)
      f[lids[i]] += local.residual_values()[i];
  }
  if (J_ == nullptr)
    return;
  KILN_ASSERT(local.has_jacobian(), "a local system without a Jacobian in a Jacobian assembly");
  const auto &values = local.jacobian_values();
  const int F = local.n_fields();
  KILN_ASSERT(F * F == static_cast<int>(pattern_.size()), "local system with other fields");
  for (int i = 0; i < n; ++i)
  {
    const double *row = values.data() + static_cast<std::size_t>(i) * n;
    const char *couples = pattern_.data() + static_cast<std::size_t>(i % F) * F;
    if (std::all_of(couples, couples + F, [](const char c) { return c != 0; }))
    {
      add_row(lids[i], lids.data(), row, n);
      continue;
    }
    // A row whose block leaves fields out (Couplings): those entries must be zero.
    row_columns_.clear();
    row_values_.clear();
    for (int j = 0; j < n; ++j)
      if (couples[j % F])
      {
        row_columns_.push_back(lids[j]);
        row_values_.push_back(row[j]);
      }
      else if (row[j] != 0.0)
        throw std::logic_error("Assembler::add: a term couples fields the Jacobian's graph "
                               "leaves out (Couplings::temperature_depends_on_displacement)");
    add_row(lids[i], row_columns_.data(), row_values_.data(), static_cast<LO>(row_columns_.size()));
  }
}

void Assembler::finish(Vector *f, Matrix *J)
{
  residual_values_ = Teuchos::null;
  if (f != nullptr)
  {
    KILN_ASSERT(assembling_residual_, "finish(f) without begin(residual)");
    f->putScalar(0.0);
    f->doExport(*overlap_residual_, *dofs_.dof_exporter(), Tpetra::ADD);
  }
  if (J != nullptr)
  {
    KILN_ASSERT(J == J_, "finish(J) without begin(residual, J)");
    local_J_ = Matrix::local_matrix_host_type();
    ghost_matrix_->fillComplete(dofs_.owned_dof_map(), dofs_.owned_dof_map());
    J->doExport(*ghost_matrix_, *ghost_exporter_, Tpetra::ADD);
    J->fillComplete(dofs_.owned_dof_map(), dofs_.owned_dof_map());
  }
  assembling_residual_ = false;
  J_ = nullptr;
}

LO Assembler::lid(const GO gid) const
{
  const LO i = gid >= 0 && static_cast<std::size_t>(gid) < overlap_lid_.size()
                   ? overlap_lid_[static_cast<std::size_t>(gid)]
                   : Teuchos::OrdinalTraits<LO>::invalid();
  KILN_ASSERT(i != Teuchos::OrdinalTraits<LO>::invalid(), "unknown " << gid << " not in overlap");
  return i;
}

std::vector<LO> Assembler::cell_lids(const int cell) const
{
  std::vector<LO> lids;
  for (const int n : mesh_.cell_nodes(cell))
    for (int f = 0; f < dofs_.n_node_fields(); ++f)
      lids.push_back(lid(dofs_.node_dof(n, f)));
  return lids;
}

std::vector<LO> Assembler::face_lids(const int cell, const int face) const
{
  std::vector<LO> lids;
  for (const int n : mesh_.face_nodes(cell, face))
    for (int f = 0; f < dofs_.n_node_fields(); ++f)
      lids.push_back(lid(dofs_.node_dof(n, f)));
  return lids;
}

std::vector<LO> Assembler::node_lids(const std::vector<int> &nodes) const
{
  std::vector<LO> lids;
  lids.reserve(nodes.size() * dofs_.n_node_fields());
  for (const int n : nodes)
    for (int f = 0; f < dofs_.n_node_fields(); ++f)
      lids.push_back(lid(dofs_.node_dof(n, f)));
  return lids;
}

std::vector<int> Assembler::with_partners(std::vector<int> nodes) const
{
  if (!couplings_.partners)
    return nodes;
  const std::size_t n = nodes.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    const auto [begin, end] = dofs_.partners(nodes[i]);
    for (const int *t = begin; t != end; ++t)
      if (std::find(nodes.begin(), nodes.end(), *t) == nodes.end())
        nodes.push_back(*t);
  }
  return nodes;
}

std::vector<int> Assembler::gap_face_nodes(const int gap_face) const
{
  KILN_ASSERT(couplings_.gap_face_nodes, "gap_face_nodes() without gap-face couplings");
  return with_partners(couplings_.gap_face_nodes(gap_face));
}

std::vector<LO> Assembler::gap_face_lids(const int gap_face) const
{
  return node_lids(gap_face_nodes(gap_face));
}
} // namespace kiln
