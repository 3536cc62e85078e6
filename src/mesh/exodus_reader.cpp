// Reading Exodus II meshes (read_exodus_mesh, exodus_counts, exodus_file_in_metres).
#include "mesh/exodus_io.hpp"

#include "base/errors.hpp"
#include "base/log.hpp"
#include "mesh/exodus_file.hpp"
#include "mesh/netcdf_header.hpp"

#include <exodusII.h>
#include <netcdf.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <utility>

namespace kiln
{
namespace internal
{
namespace // file-local: these names must not clash with other files' kiln::internal helpers
{
/// Throws an InputError naming the file and the failed operation when an
/// Exodus call returned an error code (< 0; warnings, > 0, are accepted).
void check_exodus(const int status, const std::string &path, const std::string &what)
{
  KILN_CHECK_INPUT(status >= 0, path,
                   "Exodus II error " << status << " while " << what
                                      << "; the file may be damaged or not an Exodus II mesh: "
                                         "re-export it from the mesh generator");
}

/// Exodus 6.02 reads whole netCDF variables (block and side set ids, connectivity, side
/// sets) into the caller's buffer, sized from the counts in the header: in a damaged file
/// whose variable holds more values, that overflowed Kiln's buffers (found by fuzzing).
/// Called before Kiln allocates for it, it also keeps a count in the header without data
/// behind it from asking for gigabytes (found by fuzzing: an out-of-memory).
/// Throws InputError unless variable `name` holds exactly `expected` values, or is absent
/// and not `required`.
void check_variable_size(const int exo, const std::string &path, const std::string &name,
                         const long long expected, const std::string &what,
                         const bool required = true)
{
  int varid = -1, n_dims = 0;
  const bool present = nc_inq_varid(exo, name.c_str(), &varid) == NC_NOERR;
  KILN_CHECK_INPUT(present || !required, path,
                   what << ": netCDF variable " << name
                        << " is missing; the file is damaged: re-export it");
  if (!present || nc_inq_varndims(exo, varid, &n_dims) != NC_NOERR || n_dims < 0 ||
      n_dims > NC_MAX_VAR_DIMS)
    return;
  std::vector<int> dims(std::max(n_dims, 1));
  if (nc_inq_vardimid(exo, varid, dims.data()) != NC_NOERR)
    return;
  long double size = 1;
  for (int d = 0; d < n_dims; ++d)
  {
    std::size_t length = 0;
    if (nc_inq_dimlen(exo, dims[d], &length) != NC_NOERR)
      return;
    size *= static_cast<long double>(length);
  }
  KILN_CHECK_INPUT(size == static_cast<long double>(expected), path,
                   what << " (netCDF variable " << name << ") has size "
                        << static_cast<double>(size) << " where the header announces " << expected
                        << "; the file is damaged: re-export it");
}

/// Exodus finds a block or side set by its id: with an id given twice, it would read one
/// entity's data with the other's counts.
void check_unique_ids(std::vector<int> ids, const std::string &path, const std::string &what)
{
  std::sort(ids.begin(), ids.end());
  const auto twice = std::adjacent_find(ids.begin(), ids.end());
  KILN_CHECK_INPUT(twice == ids.end(), path,
                   what << " id " << (twice == ids.end() ? 0 : *twice)
                        << " is given twice; the file is damaged: re-export it");
}

/// Exodus 6.02's ex_get_block copies block `index`'s (1-based) element type attribute whole
/// into the caller's buffer of MAX_STR_LENGTH + 1 bytes, and copies uninitialised memory
/// into it when the block's dimensions or connectivity variable are missing: in a damaged
/// file both overflowed Kiln's buffer (found by fuzzing). Refuse such a file before. An
/// empty ("NULL") block, eb_status 0, has none of these, and Exodus reads no type for it.
void check_element_type(const int exo, const std::string &path, const int index, const int id)
{
  const std::string n = std::to_string(index);
  int varid = -1, status = 1;
  const std::size_t position = static_cast<std::size_t>(index - 1);
  if (nc_inq_varid(exo, "eb_status", &varid) == NC_NOERR &&
      nc_get_var1_int(exo, varid, &position, &status) != NC_NOERR)
    status = 1;
  if (status == 0)
    return;
  int dimid = -1;
  nc_type type = NC_NAT;
  std::size_t length = 0;
  KILN_CHECK_INPUT(nc_inq_dimid(exo, ("num_el_in_blk" + n).c_str(), &dimid) == NC_NOERR &&
                       nc_inq_dimid(exo, ("num_nod_per_el" + n).c_str(), &dimid) == NC_NOERR &&
                       nc_inq_varid(exo, ("connect" + n).c_str(), &varid) == NC_NOERR &&
                       nc_inq_att(exo, varid, "elem_type", &type, &length) == NC_NOERR &&
                       type == NC_CHAR,
                   path,
                   "element block " << id
                                    << ": its size, connectivity or element type (netCDF "
                                       "num_el_in_blk"
                                    << n << ", num_nod_per_el" << n << ", connect" << n
                                    << ") is missing; the file is damaged: re-export it");
  KILN_CHECK_INPUT(length <= MAX_STR_LENGTH, path,
                   "element block " << id << ": its element type name is " << length
                                    << " characters long, more than the " << MAX_STR_LENGTH
                                    << " Exodus II allows; the file is damaged: re-export it");
}

/// Reads the element blocks (in file order) into the mesh's cells and block ids.
void read_blocks(const int exo, const std::string &path, const int n_blocks, const int n_nodes,
                 Mesh &mesh)
{
  if (n_blocks > 0)
  {
    // ex_id_lkup reads the ids and the status flags whole, in every block call.
    check_variable_size(exo, path, "eb_prop1", n_blocks, "the list of element block ids");
    check_variable_size(exo, path, "eb_status", n_blocks, "the element block status flags", false);
  }
  std::vector<int> ids(n_blocks);
  if (n_blocks > 0)
  {
    check_exodus(ex_get_elem_blk_ids(exo, ids.data()), path, "reading the element block ids");
    check_unique_ids(ids, path, "element block");
  }
  for (int index = 1; index <= n_blocks; ++index)
  {
    const int id = ids[index - 1];
    check_element_type(exo, path, index, id);
    // Larger than Exodus' MAX_STR_LENGTH + 1 and zeroed: its copy ends inside.
    char type[4 * (MAX_STR_LENGTH + 1)] = {};
    int n_elems = 0, n_per_elem = 0, n_attr = 0;
    check_exodus(ex_get_elem_block(exo, id, type, &n_elems, &n_per_elem, &n_attr), path,
                 "reading the parameters of element block " + std::to_string(id));
    const std::optional<CellType> cell_type = exodus_cell_type(type, n_per_elem);
    KILN_CHECK_INPUT(cell_type.has_value(), path,
                     "element block " << id << " has element type \"" << type << "\" with "
                                      << n_per_elem
                                      << " nodes per element; Kiln supports the volume elements "
                                      << supported_volume_types()
                                      << " (shells, beams and 2D elements are not supported): "
                                         "remesh the block with one of these");
    const int n_cell_nodes = ReferenceCell::of(*cell_type).n_nodes();
    KILN_CHECK_INPUT(n_elems >= 0, path,
                     "element block " << id << " announces " << n_elems
                                      << " elements; the file is damaged: re-export it");
    if (n_elems == 0)
      continue;
    check_variable_size(exo, path, "connect" + std::to_string(index),
                        static_cast<long long>(n_elems) * n_cell_nodes,
                        "the connectivity of element block " + std::to_string(id));
    std::vector<int> conn(static_cast<std::size_t>(n_elems) * n_cell_nodes);
    check_exodus(ex_get_elem_conn(exo, id, conn.data()), path,
                 "reading the connectivity of element block " + std::to_string(id));
    for (int e = 0; e < n_elems; ++e)
    {
      int *cell = conn.data() + static_cast<std::size_t>(e) * n_cell_nodes;
      for (int k = 0; k < n_cell_nodes; ++k)
      {
        const int node = cell[k];
        KILN_CHECK_INPUT(node >= 1 && node <= n_nodes, path,
                         "element " << e + 1 << " of element block " << id << " refers to node "
                                    << node << ", outside 1.." << n_nodes
                                    << "; the file is damaged: re-export it");
        cell[k] = node - 1;
      }
      mesh.add_cell(*cell_type, cell, id);
    }
  }
}

/// Reads the side set names, or returns empty names when the file has none.
std::vector<std::string> read_side_set_names(const int exo, const std::string &path,
                                             const int n_side_sets)
{
  // Ask for the longest name the file holds, not the default 32 characters.
  // At most 255 (NC_MAX_NAME - 1): a damaged count would ask for gigabytes per name; Exodus
  // shortens longer names to the length set here.
  const int name_length = std::clamp(
      static_cast<int>(ex_inquire_int(exo, EX_INQ_DB_MAX_USED_NAME_LENGTH)), 1, NC_MAX_NAME - 1);
  check_exodus(ex_set_max_name_length(exo, name_length), path, "setting the name length");
  std::vector<std::vector<char>> buffers(n_side_sets, std::vector<char>(name_length + 1, '\0'));
  std::vector<char *> pointers;
  for (auto &b : buffers)
    pointers.push_back(b.data());
  check_exodus(ex_get_names(exo, EX_SIDE_SET, pointers.data()), path, "reading side set names");
  std::vector<std::string> names;
  for (const auto &b : buffers)
    names.emplace_back(b.data());
  return names;
}

/// Reads every side set (sorted by id) with 0-based cells and faces.
void read_side_sets(const int exo, const std::string &path, const int n_side_sets, Mesh &mesh)
{
  if (n_side_sets == 0)
    return;
  check_variable_size(exo, path, "ss_prop1", n_side_sets, "the list of side set ids");
  check_variable_size(exo, path, "ss_status", n_side_sets, "the side set status flags", false);
  std::vector<int> ids(n_side_sets);
  check_exodus(ex_get_side_set_ids(exo, ids.data()), path, "reading the side set ids");
  check_unique_ids(ids, path, "side set");
  const std::vector<std::string> names = read_side_set_names(exo, path, n_side_sets);
  const int n_cells = mesh.n_cells();
  for (int s = 0; s < n_side_sets; ++s)
  {
    SideSet set;
    set.id = ids[s];
    set.name = names[s];
    int n_sides = 0, n_dist = 0;
    check_exodus(ex_get_side_set_param(exo, set.id, &n_sides, &n_dist), path,
                 "reading the parameters of side set " + std::to_string(set.id));
    KILN_CHECK_INPUT(n_sides >= 0, path,
                     "side set " << set.id << " announces " << n_sides
                                 << " sides; the file is damaged: re-export it");
    if (n_sides > 0)
      for (const char *variable : {"elem_ss", "side_ss"})
        check_variable_size(exo, path, variable + std::to_string(s + 1), n_sides,
                            "side set " + std::to_string(set.id));
    std::vector<int> elems(n_sides), sides(n_sides);
    if (n_sides > 0)
      check_exodus(ex_get_side_set(exo, set.id, elems.data(), sides.data()), path,
                   "reading side set " + std::to_string(set.id));
    std::set<std::pair<int, int>> seen;
    int repeats = 0, first_elem = 0, first_side = 0;
    for (int i = 0; i < n_sides; ++i)
    {
      KILN_CHECK_INPUT(elems[i] >= 1 && elems[i] <= n_cells, path,
                       "side set " << set.id << ", entry " << i + 1 << ": element " << elems[i]
                                   << " is outside 1.." << n_cells
                                   << "; the file is damaged: re-export it");
      KILN_CHECK_INPUT(sides[i] >= 1, path,
                       "side set " << set.id << ", entry " << i + 1 << " (element " << elems[i]
                                   << "): side number " << sides[i]
                                   << " is not a side (they count from 1); the file is "
                                      "damaged: re-export it");
      const ReferenceCell &cell = mesh.reference_cell(elems[i] - 1);
      KILN_CHECK_INPUT(sides[i] <= cell.n_faces(), path,
                       "side set " << set.id << ", entry " << i + 1 << " (element " << elems[i]
                                   << "): side number " << sides[i] << " is outside 1.."
                                   << cell.n_faces() << ", the sides of a " << cell.name()
                                   << "; the side set may hold edges or nodes: redefine it on "
                                      "element faces");
      // A face listed twice would take its flux, traction or pressure twice: keep it once.
      if (!seen.insert({elems[i], sides[i]}).second)
      {
        if (repeats++ == 0)
          first_elem = elems[i], first_side = sides[i];
        continue;
      }
      set.cells.push_back(elems[i] - 1);
      set.faces.push_back(sides[i] - 1);
    }
    if (repeats > 0)
      warn_once(path + ": side set " + std::to_string(set.id) + " lists " +
                std::to_string(repeats) + " face" + (repeats == 1 ? "" : "s") +
                " more than once (the first: element " + std::to_string(first_elem) + ", side " +
                std::to_string(first_side) +
                "); Kiln counts each face once, so a condition on it applies once. Remove the "
                "repeated entries from the mesh to silence this warning");
    mesh.side_sets.push_back(std::move(set));
  }
  std::stable_sort(mesh.side_sets.begin(), mesh.side_sets.end(),
                   [](const SideSet &a, const SideSet &b) { return a.id < b.id; });
}
} // namespace
} // namespace internal

namespace
{
/// Opens an Exodus file for reading, or an InputError naming what is wrong with it (missing,
/// not netCDF, damaged header).
int open_exodus_for_reading(const std::string &path)
{
  KILN_CHECK_INPUT(std::ifstream(path).good(), "",
                   "cannot open Exodus file \"" << path
                                                << "\" (missing or not readable): check the path");
  check_netcdf_file(path);
  int comp_ws = sizeof(double), io_ws = 0;
  float version = 0.0F;
  const int id = ex_open(path.c_str(), EX_READ, &comp_ws, &io_ws, &version);
  KILN_CHECK_INPUT(id >= 0, "",
                   "cannot open Exodus file \"" << path
                                                << "\": it is not an Exodus II (netCDF) file; "
                                                   "check the path and export the mesh as Exodus");
  return id;
}

/// Refuses coordinates that are all equal in one direction (a flat mesh). The Exodus library
/// takes a coordinate variable with netCDF id 0 for an absent one and returns zeros (scipy's
/// netCDF writer stores "coordx" first): such a variable is read with the netCDF library.
void check_coordinates_span(const int exo, const std::string &path,
                            const std::array<std::vector<double> *, 3> &coordinates)
{
  const int n_nodes = static_cast<int>(coordinates[0]->size());
  if (n_nodes < 2)
    return;
  const char *const axes[3] = {"x", "y", "z"};
  const auto flat = [](const std::vector<double> &values)
  {
    const auto [lowest, highest] = std::minmax_element(values.begin(), values.end());
    return *lowest == *highest;
  };
  for (int d = 0; d < 3; ++d)
  {
    std::vector<double> &values = *coordinates[d];
    if (!flat(values))
      continue;
    const std::string variable = std::string("coord") + axes[d];
    int variable_id = -1;
    if (nc_inq_varid(exo, variable.c_str(), &variable_id) == NC_NOERR && variable_id == 0)
    {
      std::vector<double> direct(values.size());
      if (nc_get_var_double(exo, variable_id, direct.data()) == NC_NOERR && !flat(direct))
      {
        values = std::move(direct);
        warn_once(path + ": the Exodus library read \"" + variable +
                  "\" as all zeros, because the file stores it as netCDF variable 0 (as "
                  "scipy.io.netcdf writes it), which that library takes for an absent variable; "
                  "Kiln read the coordinates with the netCDF library instead. Re-export the "
                  "mesh (Cubit, seacas, kiln --write-mesh) for other Exodus tools, which "
                  "misread it the same way");
        continue;
      }
    }
    KILN_CHECK_INPUT(false, path,
                     "all " << n_nodes << " nodes have " << axes[d] << " = " << values.front()
                            << ", so the mesh has no extent in " << axes[d]
                            << " and holds no 3D cell: check the program that wrote the file "
                               "(its \""
                            << variable << "\" values are all equal)");
  }
}
} // namespace

Mesh read_exodus_mesh(const std::string &path, const double scale)
{
  using internal::check_exodus;
  KILN_CHECK_INPUT(std::isfinite(scale) && scale > 0.0, path,
                   "the coordinate scale factor " << scale << " must be > 0");
  const int id = open_exodus_for_reading(path);
  internal::ExodusFile file(id);

  char title[MAX_LINE_LENGTH + 1] = {};
  int n_dim = 0, n_nodes = 0, n_elems = 0, n_blocks = 0, n_node_sets = 0, n_side_sets = 0;
  check_exodus(
      ex_get_init(id, title, &n_dim, &n_nodes, &n_elems, &n_blocks, &n_node_sets, &n_side_sets),
      path, "reading the file header");
  KILN_CHECK_INPUT(n_nodes >= 0 && n_elems >= 0 && n_blocks >= 0 && n_side_sets >= 0, path,
                   "the header announces negative counts (" << n_nodes << " nodes, " << n_elems
                                                            << " elements, " << n_blocks
                                                            << " blocks, " << n_side_sets
                                                            << " side sets); the file is "
                                                               "damaged: re-export it");
  KILN_CHECK_INPUT(n_dim == 3, path,
                   "the mesh is " << n_dim << "-dimensional; Kiln needs a 3D mesh of HEX8 "
                                  << "elements: mesh the geometry as a volume");

  Mesh mesh;
  if (n_nodes > 0)
  {
    // Old files hold the coordinates in one variable "coord" (read piecewise by Exodus).
    int coord = -1;
    if (nc_inq_varid(id, "coord", &coord) == NC_NOERR)
      internal::check_variable_size(id, path, "coord", 3LL * n_nodes, "the coordinates");
    else
      for (const char *variable : {"coordx", "coordy", "coordz"})
        internal::check_variable_size(id, path, variable, n_nodes, "the coordinates");
  }
  std::vector<double> x(n_nodes), y(n_nodes), z(n_nodes);
  if (n_nodes > 0)
  {
    check_exodus(ex_get_coord(id, x.data(), y.data(), z.data()), path, "reading the coordinates");
  }
  internal::read_blocks(id, path, n_blocks, n_nodes, mesh); // element types checked first
  check_coordinates_span(id, path, {&x, &y, &z});
  mesh.coordinates.resize(n_nodes);
  for (int i = 0; i < n_nodes; ++i)
    mesh.coordinates[i] = {scale * x[i], scale * y[i], scale * z[i]};
  KILN_CHECK_INPUT(mesh.n_cells() == n_elems, path,
                   "the header announces " << n_elems << " elements but the blocks hold "
                                           << mesh.n_cells()
                                           << "; the file is damaged: re-export it");
  internal::read_side_sets(id, path, n_side_sets, mesh);
  return mesh;
}

ExodusCounts exodus_counts(const std::string &path)
{
  const int id = open_exodus_for_reading(path);
  internal::ExodusFile file(id);
  // The counts the file's data back, not the header's alone: a damaged header (a node count
  // without coordinates) is reported by read_exodus_mesh, not taken for a large mesh.
  const auto dimension = [id](const std::string &name)
  {
    int dim = -1;
    std::size_t length = 0;
    return nc_inq_dimid(id, name.c_str(), &dim) == NC_NOERR &&
                   nc_inq_dimlen(id, dim, &length) == NC_NOERR
               ? static_cast<long long>(length)
               : 0LL;
  };
  const auto variable = [id](const std::string &name)
  {
    int var = -1;
    return nc_inq_varid(id, name.c_str(), &var) == NC_NOERR;
  };
  ExodusCounts counts;
  if (variable("coord") || (variable("coordx") && variable("coordy") && variable("coordz")))
    counts.nodes = dimension("num_nodes");
  for (long long b = 1, n = dimension("num_el_blk"); b <= n; ++b)
    if (variable("connect" + std::to_string(b)))
      counts.elements += dimension("num_el_in_blk" + std::to_string(b));
  return counts;
}

bool exodus_file_in_metres(const std::string &path)
{
  const int id = open_exodus_for_reading(path);
  internal::ExodusFile file(id);
  const int n_info = static_cast<int>(ex_inquire_int(id, EX_INQ_INFO));
  if (n_info <= 0)
    return false;
  std::vector<std::vector<char>> buffers(n_info, std::vector<char>(MAX_LINE_LENGTH + 1, '\0'));
  std::vector<char *> pointers;
  for (auto &b : buffers)
    pointers.push_back(b.data());
  internal::check_exodus(ex_get_info(id, pointers.data()), path, "reading the info records");
  return std::any_of(buffers.begin(), buffers.end(),
                     [](const std::vector<char> &b)
                     { return std::string(b.data()) == exodus_metres_record; });
}
} // namespace kiln
