#include "mesh/metis_partitioner.hpp"

#include "base/errors.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <metis.h>

#include <algorithm>
#include <climits>
#include <map>

namespace kiln
{
namespace internal
{
std::vector<int> metis_kway(const Mesh &mesh, const int n_parts)
{
  // The dual graph of the unsplit mesh: a twin node counts as its parent.
  // Cells are neighbours when they share a face: as many corners as the mesh's smallest face
  // has (4 for hexahedra, 3 with triangles). The corners alone (not the mid-side nodes of
  // quadratic cells, of which an edge has 3 with its corners) decide it.
  std::vector<idx_t> eptr(mesh.n_cells() + 1), eind;
  eind.reserve(mesh.cell_node_ids.size());
  idx_t ncommon = 4;
  for (int c = 0; c < mesh.n_cells(); ++c)
  {
    const Span<const int> nodes = mesh.cell_nodes(c);
    const ReferenceCell &cell = mesh.reference_cell(c);
    for (int i = 0; i < cell.n_vertices(); ++i)
      eind.push_back(mesh.parent_node.empty() ? nodes[i] : mesh.parent_node[nodes[i]]);
    eptr[c + 1] = static_cast<idx_t>(eind.size());
    for (int f = 0; f < cell.n_faces(); ++f)
      ncommon = std::min<idx_t>(ncommon, ReferenceCell::of(cell.face_type(f)).n_vertices());
  }
  idx_t ne = mesh.n_cells(), nn = mesh.n_nodes(), numflag = 0;
  idx_t *xadj = nullptr, *adjncy = nullptr;
  int status =
      METIS_MeshToDual(&ne, &nn, eptr.data(), eind.data(), &ncommon, &numflag, &xadj, &adjncy);
  KILN_CHECK_INPUT(status == METIS_OK, "", "METIS_MeshToDual failed with status " << status);

  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;
  options[METIS_OPTION_CONTIG] = 0;
  idx_t ncon = 1, nparts = n_parts, objval = 0;
  std::vector<idx_t> part(mesh.n_cells());
  status = METIS_PartGraphKway(&ne, &ncon, xadj, adjncy, nullptr, nullptr, nullptr, &nparts,
                               nullptr, nullptr, options, &objval, part.data());
  METIS_Free(xadj);
  METIS_Free(adjncy);
  KILN_CHECK_INPUT(status == METIS_OK, "", "METIS_PartGraphKway failed with status " << status);
  return std::vector<int>(part.begin(), part.end());
}
} // namespace internal

std::vector<int> partition_cells(const Mesh &mesh, const Teuchos::Comm<int> &comm,
                                 const std::string &where)
{
  const int n_ranks = comm.getSize();
  KILN_CHECK_INPUT(mesh.n_cells() >= n_ranks, where,
                   "the mesh has " << mesh.n_cells() << " cells, fewer than the " << n_ranks
                                   << " MPI ranks; run on at most " << mesh.n_cells()
                                   << " ranks or refine the mesh");
  std::vector<int> cell_rank(mesh.n_cells(), 0);
  if (n_ranks == 1)
    return cell_rank;
  // METIS runs on rank 0 only; its result (or its failure) is broadcast.
  std::string error;
  if (comm.getRank() == 0)
  {
    try
    {
      cell_rank = internal::metis_kway(mesh, n_ranks);
    }
    catch (const InputError &e)
    {
      error = e.what();
    }
  }
  check_collectively(comm, error.empty(), where, error);
  Teuchos::broadcast(comm, 0, mesh.n_cells(), cell_rank.data());

  // METIS may leave a part empty on a tiny mesh (2 cells on 2 ranks): then
  // split the cells in id order into contiguous, nearly equal parts.
  std::vector<int> cells_per_rank(n_ranks, 0);
  for (const int r : cell_rank)
    ++cells_per_rank[r];
  if (std::find(cells_per_rank.begin(), cells_per_rank.end(), 0) != cells_per_rank.end())
    for (int c = 0; c < mesh.n_cells(); ++c)
      cell_rank[c] = static_cast<int>(static_cast<long long>(c) * n_ranks / mesh.n_cells());
  return cell_rank;
}

std::vector<int> partition_cells_by_block(const Mesh &mesh, const Teuchos::Comm<int> &comm,
                                          const std::string &where)
{
  const std::vector<int> ids = mesh.block_ids();
  const int n_ranks = comm.getSize();
  const int n_blocks = static_cast<int>(ids.size());
  KILN_CHECK_INPUT(n_ranks <= n_blocks, where + "/\"Partition\"",
                   "is \"By Block\" but the mesh has " << n_blocks << " element blocks for "
                                                       << n_ranks << " MPI ranks; run on at most "
                                                       << n_blocks << " ranks or use \"METIS\"");
  std::vector<int> cell_rank(mesh.n_cells(), 0);
  for (int c = 0; c < mesh.n_cells(); ++c)
  {
    const int i =
        static_cast<int>(std::find(ids.begin(), ids.end(), mesh.block_id[c]) - ids.begin());
    cell_rank[c] = i * n_ranks / n_blocks;
  }
  return cell_rank;
}

std::vector<int> node_owners(const Mesh &mesh, const std::vector<int> &cell_rank)
{
  std::vector<int> low(mesh.n_nodes(), INT_MAX), high(mesh.n_nodes(), -1);
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (const int n : mesh.cell_nodes(c))
    {
      low[n] = std::min(low[n], cell_rank[c]);
      high[n] = std::max(high[n], cell_rank[c]);
    }
  // The nodes that ranks r < s share (their cells' lowest and highest ranks), in id order:
  // the first half to r, the rest to s.
  std::map<std::pair<int, int>, std::pair<long long, long long>> shared; // (count, given to r)
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (low[n] < high[n])
      ++shared[{low[n], high[n]}].first;
  std::vector<int> owner(low);
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (low[n] < high[n])
    {
      auto &[count, given] = shared[{low[n], high[n]}];
      if (2 * given < count)
        ++given;
      else
        owner[n] = high[n];
    }
  return owner;
}
} // namespace kiln
