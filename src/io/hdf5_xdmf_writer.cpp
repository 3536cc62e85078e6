#include "io/hdf5_xdmf_writer.hpp"

#include "base/errors.hpp"

#include <Teuchos_DefaultMpiComm.hpp>
#include <hdf5.h>

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <utility>

namespace kiln
{
namespace internal
{
/// Owns one HDF5 identifier and closes it with the matching H5?close function.
class H5Handle
{
public:
  using Closer = herr_t (*)(hid_t);
  H5Handle() = default;
  H5Handle(const hid_t id, const Closer closer) : id_(id), closer_(closer) {}
  ~H5Handle() { reset(); }
  H5Handle(H5Handle &&other) noexcept : id_(other.id_), closer_(other.closer_) { other.id_ = -1; }
  H5Handle &operator=(H5Handle &&other) noexcept
  {
    if (this != &other)
    {
      reset();
      std::swap(id_, other.id_);
      closer_ = other.closer_;
    }
    return *this;
  }
  H5Handle(const H5Handle &) = delete;
  H5Handle &operator=(const H5Handle &) = delete;

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  void reset()
  {
    if (id_ >= 0 && closer_ != nullptr)
      closer_(id_);
    id_ = -1;
  }

private:
  hid_t id_ = -1;
  Closer closer_ = nullptr;
};

/// A run of consecutive global rows [first, first + count).
struct RowRun
{
  hsize_t first = 0;
  hsize_t count = 0;
};

/// The contiguous runs in a sorted list of row ids.
std::vector<RowRun> contiguous_runs(const std::vector<int> &rows)
{
  std::vector<RowRun> runs;
  for (const int row : rows)
  {
    const auto r = static_cast<hsize_t>(row);
    if (!runs.empty() && runs.back().first + runs.back().count == r)
      ++runs.back().count;
    else
      runs.push_back({r, 1});
  }
  return runs;
}

/// True on every rank if `local_ok` is true on every rank.
bool all_ok(const MPI_Comm comm, const bool local_ok)
{
  int ok = local_ok ? 1 : 0;
  int global_ok = 0;
  MPI_Allreduce(&ok, &global_ok, 1, MPI_INT, MPI_MIN, comm);
  return global_ok == 1;
}

/// Throws the same InternalError on every rank if `local_ok` is false on any rank
/// (a programmer error found on some ranks only must not leave the others hanging).
void check_internal_collectively(const MPI_Comm comm, const bool local_ok, const char *condition,
                                 const std::string &message)
{
  if (!all_ok(comm, local_ok))
    throw_internal_error(__FILE__, __LINE__, condition, message);
}

/// Field names become HDF5 link names and XML attribute values: keep them plain.
bool is_valid_field_name(const std::string &name)
{
  if (name.empty() || name == "." || name == "..")
    return false;
  for (const char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
      return false;
  return true;
}

std::string directory_of(const std::string &path)
{
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash + 1);
}

std::string file_name_of(const std::string &path)
{
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string step_group_name(const int step)
{
  std::ostringstream s;
  s << std::setw(6) << std::setfill('0') << step;
  return s.str();
}

/// Silences the HDF5 error stack printout while it lives (for calls whose failure
/// becomes a Kiln error message instead).
class QuietHdf5Errors
{
public:
  QuietHdf5Errors()
  {
    H5Eget_auto2(H5E_DEFAULT, &old_func_, &old_data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5Errors() { H5Eset_auto2(H5E_DEFAULT, old_func_, old_data_); }
  QuietHdf5Errors(const QuietHdf5Errors &) = delete;
  QuietHdf5Errors &operator=(const QuietHdf5Errors &) = delete;

private:
  H5E_auto2_t old_func_ = nullptr;
  void *old_data_ = nullptr;
};

enum class Center
{
  node,
  cell
};

struct FieldRecord
{
  std::string name;
  Center center = Center::node;
  int n_components = 1;
};

struct StepRecord
{
  double time = 0.0;
  int cycle = 0;
  double dt = 0.0;
  std::vector<FieldRecord> fields;
};
} // namespace internal

struct Hdf5XdmfWriter::Impl
{
  using H5Handle = internal::H5Handle;

  MPI_Comm comm = MPI_COMM_NULL;
  int rank = 0;
  std::string h5_path;
  std::string xmf_path;
  std::string h5_name; ///< h5_path relative to the .xmf file's folder
  int n_nodes = 0;
  int n_cells = 0;
  std::vector<internal::RowRun> node_runs;
  std::vector<internal::RowRun> cell_runs;
  std::size_t n_owned_nodes = 0;
  std::size_t n_owned_cells = 0;
  std::vector<internal::StepRecord> steps;
  bool in_step = false;

  // Declared in the order they are opened: destroyed (closed) in reverse.
  H5Handle fapl;
  H5Handle dxpl;
  H5Handle file;
  H5Handle step_group;

  void create_file();
  void check_io(bool local_ok, const std::string &what) const;
  void write_rows(hid_t location, const std::string &name, hid_t file_type, hid_t memory_type,
                  const void *data, bool node_rows, int n_components) const;
  void write_field(const std::string &name, internal::Center center, int n_components,
                   const std::vector<double> &values);
  void write_mesh(const Mesh &mesh, const std::vector<int> &owned_nodes,
                  const std::vector<int> &owned_cells, const std::vector<int> &cell_rank) const;
  void write_step_attributes(const internal::StepRecord &step) const;
  std::string xdmf_text() const;
  void write_xdmf() const;
};

void Hdf5XdmfWriter::Impl::check_io(const bool local_ok, const std::string &what) const
{
  const Teuchos::MpiComm<int> teuchos_comm(comm);
  check_collectively(teuchos_comm, local_ok, h5_path,
                     what + " failed; check that the disk is not full and that the file is not "
                            "removed or opened by another program while Kiln runs");
}

void Hdf5XdmfWriter::Impl::create_file()
{
  fapl = H5Handle(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_fapl_mpio(fapl.get(), comm, MPI_INFO_NULL);
  // Metadata (groups, attributes, dataset headers) is written collectively too.
  H5Pset_all_coll_metadata_ops(fapl.get(), true);
  H5Pset_coll_metadata_write(fapl.get(), true);
  dxpl = H5Handle(H5Pcreate(H5P_DATASET_XFER), H5Pclose);
  H5Pset_dxpl_mpio(dxpl.get(), H5FD_MPIO_COLLECTIVE);

  {
    const internal::QuietHdf5Errors quiet;
    file = H5Handle(H5Fcreate(h5_path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose);
  }
  const Teuchos::MpiComm<int> teuchos_comm(comm);
  check_collectively(teuchos_comm, file.valid(), h5_path,
                     "cannot create the results file; check that the folder \"" +
                         internal::directory_of(h5_path) +
                         "\" exists and is writable, or choose another output path");
}

/// Writes a dataset of (rows) or (rows x n_components) values, rows = nodes or cells, from
/// this rank's owned rows, collectively. `data` holds n_components values per owned row.
void Hdf5XdmfWriter::Impl::write_rows(const hid_t location, const std::string &name,
                                      const hid_t file_type, const hid_t memory_type,
                                      const void *data, const bool node_rows,
                                      const int n_components) const
{
  const auto &runs = node_rows ? node_runs : cell_runs;
  const std::size_t n_owned = node_rows ? n_owned_nodes : n_owned_cells;
  const hsize_t n_rows = static_cast<hsize_t>(node_rows ? n_nodes : n_cells);
  const hsize_t n_cols = static_cast<hsize_t>(n_components);
  const int rank_of_data = n_components == 1 ? 1 : 2;
  const hsize_t dims[2] = {n_rows, n_cols};

  const H5Handle file_space(H5Screate_simple(rank_of_data, dims, nullptr), H5Sclose);
  const H5Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_fill_time(dcpl.get(), H5D_FILL_TIME_NEVER); // every row is written below
  const H5Handle dataset(H5Dcreate2(location, name.c_str(), file_type, file_space.get(),
                                    H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                         H5Dclose);
  check_io(dataset.valid(), "creating dataset \"" + name + "\"");

  // This rank's rows: the union of its runs of consecutive rows, or nothing.
  if (runs.empty())
    H5Sselect_none(file_space.get());
  for (std::size_t r = 0; r < runs.size(); ++r)
  {
    const hsize_t start[2] = {runs[r].first, 0};
    const hsize_t count[2] = {runs[r].count, n_cols};
    H5Sselect_hyperslab(file_space.get(), r == 0 ? H5S_SELECT_SET : H5S_SELECT_OR, start, nullptr,
                        count, nullptr);
  }
  // Memory: the owned values in a row, or a 1-value space with nothing selected.
  const hsize_t n_values = n_owned * n_cols;
  const hsize_t memory_dims[1] = {n_values > 0 ? n_values : 1};
  const H5Handle memory_space(H5Screate_simple(1, memory_dims, nullptr), H5Sclose);
  if (n_values == 0)
    H5Sselect_none(memory_space.get());
  const double dummy = 0.0;
  const herr_t status = H5Dwrite(dataset.get(), memory_type, memory_space.get(), file_space.get(),
                                 dxpl.get(), n_values > 0 ? data : &dummy);
  check_io(status >= 0, "writing dataset \"" + name + "\"");
}

void Hdf5XdmfWriter::Impl::write_mesh(const Mesh &mesh, const std::vector<int> &owned_nodes,
                                      const std::vector<int> &owned_cells,
                                      const std::vector<int> &cell_rank) const
{
  const H5Handle group(H5Gcreate2(file.get(), "mesh", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                       H5Gclose);
  check_io(group.valid(), "creating group /mesh");

  std::vector<double> coordinates;
  coordinates.reserve(3 * owned_nodes.size());
  for (const int n : owned_nodes)
    coordinates.insert(coordinates.end(), mesh.coordinates[n].begin(), mesh.coordinates[n].end());
  write_rows(group.get(), "coordinates", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, coordinates.data(),
             true, 3);

  std::vector<std::int64_t> connectivity;
  std::vector<std::int32_t> block_id;
  std::vector<std::int32_t> owner;
  connectivity.reserve(n_hex_nodes * owned_cells.size());
  for (const int c : owned_cells)
  {
    connectivity.insert(connectivity.end(), mesh.connectivity[c].begin(),
                        mesh.connectivity[c].end());
    block_id.push_back(mesh.block_id[c]);
    owner.push_back(cell_rank[c]);
  }
  write_rows(group.get(), "connectivity", H5T_STD_I64LE, H5T_NATIVE_INT64, connectivity.data(),
             false, n_hex_nodes);
  write_rows(group.get(), "block_id", H5T_STD_I32LE, H5T_NATIVE_INT32, block_id.data(), false, 1);
  write_rows(group.get(), "cell_rank", H5T_STD_I32LE, H5T_NATIVE_INT32, owner.data(), false, 1);

  const H5Handle steps_group(H5Gcreate2(file.get(), "steps", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                             H5Gclose);
  check_io(steps_group.valid(), "creating group /steps");
}

void Hdf5XdmfWriter::Impl::write_step_attributes(const internal::StepRecord &step) const
{
  const H5Handle scalar(H5Screate(H5S_SCALAR), H5Sclose);
  bool ok = true;
  const auto write_attribute =
      [&](const char *name, const hid_t file_type, const hid_t mem_type, const void *value)
  {
    const H5Handle attribute(
        H5Acreate2(step_group.get(), name, file_type, scalar.get(), H5P_DEFAULT, H5P_DEFAULT),
        H5Aclose);
    ok = ok && attribute.valid() && H5Awrite(attribute.get(), mem_type, value) >= 0;
  };
  const std::int32_t cycle = step.cycle;
  write_attribute("time", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &step.time);
  write_attribute("dt", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &step.dt);
  write_attribute("cycle", H5T_STD_I32LE, H5T_NATIVE_INT32, &cycle);
  check_io(ok, "writing the attributes of step " +
                   internal::step_group_name(static_cast<int>(steps.size()) - 1));
}

void Hdf5XdmfWriter::Impl::write_field(const std::string &name, const internal::Center center,
                                       const int n_components, const std::vector<double> &values)
{
  const char *kind = center == internal::Center::node ? "node" : "cell";
  if (!in_step)
    internal::throw_internal_error(__FILE__, __LINE__, "in_step",
                                   std::string("write_") + kind + "_field(\"" + name +
                                       "\") called outside begin_step()/end_step()");
  KILN_CHECK_INPUT(internal::is_valid_field_name(name), h5_path,
                   "field name \"" << name
                                   << "\" is not valid: use letters, digits, '_', '-' and '.'");
  KILN_CHECK_INPUT(n_components >= 1, h5_path,
                   "field \"" << name << "\" has " << n_components << " components; need >= 1");
  for (const auto &f : steps.back().fields)
    KILN_CHECK_INPUT(f.name != name, h5_path,
                     "field \"" << name << "\" is written twice in step "
                                << internal::step_group_name(static_cast<int>(steps.size()) - 1));
  const std::size_t n_owned = center == internal::Center::node ? n_owned_nodes : n_owned_cells;
  std::ostringstream message;
  message << kind << " field \"" << name << "\" has " << values.size()
          << " values on some rank, expected " << n_components << " per owned " << kind;
  internal::check_internal_collectively(
      comm, values.size() == n_owned * static_cast<std::size_t>(n_components),
      "values.size() == n_owned * n_components", message.str());

  write_rows(step_group.get(), name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.data(),
             center == internal::Center::node, n_components);
  steps.back().fields.push_back({name, center, n_components});
}

namespace internal
{
void write_data_item(std::ostream &out, const std::string &indent, const std::string &h5_name,
                     const std::string &path, const std::string &dimensions,
                     const char *number_type, const int precision)
{
  out << indent << "<DataItem Dimensions=\"" << dimensions << "\" NumberType=\"" << number_type
      << "\" Precision=\"" << precision << "\" Format=\"HDF\">" << h5_name << ":" << path
      << "</DataItem>\n";
}

/// One Uniform grid: the mesh, the mesh attributes and, for a step, its fields.
void write_grid(std::ostream &out, const std::string &indent, const std::string &h5_name,
                const int n_nodes, const int n_cells, const StepRecord *step, const int index)
{
  const std::string in1 = indent + "  ";
  const std::string in2 = in1 + "  ";
  const std::string nodes = std::to_string(n_nodes);
  const std::string cells = std::to_string(n_cells);
  out << indent << "<Grid Name=\"" << (step ? "step_" + step_group_name(index) : "mesh")
      << "\" GridType=\"Uniform\">\n";
  if (step)
    out << in1 << "<Time Value=\"" << std::setprecision(17) << step->time << "\"/>\n";
  out << in1 << "<Topology TopologyType=\"Hexahedron\" NumberOfElements=\"" << cells
      << "\" NodesPerElement=\"8\">\n";
  write_data_item(out, in2, h5_name, "/mesh/connectivity", cells + " 8", "Int", 8);
  out << in1 << "</Topology>\n";
  out << in1 << "<Geometry GeometryType=\"XYZ\">\n";
  write_data_item(out, in2, h5_name, "/mesh/coordinates", nodes + " 3", "Float", 8);
  out << in1 << "</Geometry>\n";
  for (const char *name : {"block_id", "cell_rank"})
  {
    out << in1 << "<Attribute Name=\"" << name << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n";
    write_data_item(out, in2, h5_name, std::string("/mesh/") + name, cells, "Int", 4);
    out << in1 << "</Attribute>\n";
  }
  if (step)
    for (const auto &f : step->fields)
    {
      const bool on_nodes = f.center == Center::node;
      const char *type = f.n_components == 1 ? "Scalar" : f.n_components == 3 ? "Vector" : "Matrix";
      std::string dimensions = on_nodes ? nodes : cells;
      if (f.n_components > 1)
        dimensions += " " + std::to_string(f.n_components);
      out << in1 << "<Attribute Name=\"" << f.name << "\" AttributeType=\"" << type
          << "\" Center=\"" << (on_nodes ? "Node" : "Cell") << "\">\n";
      write_data_item(out, in2, h5_name, "/steps/" + step_group_name(index) + "/" + f.name,
                      dimensions, "Float", 8);
      out << in1 << "</Attribute>\n";
    }
  out << indent << "</Grid>\n";
}
} // namespace internal

/// Before the first step: one Uniform grid with the mesh (a valid file ParaView opens).
/// After: a Temporal collection with one Uniform grid per step.
std::string Hdf5XdmfWriter::Impl::xdmf_text() const
{
  std::ostringstream out;
  out << "<?xml version=\"1.0\" ?>\n"
      << "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
      << "  <Domain>\n";
  if (steps.empty())
    internal::write_grid(out, "    ", h5_name, n_nodes, n_cells, nullptr, 0);
  else
  {
    out << "    <Grid Name=\"results\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (std::size_t s = 0; s < steps.size(); ++s)
      internal::write_grid(out, "      ", h5_name, n_nodes, n_cells, &steps[s],
                           static_cast<int>(s));
    out << "    </Grid>\n";
  }
  out << "  </Domain>\n"
      << "</Xdmf>\n";
  return out.str();
}

/// Rank 0 writes the whole file under a temporary name and renames it, so a reader
/// never sees a half-written file.
void Hdf5XdmfWriter::Impl::write_xdmf() const
{
  bool ok = true;
  if (rank == 0)
  {
    const std::string temporary = xmf_path + ".tmp";
    {
      std::ofstream out(temporary, std::ios::trunc);
      out << xdmf_text();
      out.close();
      ok = static_cast<bool>(out);
    }
    ok = ok && std::rename(temporary.c_str(), xmf_path.c_str()) == 0;
    if (!ok)
      std::remove(temporary.c_str());
  }
  const Teuchos::MpiComm<int> teuchos_comm(comm);
  check_collectively(teuchos_comm, ok, xmf_path,
                     "cannot write the XDMF file; check that its folder is writable and the "
                     "disk is not full");
}

Hdf5XdmfWriter::Hdf5XdmfWriter(const MPI_Comm comm, const std::string &base_path, const Mesh &mesh,
                               const std::vector<int> &owned_nodes,
                               const std::vector<int> &owned_cells,
                               const std::vector<int> &cell_rank)
    : impl_(std::make_unique<Impl>())
{
  Impl &m = *impl_;
  m.comm = comm;
  MPI_Comm_rank(comm, &m.rank);
  m.h5_path = base_path + ".h5";
  m.xmf_path = base_path + ".xmf";
  m.h5_name = internal::file_name_of(m.h5_path);
  m.n_nodes = mesh.n_nodes();
  m.n_cells = mesh.n_cells();

  // The ownership must be a partition of the rows; a mistake here is the caller's.
  const auto is_sorted_in_range = [](const std::vector<int> &rows, const int n)
  {
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (rows[i] < 0 || rows[i] >= n || (i > 0 && rows[i] <= rows[i - 1]))
        return false;
    return true;
  };
  long long counts[2] = {static_cast<long long>(owned_nodes.size()),
                         static_cast<long long>(owned_cells.size())};
  MPI_Allreduce(MPI_IN_PLACE, counts, 2, MPI_LONG_LONG, MPI_SUM, comm);
  internal::check_internal_collectively(
      comm,
      is_sorted_in_range(owned_nodes, m.n_nodes) && is_sorted_in_range(owned_cells, m.n_cells) &&
          counts[0] == m.n_nodes && counts[1] == m.n_cells &&
          cell_rank.size() == static_cast<std::size_t>(m.n_cells) &&
          mesh.block_id.size() == static_cast<std::size_t>(m.n_cells),
      "owned rows form a partition",
      "owned_nodes/owned_cells must be increasing, in range and own every row once; "
      "cell_rank and block_id need one entry per cell");

  m.node_runs = internal::contiguous_runs(owned_nodes);
  m.cell_runs = internal::contiguous_runs(owned_cells);
  m.n_owned_nodes = owned_nodes.size();
  m.n_owned_cells = owned_cells.size();

  m.create_file();
  m.write_mesh(mesh, owned_nodes, owned_cells, cell_rank);
  m.check_io(H5Fflush(m.file.get(), H5F_SCOPE_GLOBAL) >= 0, "flushing the file");
  m.write_xdmf();
}

Hdf5XdmfWriter::~Hdf5XdmfWriter() = default;

void Hdf5XdmfWriter::begin_step(const double time, const int cycle, const double dt)
{
  Impl &m = *impl_;
  if (m.in_step)
    internal::throw_internal_error(__FILE__, __LINE__, "!in_step",
                                   "begin_step() called twice without end_step()");
  const std::string name = "steps/" + internal::step_group_name(static_cast<int>(m.steps.size()));
  m.step_group = internal::H5Handle(
      H5Gcreate2(m.file.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  m.check_io(m.step_group.valid(), "creating group /" + name);
  m.steps.push_back({time, cycle, dt, {}});
  m.in_step = true;
  m.write_step_attributes(m.steps.back());
}

void Hdf5XdmfWriter::write_node_field(const std::string &name, const int n_components,
                                      const std::vector<double> &values)
{
  impl_->write_field(name, internal::Center::node, n_components, values);
}

void Hdf5XdmfWriter::write_cell_field(const std::string &name, const int n_components,
                                      const std::vector<double> &values)
{
  impl_->write_field(name, internal::Center::cell, n_components, values);
}

void Hdf5XdmfWriter::end_step()
{
  Impl &m = *impl_;
  if (!m.in_step)
    internal::throw_internal_error(__FILE__, __LINE__, "in_step",
                                   "end_step() called without begin_step()");
  m.step_group.reset();
  m.in_step = false;
  m.check_io(H5Fflush(m.file.get(), H5F_SCOPE_GLOBAL) >= 0, "flushing the file");
  m.write_xdmf();
}

std::string Hdf5XdmfWriter::h5_path() const
{
  return impl_->h5_path;
}

std::string Hdf5XdmfWriter::xdmf_path() const
{
  return impl_->xmf_path;
}
} // namespace kiln
