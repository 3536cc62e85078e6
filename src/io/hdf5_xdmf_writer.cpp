#include "io/hdf5_xdmf_writer.hpp"

#include "base/errors.hpp"
#include "io/collective_checks.hpp"
#include "io/field_catalog.hpp"
#include "io/gap_surface.hpp"
#include "io/history_csv.hpp"
#include "io/parallel_hdf5_file.hpp"
#include "io/xdmf_index.hpp"

#include <cstdint>
#include <cstdio>
#include <map>

namespace kiln
{
using internal::Center;
using internal::FieldSpec;

/// The HDF5 file (written collectively), its XDMF index and the step in progress.
struct Hdf5XdmfWriter::Impl
{
  Impl(MPI_Comm comm, const std::string &base_path, const Mesh &mesh,
       const std::vector<int> &owned_nodes, const std::vector<int> &owned_cells);
  /// The unit, components and meaning of a field of the catalog on its dataset in `group`.
  void describe(hid_t group, const std::string &name) const;
  /// A gap's surface (an HDF5 group /NAME, NAME = Mesh::gap_name()), the points whose node
  /// (side a) this rank owns and the group of the step in progress.
  struct GapGrid
  {
    std::string name;
    internal::GapSurface surface;
    std::vector<int> owned_points;
    std::vector<std::size_t> value_row; ///< for each owned point, its node's owned position
    internal::OwnedRows rows;
    internal::H5Handle step_group;
  };
  /// /NAME: the gap surface's points, quadrilaterals, nodes and areas (rank 0 writes).
  void write_gap_surface(const GapGrid &grid) const;
  /// The values of a node field at the points of `grid` this rank owns: the pairs' values of
  /// write_gap_field() where given, else the values at their nodes a.
  std::vector<double> gap_values(const GapGrid &grid, const std::string &name,
                                 const std::vector<double> &values, int n_components) const;
  /// The history rows held back, into /history (collective).
  void write_pending_history();

  void write_mesh(const Mesh &mesh, const std::vector<int> &owned_nodes,
                  const std::vector<int> &owned_cells, const std::vector<int> &cell_rank) const;
  /// /mesh/topology, the cells in XDMF's node order: (cells x nodes) for one type, or
  /// "Mixed" (each cell's XDMF code, then its nodes).
  void write_xdmf_topology(const Mesh &mesh, const std::vector<int> &owned_cells,
                           hid_t group) const;
  void write_field(const FieldSpec &field, const std::vector<double> &values);
  /// The name of the step in progress (the last one begun), for messages.
  std::string step_name() const { return internal::step_group_name(index.n_steps() - 1); }

