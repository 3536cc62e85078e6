#pragma once
/// The bodies of a mesh: its connected sets of cells (cells that share a node are in one
/// body). A gap split at a side set that cuts the mesh apart (the contact box) leaves two.
#include "mesh/mesh.hpp"

#include <vector>

namespace kiln
{
struct MeshBodies
{
  int count = 0;         ///< the number of bodies
  std::vector<int> body; ///< per node, its body 0..count-1, numbered in the order of their
                         ///< first cells; -1 for a node of no cell
};

/// The bodies of `mesh` (deterministic: the same on every rank for the same mesh).
MeshBodies mesh_bodies(const Mesh &mesh);
} // namespace kiln
