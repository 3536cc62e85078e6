// Writing Exodus II meshes (write_exodus_mesh) and the layout every Exodus file Kiln writes
// shares (exodus_layout, the names, the QA and info records).
#include "mesh/exodus_io.hpp"

#include "base/errors.hpp"
#include "mesh/exodus_file.hpp"
#include "mesh/side_set_nodes.hpp"

#include <exodusII.h>
#include <kiln/version.hpp>

#include <algorithm>
#include <ctime>
#include <map>
#include <set>
#include <utility>

namespace kiln
{
namespace internal
{
namespace // file-local: these names must not clash with other files' kiln::internal helpers
{
/// "YYYY-MM-DD" and "hh:mm:ss" now (local time), for the QA record.
std::pair<std::string, std::string> date_and_time()
{
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char date[16] = {}, clock[16] = {};
  std::strftime(date, sizeof date, "%Y-%m-%d", &local);
  std::strftime(clock, sizeof clock, "%H:%M:%S", &local);
  return {date, clock};
}

void put_blocks(const int exo, const std::string &path, const Mesh &mesh,
                const ExodusLayout &layout, const std::vector<int> *cell_rank)
{
  for (std::size_t b = 0; b < layout.block_ids.size(); ++b)
  {
    const int id = layout.block_ids[b];
    const std::vector<int> &cells = layout.block_cells[b];
    const std::string what = "writing element block " + std::to_string(id);
    // A block holds cells of one type (check_mesh); an empty block is written as HEX8.
    const ReferenceCell &type =
        ReferenceCell::of(cells.empty() ? CellType::hex8 : mesh.cell_type(cells.front()));
    check_exodus_write(ex_put_elem_block(exo, id, type.name().c_str(),
                                         static_cast<int64_t>(cells.size()), type.n_nodes(),
                                         cell_rank != nullptr ? 1 : 0),
                       path, what);
    std::vector<int> conn;
    for (const int c : cells)
      for (const int node : mesh.cell_nodes(c))
      {
        KILN_ASSERT(node >= 0 && node < mesh.n_nodes(), "cell " << c << " node " << node);
        conn.push_back(node + 1);
      }
    check_exodus_write(ex_put_elem_conn(exo, id, conn.data()), path, what);
    if (cell_rank != nullptr)
    {
      std::vector<double> rank;
      for (const int c : cells)
        rank.push_back((*cell_rank)[c]);
      check_exodus_write(ex_put_elem_attr(exo, id, rank.data()), path, what);
      ExodusNames attribute_name({"cell_rank"});
      check_exodus_write(ex_put_attr_names(exo, EX_ELEM_BLOCK, id, attribute_name.data()), path,
                         what);
    }
  }
  if (!layout.block_ids.empty())
  {
    ExodusNames names(layout.block_names);
    check_exodus_write(ex_put_names(exo, EX_ELEM_BLOCK, names.data()), path,
                       "writing element block names");
  }
}

/// The side sets, with cells renumbered to their position in the written file, and a node
/// set for each.
void put_sets(const int exo, const std::string &path, const Mesh &mesh, const ExodusLayout &layout)
{
  std::vector<int> file_number(mesh.n_cells()); // 1-based Exodus element number per cell
  int next = 1;
  for (const auto &cells : layout.block_cells)
    for (const int c : cells)
      file_number[c] = next++;
  for (std::size_t s = 0; s < mesh.side_sets.size(); ++s)
  {
    const SideSet &set = mesh.side_sets[s];
    KILN_ASSERT(set.faces.size() == set.cells.size(), "side set " << set.id);
    std::vector<int> elems, sides;
    for (int i = 0; i < set.n_sides(); ++i)
    {
      KILN_ASSERT(set.cells[i] >= 0 && set.cells[i] < mesh.n_cells(), "side set " << set.id);
      KILN_ASSERT(set.faces[i] >= 0 && set.faces[i] < mesh.reference_cell(set.cells[i]).n_faces(),
                  "side set " << set.id);
      elems.push_back(file_number[set.cells[i]]);
      sides.push_back(set.faces[i] + 1);
    }
    const std::string what = "writing side set " + std::to_string(set.id);
    check_exodus_write(ex_put_side_set_param(exo, set.id, set.n_sides(), 0), path, what);
    check_exodus_write(ex_put_side_set(exo, set.id, elems.data(), sides.data()), path, what);

    std::vector<int> nodes;
    for (const int n : layout.side_set_nodes[s])
      nodes.push_back(n + 1);
    const std::string node_set = "writing node set " + std::to_string(set.id);
    check_exodus_write(ex_put_node_set_param(exo, set.id, static_cast<int64_t>(nodes.size()), 0),
                       path, node_set);
    check_exodus_write(ex_put_node_set(exo, set.id, nodes.data()), path, node_set);
  }
  if (mesh.side_sets.empty())
    return;
  ExodusNames side_set_names(layout.side_set_names);
  check_exodus_write(ex_put_names(exo, EX_SIDE_SET, side_set_names.data()), path,
                     "writing side set names");
  ExodusNames node_set_names(layout.side_set_names);
  check_exodus_write(ex_put_names(exo, EX_NODE_SET, node_set_names.data()), path,
                     "writing node set names");
}

/// The QA record (code, version, date, time) and the info record on the unit.
void put_records(const int exo, const std::string &path)
{
  const auto [date, clock] = date_and_time();
  ExodusNames qa({"kiln", version_string, date, clock});
  char *qa_record[1][4] = {{qa.data()[0], qa.data()[1], qa.data()[2], qa.data()[3]}};
  check_exodus_write(ex_put_qa(exo, 1, qa_record), path, "writing the QA record");
  ExodusNames info({exodus_metres_record});
  check_exodus_write(ex_put_info(exo, 1, info.data()), path, "writing the info record");
}
} // namespace
} // namespace internal

ExodusLayout exodus_layout(const Mesh &mesh, const std::vector<int> &gap_side_sets)
{
  const auto gap_name = [&](const int id) -> std::string
  {
    if (!gap_side_sets.empty() && id == gap_side_sets.front())
      return "gap";
    return std::find(gap_side_sets.begin(), gap_side_sets.end(), id) != gap_side_sets.end()
               ? "gap_" + std::to_string(id)
               : "";
  };
  ExodusLayout layout;
  std::map<int, std::vector<int>> cells_of_block;
  for (int c = 0; c < mesh.n_cells(); ++c)
    cells_of_block[mesh.block_id[c]].push_back(c);
  for (auto &block : cells_of_block)
  {
    layout.block_ids.push_back(block.first);
    layout.block_names.push_back("block_" + std::to_string(block.first));
    layout.block_cells.push_back(std::move(block.second));
  }

  std::set<std::string> taken;
  for (const int id : gap_side_sets)
    if (mesh.find_side_set(id) != nullptr)
      taken.insert(gap_name(id));
  for (const SideSet &set : mesh.side_sets)
  {
    const bool gap = !gap_name(set.id).empty();
    std::string name = gap                ? gap_name(set.id)
                       : set.name.empty() ? "sideset_" + std::to_string(set.id)
                                          : set.name;
    if (!gap && !taken.insert(name).second)
    {
      name += "_" + std::to_string(set.id);
      taken.insert(name);
    }
    layout.side_set_names.push_back(name);

    layout.side_set_nodes.push_back(side_set_nodes(mesh, set));
  }
  return layout;
}

namespace internal
{
void check_exodus_write(const int status, const std::string &path, const std::string &what)
{
  KILN_CHECK_INPUT(status >= 0, path,
                   "Exodus II error " << status << " while " << what
                                      << "; check that the disk is not full and that the file "
                                         "is not removed or opened by another program while "
                                         "Kiln writes it");
}

ExodusNames::ExodusNames(const std::vector<std::string> &names)
{
  for (const auto &name : names)
  {
    buffers_.emplace_back(name.begin(), name.end());
    buffers_.back().push_back('\0');
  }
  for (auto &b : buffers_)
    pointers_.push_back(b.data());
}

void put_exodus_mesh(const int exo, const std::string &path, const Mesh &mesh,
                     const ExodusLayout &layout, const std::string &title,
                     const int min_name_length, const std::vector<int> *cell_rank)
{
  KILN_ASSERT(static_cast<int>(mesh.block_id.size()) == mesh.n_cells(), "block_id size");
  KILN_ASSERT(cell_rank == nullptr || static_cast<int>(cell_rank->size()) == mesh.n_cells(),
              "cell_rank size");
  // Names longer than the default 32 characters are kept only if the length is set before
  // ex_put_init defines the file.
  std::size_t name_length = std::max<std::size_t>(MAX_NAME_LENGTH, min_name_length);
  for (const auto &name : layout.side_set_names)
    name_length = std::max(name_length, name.size());
  for (const auto &name : layout.block_names)
    name_length = std::max(name_length, name.size());
  check_exodus_write(ex_set_max_name_length(exo, static_cast<int>(name_length)), path,
                     "setting the name length");

  const int64_t n_sets = static_cast<int64_t>(mesh.side_sets.size());
  check_exodus_write(ex_put_init(exo, title.c_str(), 3, mesh.n_nodes(), mesh.n_cells(),
                                 static_cast<int64_t>(layout.block_ids.size()), n_sets, n_sets),
                     path, "writing the file header");
  std::vector<double> x, y, z;
  for (const auto &p : mesh.coordinates)
  {
    x.push_back(p[0]);
    y.push_back(p[1]);
    z.push_back(p[2]);
  }
  check_exodus_write(ex_put_coord(exo, x.data(), y.data(), z.data()), path,
                     "writing the coordinates");
  ExodusNames coordinate_names({"x", "y", "z"});
  check_exodus_write(ex_put_coord_names(exo, coordinate_names.data()), path,
                     "writing the coordinate names");
  put_blocks(exo, path, mesh, layout, cell_rank);
  put_sets(exo, path, mesh, layout);
  put_records(exo, path);
}
} // namespace internal

void write_exodus_mesh(const Mesh &mesh, const std::string &path,
                       const std::vector<int> &gap_side_sets)
{
  int comp_ws = sizeof(double), io_ws = sizeof(double);
  const int id = ex_create(path.c_str(), EX_CLOBBER, &comp_ws, &io_ws);
  KILN_CHECK_INPUT(id >= 0, "",
                   "cannot create Exodus file \"" << path
                                                  << "\": check that its folder exists and is "
                                                     "writable");
  internal::ExodusFile file(id);
  internal::put_exodus_mesh(id, path, mesh, exodus_layout(mesh, gap_side_sets), "Kiln mesh",
                            MAX_NAME_LENGTH, nullptr);
  internal::check_exodus_write(file.close(), path, "closing the file");
}

void write_exodus_mesh(const Mesh &mesh, const std::string &path)
{
  write_exodus_mesh(mesh, path, mesh.gap_side_sets);
}
} // namespace kiln
