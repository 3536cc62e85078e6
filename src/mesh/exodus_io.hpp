#pragma once
/// Exodus II (Cubit) mesh files: HEX8 element blocks, side sets. Also the one home of what
/// every Exodus file Kiln writes (meshes, results) shares: the block, side set and node set
/// names, the cell order, the info record that says the coordinates are in metres.
#include "mesh/mesh.hpp"

#include <string>
#include <vector>

namespace kiln
{
/// Reads every element block (each of a volume type Kiln supports: exodus_cell_type(), e.g.
/// "HEX8", "HEX" or "HEXAHEDRON", any case, with 8 nodes per element) and
/// every side set. Coordinates are multiplied by `scale` (Cubit meshes in cm
/// are read with 0.01). Nodes and cells keep the file's order (0-based);
/// cells are numbered block after block as Exodus does. Side sets are sorted
/// by id and carry their names when the file has them. Node sets are ignored.
/// Throws InputError naming the file for a missing or unreadable file, a truncated
/// or damaged netCDF classic file (check_netcdf_file), a block of another type (naming the
/// block and its element type), or a 2D mesh.
Mesh read_exodus_mesh(const std::string &path, double scale);

/// Writes `mesh` (nodes, blocks in increasing id order, side sets, and one node set per
/// side set with the nodes of its faces) as an Exodus II file, overwriting `path`, with
/// the names of exodus_layout(mesh, gap_side_sets), a QA record (kiln, version, date)
/// and the info record exodus_metres_record. Cells of a block are written in
/// increasing cell order; reading the file back gives the same mesh when its
/// cells are already grouped by block in increasing id order.
/// `gap_side_sets`: the gaps' side sets (the first named "gap"); the mesh before the split
/// does not know them yet (mesh.gap_side_sets is empty), so the caller passes them.
/// Throws InputError naming the path when the file cannot be created.
void write_exodus_mesh(const Mesh &mesh, const std::string &path,
                       const std::vector<int> &gap_side_sets);
/// The same with mesh.gap_side_sets.
void write_exodus_mesh(const Mesh &mesh, const std::string &path);

/// The node and element counts of the Exodus file at `path`, from its netCDF header alone
/// (nothing else is read): the nodes if there are coordinates, the elements of the blocks
/// with a connectivity (a damaged file is reported when read_exodus_mesh reads it). Throws
/// InputError naming the file when it cannot be opened as Exodus or its netCDF header is
/// damaged or cut short.
struct ExodusCounts
{
  long long nodes = 0;
  long long elements = 0;
};
ExodusCounts exodus_counts(const std::string &path);

/// The info record of every Exodus file Kiln writes: its coordinates are in metres.
inline constexpr const char *exodus_metres_record = "Kiln: coordinates in metres (m)";

/// True if the Exodus file at `path` carries exodus_metres_record, i.e. Kiln wrote it and
/// its coordinates are in metres already; false for files from other programs (Cubit).
/// Throws InputError naming the file when it cannot be opened as Exodus.
bool exodus_file_in_metres(const std::string &path);

/// How a mesh is laid out in the Exodus files Kiln writes, and the names it gets there:
/// - element blocks in increasing id, named "block_<id>"; the cells of a block in increasing
///   order (Exodus element numbers run block after block in this order);
/// - side sets in the mesh's order, named as in the mesh, or "sideset_<id>" when the mesh
///   has no name for them; the gap side set is named "gap" whatever its name in the mesh. A
///   name already taken by an earlier set gets "_<id>" appended, so names are unique;
/// - node sets: one per side set, same id and name, holding the nodes of its faces.
struct ExodusLayout
{
  std::vector<int> block_ids;                   ///< increasing
  std::vector<std::string> block_names;         ///< per block
  std::vector<std::vector<int>> block_cells;    ///< per block, its cells, increasing
  std::vector<std::string> side_set_names;      ///< per mesh.side_sets entry
  std::vector<std::vector<int>> side_set_nodes; ///< per side set, its face nodes, increasing
};
/// `gap_side_sets`: the ids of the gaps' side sets: the first is named "gap", the others
/// "gap_<id>".
ExodusLayout exodus_layout(const Mesh &mesh, const std::vector<int> &gap_side_sets);

namespace internal
{
/// Throws an InputError naming `path` and `what` was being done when an Exodus call made
/// while writing returned an error code (< 0; warnings, > 0, are accepted).
void check_exodus_write(int status, const std::string &path, const std::string &what);

/// Null-terminated copies of `names` and the char* array the Exodus C API wants.
class ExodusNames
{
public:
  explicit ExodusNames(const std::vector<std::string> &names);
  char **data() { return pointers_.data(); }

private:
  std::vector<std::vector<char>> buffers_;
  std::vector<char *> pointers_;
};

/// Writes everything but results into the Exodus file `exo` (an id from ex_create, nothing
/// written yet): the length of names (at least `min_name_length`), the header with `title`,
/// coordinates with their names, the element blocks of `layout` (with `cell_rank` as the
/// element attribute "cell_rank" when it is not null), the side sets and node sets, the
/// names, a QA record and the info record exodus_metres_record.
/// Throws InputError naming `path` when an Exodus call fails.
void put_exodus_mesh(int exo, const std::string &path, const Mesh &mesh, const ExodusLayout &layout,
                     const std::string &title, int min_name_length,
                     const std::vector<int> *cell_rank);
} // namespace internal
} // namespace kiln
