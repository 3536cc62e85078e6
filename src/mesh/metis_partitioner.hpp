#pragma once
/// METIS k-way partition of the cells, computed on rank 0 and broadcast.
#include "mesh/mesh.hpp"

#include <Teuchos_Comm.hpp>

#include <vector>

namespace kiln
{
/// The owning rank of every cell, the same on every rank and for every run
/// (METIS with a fixed seed on the dual graph: cells sharing a face, across a
/// split gap too, so the gap's two sides tend to share a rank). If METIS
/// leaves a rank empty (tiny meshes), the cells are split in id order into
/// contiguous parts instead. Throws InputError if the mesh has fewer cells
/// than ranks.
std::vector<int> partition_cells(const Mesh &mesh, const Teuchos::Comm<int> &comm,
                                 const std::string &where);
/// Element block i (of the mesh's block ids, increasing) to rank i np / n_blocks. Throws
/// InputError (naming `where`) if there are more ranks than blocks.
std::vector<int> partition_cells_by_block(const Mesh &mesh, const Teuchos::Comm<int> &comm,
                                          const std::string &where);

/// The owner of each node: the rank of its cells if they have one; the nodes whose cells' lowest
/// and highest ranks are r < s are split in id order, the first half (rounded up) to r, so
/// that the ranks own nearly equal numbers of nodes (the lowest rank took them all before:
/// 2% more rows than the mean on the 64^3 contact box on 2 ranks).
std::vector<int> node_owners(const Mesh &mesh, const std::vector<int> &cell_rank);
} // namespace kiln
