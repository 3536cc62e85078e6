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

/// The owner of each node: the lowest rank among the cells around it.
std::vector<int> node_owners(const Mesh &mesh, const std::vector<int> &cell_rank);
} // namespace kiln