  MPI_Comm comm;
  std::string base;
  /// Whether XDMF reads the cells from /mesh/topology (internal::xdmf_topology); set before
  /// `index` is made.
  bool own_topology_dataset = false;
  internal::OwnedRows node_rows;
  internal::OwnedRows cell_rows;
  internal::ParallelHdf5File file;
  internal::XdmfIndex index;
  std::vector<HistoryColumn> columns;               ///< of the history
  std::vector<std::vector<double>> pending_history; ///< rows not yet in /history
  // After the file: closed before it.
  std::vector<GapGrid> gaps; ///< those with pairs, Mesh::gap_side_sets order
  std::map<std::string, std::vector<double>> gap_fields; ///< this step's, per mesh pair
  internal::H5Handle step_group;
  bool in_step = false;
  /// The file's size after the last step (or the mesh), and the largest growth of a step [bytes].
  std::uintmax_t size_before_step = 0;
  std::uintmax_t largest_step = 0;
};

Hdf5XdmfWriter::Impl::Impl(const MPI_Comm communicator, const std::string &base_path,
                           const Mesh &mesh, const std::vector<int> &owned_nodes,
                           const std::vector<int> &owned_cells)
    : comm(communicator), base(base_path), node_rows(owned_nodes, mesh.n_nodes()),
      cell_rows(owned_cells, mesh.n_cells()), file(communicator, base_path + ".running.h5"),
      index(communicator, base_path + ".running.xmf", file.path(), mesh.n_nodes(), mesh.n_cells(),
            internal::xdmf_topology(mesh, own_topology_dataset)),
      columns(history_columns(mesh.gap_side_sets, mesh.contact_pair_names()))
{
  std::map<int, std::size_t> owned_position;
  for (std::size_t i = 0; i < owned_nodes.size(); ++i)
    owned_position[owned_nodes[i]] = i;
  const auto add_grid = [&](const std::string &name, internal::GapSurface surface)
  {
    std::vector<int> owned_points;
    std::vector<std::size_t> value_row;
    for (int p = 0; p < surface.n_points(); ++p)
      if (const auto it = owned_position.find(static_cast<int>(surface.node_a[p]));
          it != owned_position.end())
      {
        owned_points.push_back(p);
        value_row.push_back(it->second);
      }
    const internal::OwnedRows rows(owned_points, surface.n_points());
    index.add_gap(name, surface.n_points(), surface.n_faces(), surface.face_type(),
                  internal::mixed_gap_connectivity(surface).size());
    gaps.push_back({name, std::move(surface), std::move(owned_points), std::move(value_row), rows,
                    internal::H5Handle()});
  };
  for (int g = 0; g < static_cast<int>(mesh.gap_side_sets.size()); ++g)
    if (internal::GapSurface surface(mesh, g); surface.n_points() > 0)
      add_grid(mesh.gap_name(g), std::move(surface));
  // A contact pair's secondary surface: its side set's faces, the node fields at its nodes.
  for (const ContactPairSurface &pair : mesh.contact_pairs)
    for (const SideSet &side_set : mesh.side_sets)
      if (side_set.id == pair.secondary_side_set)
        add_grid(pair.surface_name(), internal::GapSurface(mesh, side_set));
}

void Hdf5XdmfWriter::Impl::describe(const hid_t group, const std::string &name) const
{
  const FieldDescription *known = describe_field(name);
  if (known == nullptr)
    return;
  std::string components;
  for (const std::string &c : known->components)
    components += (components.empty() ? "" : ",") + c;
  const internal::H5Handle dataset = file.open_dataset(group, name);
  file.write_attributes(dataset.get(),
                        {{"unit", known->unit},
                         {"components", components.empty() ? std::string("scalar") : components},
                         {"meaning", known->meaning}},
                        "describing field " + name);
}

void Hdf5XdmfWriter::Impl::write_xdmf_topology(const Mesh &mesh,
                                               const std::vector<int> &owned_cells,
                                               const hid_t group) const
{
  const bool mixed = mesh.types().size() > 1;
  std::vector<std::int64_t> entries;
  std::vector<int> owned_entries; // Mixed: this rank's positions in the 1-D dataset
  for (const int c : owned_cells)
  {
    const ReferenceCell &cell = mesh.reference_cell(c);
    const Span<const int> nodes = mesh.cell_nodes(c);
    if (mixed)
    {
      const int first = c + mesh.cell_offsets[c]; // the codes and nodes of the cells before
      for (int k = 0; k <= nodes.size(); ++k)
        owned_entries.push_back(first + k);
      entries.push_back(cell.xdmf_code());
    }
    for (int i = 0; i < nodes.size(); ++i)
      entries.push_back(nodes[cell.xdmf_order().empty() ? i : cell.xdmf_order()[i]]);
  }
  if (mixed)
    file.write_rows(
        group, "topology",
        internal::OwnedRows(owned_entries,
                            mesh.n_cells() + static_cast<int>(mesh.cell_node_ids.size())),
        1, entries);
  else
    file.write_rows(group, "topology", cell_rows, mesh.reference_cell(0).n_nodes(), entries);
}

void Hdf5XdmfWriter::Impl::write_mesh(const Mesh &mesh, const std::vector<int> &owned_nodes,
                                      const std::vector<int> &owned_cells,
                                      const std::vector<int> &cell_rank) const
{
  const internal::H5Handle group = file.create_group("mesh");
  std::vector<double> coordinates;
  coordinates.reserve(3 * owned_nodes.size());
  for (const int n : owned_nodes)
    coordinates.insert(coordinates.end(), mesh.coordinates[n].begin(), mesh.coordinates[n].end());
  file.write_rows(group.get(), "coordinates", node_rows, 3, coordinates);

  // (cells x the most nodes of a cell), Exodus order, a smaller cell's row padded with -1.
  int width = 0;
  for (const CellType type : mesh.types())
    width = std::max(width, ReferenceCell::of(type).n_nodes());
  std::vector<std::int64_t> connectivity;
  std::vector<std::int32_t> block_id;
  std::vector<std::int32_t> owner;
  connectivity.reserve(static_cast<std::size_t>(width) * owned_cells.size());
  for (const int c : owned_cells)
  {
    const Span<const int> nodes = mesh.cell_nodes(c);
    connectivity.insert(connectivity.end(), nodes.begin(), nodes.end());
    connectivity.insert(connectivity.end(), width - nodes.size(), -1);
    block_id.push_back(mesh.block_id[c]);
    owner.push_back(cell_rank[c]);
  }
  file.write_rows(group.get(), "connectivity", cell_rows, width, connectivity);
  if (own_topology_dataset)
    write_xdmf_topology(mesh, owned_cells, group.get());
  file.write_rows(group.get(), "block_id", cell_rows, 1, block_id);
  file.write_rows(group.get(), "cell_rank", cell_rows, 1, owner);

  file.create_group("steps"); // closed at once: each step opens its own group in it
}

void Hdf5XdmfWriter::Impl::write_field(const FieldSpec &field, const std::vector<double> &values)
{
  const std::string &name = field.name;
  internal::check_write_field(in_step, field);
  // "." and ".." would be read as paths by HDF5.
  KILN_CHECK_INPUT(internal::is_valid_field_name(name) && name != "." && name != "..", file.path(),
                   "field name \"" << name
                                   << "\" is not valid: use letters, digits, '_', '-' and '.'");
  KILN_CHECK_INPUT(field.n_components >= 1, file.path(),
                   "field \"" << name << "\" has " << field.n_components
                              << " components; need >= 1");
  KILN_CHECK_INPUT(!index.has_field(name), file.path(),
                   "field \"" << name << "\" is written twice in step " << step_name());
  const std::size_t n_owned = field.center == Center::node ? node_rows.n_owned : cell_rows.n_owned;
  internal::check_field_size(comm, field, n_owned, values.size());

  file.write_rows(step_group.get(), name, field.center == Center::node ? node_rows : cell_rows,
                  field.n_components, values);
  describe(step_group.get(), name);
  if (field.center == Center::node)
    for (const GapGrid &grid : gaps)
    {
      file.write_rows(grid.step_group.get(), name, grid.rows, field.n_components,
                      gap_values(grid, name, values, field.n_components));
      describe(grid.step_group.get(), name);
    }
  index.add_field(field);
}

std::vector<double> Hdf5XdmfWriter::Impl::gap_values(const GapGrid &grid, const std::string &name,
                                                     const std::vector<double> &values,
                                                     const int n_components) const
{
  std::vector<double> at_gap;
  at_gap.reserve(grid.value_row.size() * static_cast<std::size_t>(n_components));
  const auto of_pairs = gap_fields.find(name);
  const bool of_gap = !grid.surface.pair.empty() && grid.surface.pair.front() >= 0;
  if (of_pairs != gap_fields.end() && n_components == 1 && of_gap)
  {
    for (const int p : grid.owned_points)
      at_gap.push_back(of_pairs->second[static_cast<std::size_t>(grid.surface.pair[p])]);
    return at_gap;
  }
  for (const std::size_t row : grid.value_row)
    for (int c = 0; c < n_components; ++c)
      at_gap.push_back(values[row * static_cast<std::size_t>(n_components) + c]);
  return at_gap;
}

void Hdf5XdmfWriter::Impl::write_gap_surface(const GapGrid &grid) const
{
  const internal::GapSurface &gap = grid.surface;
  const internal::H5Handle group = file.create_group(grid.name);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  // Rank 0 writes every row (the gap is small and replicated).
  // One type of face: n_faces x its nodes; several: XDMF's Mixed list (type code, nodes).
  const std::optional<CellType> face_type = gap.face_type();
  const int corners = face_type ? ReferenceCell::of(*face_type).n_nodes() : 0;
  const std::vector<std::int64_t> mixed =
      corners == 0 ? internal::mixed_gap_connectivity(gap) : std::vector<std::int64_t>();
  const int n_rows = corners == 0 ? static_cast<int>(mixed.size()) : gap.n_faces();
  std::vector<int> all_points, all_rows;
  if (rank == 0)
  {
    for (int p = 0; p < gap.n_points(); ++p)
      all_points.push_back(p);
    for (int q = 0; q < n_rows; ++q)
      all_rows.push_back(q);
  }
  const internal::OwnedRows points(all_points, gap.n_points()), rows(all_rows, n_rows);
  std::vector<double> coordinates, area, s, t;
  std::vector<std::int64_t> connectivity, node_a, node_b;
  if (rank == 0)
  {
    for (const Point &x : gap.points)
      coordinates.insert(coordinates.end(), x.begin(), x.end());
    if (corners == 0)
      connectivity = mixed;
    else
      for (const auto &face : gap.faces)
        connectivity.insert(connectivity.end(), face.begin(), face.end());
    area = gap.area;
    s = gap.s;
    t = gap.t;
    node_a = gap.node_a;
    node_b = gap.node_b;
  }
  file.write_rows(group.get(), "coordinates", points, 3, coordinates);
  file.write_rows(group.get(), "connectivity", rows, corners == 0 ? 1 : corners, connectivity);
  file.write_rows(group.get(), "node_a", points, 1, node_a);
  file.write_rows(group.get(), "node_b", points, 1, node_b);
  file.write_rows(group.get(), "area", points, 1, area);
  file.write_rows(group.get(), "s", points, 1, s);
  file.write_rows(group.get(), "t", points, 1, t);
  file.create_group(grid.name + "/steps");
}

void Hdf5XdmfWriter::Impl::write_pending_history()
{
  if (pending_history.empty())
    return;
  const internal::H5Handle group(H5Gopen2(file.root(), "history", H5P_DEFAULT), H5Gclose);
  file.check_io(group.valid(), "opening group /history");
  for (std::size_t c = 0; c < columns.size(); ++c)
  {
    std::vector<double> values;
    for (const auto &row : pending_history)
      values.push_back(row[c]);
    file.append_rows(group.get(), columns[c].name, values);
  }
  pending_history.clear();
}

Hdf5XdmfWriter::Hdf5XdmfWriter(const MPI_Comm comm, const std::string &base_path, const Mesh &mesh,
                               const std::vector<int> &owned_nodes,
                               const std::vector<int> &owned_cells,
                               const std::vector<int> &cell_rank, const ResultsMetadata &metadata)
{
  // The ownership must be a partition of the rows; a mistake here is the caller's.
  internal::check_row_partition(comm, mesh, owned_nodes, owned_cells, cell_rank);
  impl_ = std::make_unique<Impl>(comm, base_path, mesh, owned_nodes, owned_cells);
  impl_->file.write_attributes(impl_->file.root(),
                               {{"kiln_version", metadata.kiln_version},
                                {"created", metadata.created},
                                {"input_path", metadata.input_path},
                                {"input", metadata.input},
                                {"run_fingerprint", metadata.run_fingerprint}},
                               "writing the run's metadata");
  impl_->write_mesh(mesh, owned_nodes, owned_cells, cell_rank);
  for (const Impl::GapGrid &grid : impl_->gaps)
    impl_->write_gap_surface(grid);
  {
    // The history's datasets, empty until the first rows, each with its unit and meaning.
    const internal::H5Handle group = impl_->file.create_group("history");
    for (const HistoryColumn &c : impl_->columns)
    {
      impl_->file.append_rows(group.get(), c.name, {});
      const internal::H5Handle dataset = impl_->file.open_dataset(group.get(), c.name);
      impl_->file.write_attributes(dataset.get(), {{"unit", c.unit}, {"meaning", c.meaning}},
                                   "describing /history/" + c.name);
    }
  }
  impl_->file.flush();
  impl_->size_before_step = impl_->file.size();
  // Before the first step, a guess: a step's fields take about a quarter of the mesh's bytes.
  impl_->largest_step = impl_->size_before_step / 4;
  impl_->index.write();
}

Hdf5XdmfWriter::~Hdf5XdmfWriter() = default;

void Hdf5XdmfWriter::begin_step(const double time, const int cycle, const double dt)
{
  Impl &m = *impl_;
  internal::check_begin_step(m.in_step);
  // Room for twice the largest step so far (the mesh before the first), and the metadata.
  m.file.reserve(2 * m.largest_step + (std::uintmax_t{64} << 10));
  m.step_group = m.file.create_group("steps/" + internal::step_group_name(m.index.n_steps()));
  for (Impl::GapGrid &grid : m.gaps)
    grid.step_group =
        m.file.create_group(grid.name + "/steps/" + internal::step_group_name(m.index.n_steps()));
  m.gap_fields.clear();
  m.index.add_step(time);
  m.in_step = true;
  m.file.write_attributes(m.step_group.get(),
                          {{"time", time}, {"dt", dt}, {"cycle", std::int32_t{cycle}}},
                          "writing the attributes of step " + m.step_name());
}

void Hdf5XdmfWriter::write_node_field(const std::string &name, const int n_components,
                                      const std::vector<double> &values)
{
  impl_->write_field({name, Center::node, n_components}, values);
}

void Hdf5XdmfWriter::write_gap_field(const std::string &name, const std::vector<double> &per_pair)
{
  impl_->gap_fields[name] = per_pair;
}

void Hdf5XdmfWriter::write_cell_field(const std::string &name, const int n_components,
                                      const std::vector<double> &values)
{
  impl_->write_field({name, Center::cell, n_components}, values);
}

void Hdf5XdmfWriter::write_history(const std::vector<double> &row)
{
  internal::check_usage(row.size() == impl_->columns.size(), "row.size() == columns.size()",
                        "a history row needs one value per column of "
                        "history_columns(mesh.gap_side_sets, mesh.contact_pair_names())");
  impl_->pending_history.push_back(row);
}

void Hdf5XdmfWriter::end_step()
{
  Impl &m = *impl_;
  internal::check_end_step(m.in_step);
  m.step_group.reset();
  for (Impl::GapGrid &grid : m.gaps)
    grid.step_group.reset();
  m.gap_fields.clear();
  m.in_step = false;
  m.write_pending_history();
  m.file.flush();
  const std::uintmax_t size = m.file.size();
  m.largest_step = std::max(m.largest_step, size - std::min(size, m.size_before_step));
  m.size_before_step = size;
  m.index.write();
}

void Hdf5XdmfWriter::finish(const std::string &status)
{
  Impl &m = *impl_;
  if (m.in_step) // the same on every rank: the calls are collective
    throw InternalError(m.file.path() + ": finish() while step " + m.step_name() +
                        " is open; call end_step() first");
  m.write_pending_history();
  m.file.write_attributes(m.file.root(), {{"status", status}}, "writing the status");
  const std::string running_h5 = m.file.path(), running_xmf = m.index.path();
  m.file.close();
  int rank = 0;
  MPI_Comm_rank(m.comm, &rank);
  bool ok = true;
  if (rank == 0)
    ok = std::rename(running_h5.c_str(), (m.base + ".h5").c_str()) == 0;
  internal::check_input_collectively(m.comm, ok, m.base + ".h5",
                                     "cannot rename " + running_h5 +
                                         " to its final name; check the folder's permissions");
  m.index.rename(m.base + ".xmf", m.base + ".h5");
  m.index.write();
  if (rank == 0)
    std::remove(running_xmf.c_str());
  finished_h5_ = m.base + ".h5";
}

void Hdf5XdmfWriter::set_final_base(const std::string &final_base)
{
  impl_->base = final_base;
}

std::string Hdf5XdmfWriter::h5_path() const
{
  return finished_h5_.empty() ? impl_->file.path() : finished_h5_;
}

std::string Hdf5XdmfWriter::xdmf_path() const
{
  return impl_->index.path();
}
} // namespace kiln
