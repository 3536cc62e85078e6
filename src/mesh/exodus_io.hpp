#pragma once
/// Exodus II (Cubit) mesh files: HEX8 element blocks, side sets.
#include "mesh/mesh.hpp"

#include <string>

namespace kiln
{
/// Reads every element block (all must be 8-node hexahedra: "HEX8", "HEX" or
/// "HEXAHEDRON", any case, with 8 nodes per element) and
/// every side set. Coordinates are multiplied by `scale` (Cubit meshes in cm
/// are read with 0.01). Nodes and cells keep the file's order (0-based);
/// cells are numbered block after block as Exodus does. Side sets are sorted
/// by id and carry their names when the file has them.
/// Throws InputError naming the file for a missing or unreadable file, a truncated
/// or damaged netCDF classic file (check_netcdf_file), a non-HEX8 block (naming the
/// block and its element type), or a 2D mesh.
Mesh read_exodus_mesh(const std::string &path, double scale);

/// Writes `mesh` (nodes, blocks in increasing id order, side sets) as an
/// Exodus II file, overwriting `path`. Cells of a block are written in
/// increasing cell order; reading the file back gives the same mesh when its
/// cells are already grouped by block in increasing id order.
/// Throws InputError naming the path when the file cannot be created.
void write_exodus_mesh(const Mesh &mesh, const std::string &path);
} // namespace kiln
