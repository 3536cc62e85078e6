#include "io/checkpoint.hpp"

#include "base/errors.hpp"
#include "base/hash.hpp"
#include "io/hdf5_errors.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <Tpetra_Import.hpp>
#include <hdf5.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace kiln
{
namespace internal
{
/// An HDF5 handle closed by `close` at the end of its scope; invalid (< 0) handles raise
/// the error `what`.
class H5
{
public:
  H5(const hid_t id, herr_t (*closer)(hid_t), const std::string &what) : id_(id), close_(closer)
  {
    if (id < 0)
      throw std::runtime_error(what + in_parentheses(hdf5_failure_reason()));
  }
  ~H5()
  {
    if (id_ >= 0)
      close_(id_);
  }
  /// Closes the object now; an error (`what` failed) if that fails.
  void close(const std::string &what)
  {
    const hid_t id = id_;
    id_ = -1;
    if (close_(id) < 0)
      throw std::runtime_error(what + in_parentheses(hdf5_failure_reason()));
  }
  H5(const H5 &) = delete;
  H5 &operator=(const H5 &) = delete;
  operator hid_t() const { return id_; }

private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void check(const herr_t status, const std::string &what)
{
  if (status < 0)
    throw std::runtime_error(what + in_parentheses(hdf5_failure_reason()));
}

void write_attribute(const hid_t object, const std::string &name, const double value)
{
  const H5 space(H5Screate(H5S_SCALAR), H5Sclose, "dataspace");
  const H5 a(H5Acreate2(object, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT),
             H5Aclose, "attribute " + name);
  check(H5Awrite(a, H5T_NATIVE_DOUBLE, &value), "attribute " + name);
}

void write_attribute(const hid_t object, const std::string &name, const int value)
{
  const H5 space(H5Screate(H5S_SCALAR), H5Sclose, "dataspace");
  const H5 a(H5Acreate2(object, name.c_str(), H5T_STD_I32LE, space, H5P_DEFAULT, H5P_DEFAULT),
             H5Aclose, "attribute " + name);
  check(H5Awrite(a, H5T_NATIVE_INT, &value), "attribute " + name);
}

/// A fixed-length string type of `size` characters (at least 1).
hid_t string_type(const std::size_t size)
{
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, std::max<std::size_t>(size, 1));
  return type;
}

void write_attribute(const hid_t object, const std::string &name, const std::string &value)
{
  const H5 type(string_type(value.size()), H5Tclose, "string type");
  const H5 space(H5Screate(H5S_SCALAR), H5Sclose, "dataspace");
  const H5 a(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
             "attribute " + name);
  check(H5Awrite(a, type, value.empty() ? "" : value.data()), "attribute " + name);
}

void write_string(const hid_t group, const std::string &name, const std::string &value)
{
  const H5 type(string_type(value.size()), H5Tclose, "string type");
  const H5 space(H5Screate(H5S_SCALAR), H5Sclose, "dataspace");
  const H5 d(H5Dcreate2(group, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
             H5Dclose, "dataset " + name);
  check(H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, value.empty() ? "" : value.data()),
        "dataset " + name);
}

template <typename T>
void write_array(const hid_t group, const std::string &name, const std::vector<T> &values,
                 const hsize_t columns)
{
  const hsize_t dims[2] = {values.size() / columns, columns};
  const H5 space(H5Screate_simple(columns > 1 ? 2 : 1, dims, nullptr), H5Sclose, "dataspace");
  const hid_t file_type = std::is_same_v<T, double> ? H5T_IEEE_F64LE : H5T_STD_I32LE;
  const hid_t memory_type = std::is_same_v<T, double> ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT;
  // A Fletcher32 checksum of the data (read_checkpoint refuses a flipped bit); the filter needs
  // a chunked layout: one chunk of at most 2^20 rows.
  const H5 dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "dataset properties");
  if (!values.empty())
  {
    const hsize_t chunk[2] = {std::min<hsize_t>(dims[0], hsize_t{1} << 20), columns};
    check(H5Pset_chunk(dcpl, columns > 1 ? 2 : 1, chunk), "chunking dataset " + name);
    check(H5Pset_fletcher32(dcpl), "checksum of dataset " + name);
  }
  const H5 d(H5Dcreate2(group, name.c_str(), file_type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
             H5Dclose, "dataset " + name);
  check(H5Dwrite(d, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "dataset " + name);
}

template <typename T> T read_attribute(const hid_t object, const std::string &name)
{
  const H5 a(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose, "attribute " + name);
  T value{};
  check(H5Aread(a, std::is_same_v<T, double> ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT, &value),
        "attribute " + name);
  return value;
}

std::string read_string(const hid_t object, const std::string &name, const bool attribute)
{
  const std::string what = (attribute ? "attribute " : "dataset ") + name;
  const H5 item(attribute ? H5Aopen(object, name.c_str(), H5P_DEFAULT)
                          : H5Dopen2(object, name.c_str(), H5P_DEFAULT),
                attribute ? H5Aclose : H5Dclose, what);
  const H5 type(attribute ? H5Aget_type(item) : H5Dget_type(item), H5Tclose, what);
  if (H5Tget_class(type) != H5T_STRING)
    throw std::runtime_error(what + " is not a string");
  std::string value(H5Tget_size(type), '\0');
  check(attribute ? H5Aread(item, type, value.data())
                  : H5Dread(item, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, value.data()),
        what);
  value.resize(value.find('\0') == std::string::npos ? value.size() : value.find('\0'));
  return value;
}

template <typename T>
std::vector<T> read_array(const hid_t group, const std::string &name, const std::size_t size)
{
  const H5 d(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "dataset " + name);
  const H5 space(H5Dget_space(d), H5Sclose, "dataset " + name);
  if (static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)) != size)
    throw std::runtime_error("dataset " + name + " has " +
                             std::to_string(H5Sget_simple_extent_npoints(space)) +
                             " values where " + std::to_string(size) + " are expected");
  std::vector<T> values(size);
  check(H5Dread(d, std::is_same_v<T, double> ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT, H5S_ALL, H5S_ALL,
                H5P_DEFAULT, values.data()),
        "dataset " + name);
  return values;
}

/// The values of each of `vectors` (all on one map) on rank 0, in global-id order (empty
/// elsewhere). One Import serves them all: making it looks up every id in Tpetra's directory,
/// which costs more than moving the values.
std::vector<std::vector<double>> gather(const std::vector<const Tpetra::Vector<> *> &vectors)
{
  const auto map = vectors.front()->getMap();
  const auto n = map->getGlobalNumElements();
  const bool root = map->getComm()->getRank() == 0;
  const auto root_map = Teuchos::rcp(new Map(n, root ? n : 0, 0, map->getComm()));
  const Tpetra::Import<> import(map, root_map);
  Tpetra::Vector<> on_root(root_map);
  std::vector<std::vector<double>> gathered;
  for (const Tpetra::Vector<> *x : vectors)
  {
    on_root.doImport(*x, import, Tpetra::INSERT);
    const auto values = on_root.getData();
    gathered.emplace_back(values.begin(), values.end());
  }
  return gathered;
}

/// Every rank's `record` (all of one length) on rank 0, rank by rank; empty if the lengths
/// differ or are 0. Collective.
std::vector<double> gather_records(const std::vector<double> &record,
                                   const Teuchos::Comm<int> &comm, int &length)
{
  const int here = static_cast<int>(record.size());
  int shortest = 0, longest = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, here, Teuchos::outArg(shortest));
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, here, Teuchos::outArg(longest));
  length = shortest == longest ? longest : 0;
  if (length == 0)
    return {};
  std::vector<double> all(comm.getRank() == 0 ? static_cast<std::size_t>(length * comm.getSize())
                                              : 0);
  Teuchos::gather(record.data(), length, all.data(), length, 0, comm);
  return all;
}

/// Row `row` of the two-dimensional dataset `name`, or empty if it has not `rows` rows.
std::vector<double> read_row(const hid_t group, const std::string &name, const int rows,
                             const int row)
{
  const H5 d(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "dataset " + name);
  const H5 space(H5Dget_space(d), H5Sclose, "dataset " + name);
  hsize_t dims[2] = {0, 0};
  if (H5Sget_simple_extent_ndims(space) != 2 ||
      H5Sget_simple_extent_dims(space, dims, nullptr) != 2 || dims[0] != static_cast<hsize_t>(rows))
    return {};
  std::vector<double> all(dims[0] * dims[1]);
  check(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, all.data()),
        "dataset " + name);
  return std::vector<double>(all.begin() + static_cast<std::ptrdiff_t>(row * dims[1]),
                             all.begin() + static_cast<std::ptrdiff_t>((row + 1) * dims[1]));
}

/// Whether every value of `vectors` is a finite number.
bool all_finite(const std::vector<const std::vector<double> *> &vectors)
{
  for (const auto *v : vectors)
    for (const double value : *v)
      if (!std::isfinite(value))
        return false;
  return true;
}

/// Writes `bytes` to `path` and makes them durable (fsync): an error naming the system's
/// reason (e.g. "No space left on device", "File too large") if any of it fails.
void write_file(const std::string &path, const std::vector<char> &bytes)
{
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0)
    throw std::runtime_error(std::string("cannot create the file (") + std::strerror(errno) + ")");
  std::size_t written = 0;
  int error_number = 0;
  while (written < bytes.size() && error_number == 0)
  {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno != EINTR)
      error_number = errno;
    else if (n > 0)
      written += static_cast<std::size_t>(n);
  }
  if (error_number == 0 && ::fsync(fd) != 0)
    error_number = errno;
  if (::close(fd) != 0 && error_number == 0)
    error_number = errno;
  if (error_number != 0)
    throw std::runtime_error(std::string("writing the file failed (") +
                             std::strerror(error_number) + ")");
}

/// The largest time or step a checkpoint may hold [s]: 10^15 s, 30 million years.
constexpr double largest_time = 1e15;

/// An error naming the first scalar of `state` (or `output_steps`) out of its range: times and
/// steps finite and in [0, largest_time], counts >= 0.
void check_ranges(const TimeStepper::State &state, const int output_steps)
{
  const std::pair<const char *, double> times[] = {{"time", state.time},
                                                   {"next_step", state.next_step},
                                                   {"last_step", state.last_step},
                                                   {"step_before", state.step_before}};
  for (const auto &[name, value] : times)
    if (!std::isfinite(value) || value < 0.0 || value > largest_time)
    {
      std::ostringstream m;
      m << "its attribute state/" << name << " = " << value
        << " is out of range (a finite number in [0, " << largest_time
        << "] s is expected): a damaged checkpoint";
      throw std::runtime_error(m.str());
    }
  const TimeStepper::Statistics &t = state.statistics;
  const std::pair<const char *, int> counts[] = {{"accepted", state.accepted},
                                                 {"attempts", state.attempts},
                                                 {"steps", t.steps},
                                                 {"error_rejections", t.error_rejections},
                                                 {"newton_failures", t.newton_failures},
                                                 {"newton_iterations", t.newton_iterations},
                                                 {"linear_iterations", t.linear_iterations},
                                                 {"output_steps", output_steps}};
  for (const auto &[name, value] : counts)
    if (value < 0)
      throw std::runtime_error("its attribute state/" + std::string(name) + " = " +
                               std::to_string(value) +
                               " is negative (a count >= 0 is expected): a damaged checkpoint");
}

/// Reads the checkpoint just written at `path` back (every checksum of its state checked) and
/// compares it with what was written: an error if anything differs. `components`: the state
/// at quadrature points, by name (none: the checkpoint has none).
void verify_checkpoint(
    const std::string &path, const double time,
    const std::vector<const std::vector<double> *> &states,
    const std::vector<std::pair<std::string, const std::vector<double> *>> &components)
{
  const H5 file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                "reading the file back failed");
  if (!components.empty())
  {
    const H5 values(H5Gopen2(file, "quadrature_state/components", H5P_DEFAULT), H5Gclose,
                    "reading group quadrature_state/components back");
    for (const auto &[name, written] : components)
    {
      const std::vector<double> read = read_array<double>(values, name, written->size());
      if (!read.empty() &&
          std::memcmp(read.data(), written->data(), read.size() * sizeof(double)) != 0)
        throw std::runtime_error("dataset quadrature_state/components/" + name +
                                 " read back differs from what was written");
    }
  }
  const H5 s(H5Gopen2(file, "state", H5P_DEFAULT), H5Gclose, "reading group state back");
  const char *const names[] = {"x", "x_1", "x_2"};
  for (std::size_t v = 0; v < states.size(); ++v)
  {
    const std::vector<double> read = read_array<double>(s, names[v], states[v]->size());
    if (!read.empty() &&
        std::memcmp(read.data(), states[v]->data(), read.size() * sizeof(double)) != 0)
      throw std::runtime_error(std::string("dataset state/") + names[v] +
                               " read back differs from what was written");
  }
  const double read_time = read_attribute<double>(s, "time");
  if (std::memcmp(&read_time, &time, sizeof time) != 0)
    throw std::runtime_error("attribute state/time read back differs from what was written");
}

const char *const physics_blocks[] = {"Mesh", "Material", "Materials", "Thermal", "Mechanics"};

/// The number of points of every cell of the mesh (`n_cells`), from every rank's owned ones,
/// on every rank. Collective.
std::vector<int> points_per_cell(const QuadratureState &qs, const int n_cells,
                                 const Teuchos::Comm<int> &comm)
{
  std::vector<int> local(static_cast<std::size_t>(n_cells), 0), global(local.size(), 0);
  for (int c = 0; c < qs.n_cells(); ++c)
    local[static_cast<std::size_t>(qs.cells()[c])] = qs.n_points(c);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, n_cells, local.data(), global.data());
  return global;
}

/// The first point of each cell in global cell order, and the number of all (the last entry).
std::vector<GO> point_offsets(const std::vector<int> &points)
{
  std::vector<GO> offsets(points.size() + 1, 0);
  for (std::size_t c = 0; c < points.size(); ++c)
    offsets[c + 1] = offsets[c] + points[c];
  return offsets;
}

/// Component by component, the committed state of every point on rank 0, in global cell and
/// point order (empty elsewhere). Collective.
std::vector<std::vector<double>>
gather_quadrature_state(const QuadratureState &qs, const std::vector<int> &points,
                        const Teuchos::RCP<const Teuchos::Comm<int>> &comm)
{
  const std::vector<GO> offsets = point_offsets(points);
  std::vector<GO> gids;
  gids.reserve(static_cast<std::size_t>(qs.n_points()));
  for (int c = 0; c < qs.n_cells(); ++c)
    for (int q = 0; q < qs.n_points(c); ++q)
      gids.push_back(offsets[static_cast<std::size_t>(qs.cells()[c])] + q);
  const auto map = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(offsets.back()),
                                        Teuchos::ArrayView<const GO>(gids), 0, comm));
  std::vector<Tpetra::Vector<>> components;
  std::vector<const Tpetra::Vector<> *> pointers;
  components.reserve(static_cast<std::size_t>(qs.n_state()));
  for (int k = 0; k < qs.n_state(); ++k)
  {
    components.emplace_back(map);
    const std::vector<double> values = qs.old_component(k);
    auto target = components.back().getDataNonConst();
    std::copy(values.begin(), values.end(), target.begin());
  }
  for (const auto &component : components)
    pointers.push_back(&component);
  return gather(pointers);
}

/// What a checkpoint holds of the state at quadrature points (read_checkpoint).
struct SavedQuadratureState
{
  bool present = false;
  std::vector<std::string> names;
  std::vector<int> points; ///< per cell, global order
  std::vector<std::vector<double>> components;
};

/// The group quadrature_state of `file`, if any (a mesh of `n_cells` cells); an error if it is
/// damaged.
SavedQuadratureState read_saved_quadrature_state(const hid_t file, const int n_cells)
{
  SavedQuadratureState saved;
  if (H5Lexists(file, "quadrature_state", H5P_DEFAULT) <= 0)
    return saved;
  saved.present = true;
  const H5 group(H5Gopen2(file, "quadrature_state", H5P_DEFAULT), H5Gclose,
                 "group quadrature_state");
  const int n = read_attribute<int>(group, "n_components");
  if (n < 1 || n > 10000)
    throw std::runtime_error("its attribute quadrature_state/n_components = " + std::to_string(n) +
                             " is out of range: a damaged checkpoint");
  saved.points = read_array<int>(group, "points_per_cell", static_cast<std::size_t>(n_cells));
  std::size_t total = 0;
  for (const int p : saved.points)
  {
    if (p < 0)
      throw std::runtime_error("its dataset quadrature_state/points_per_cell holds a negative "
                               "count: a damaged checkpoint");
    total += static_cast<std::size_t>(p);
  }
  const H5 components(H5Gopen2(group, "components", H5P_DEFAULT), H5Gclose,
                      "group quadrature_state/components");
  for (int k = 0; k < n; ++k)
  {
    saved.names.push_back(read_string(group, "component_" + std::to_string(k), true));
    saved.components.push_back(read_array<double>(components, saved.names.back(), total));
    if (!all_finite({&saved.components.back()}))
      throw std::runtime_error("its state at quadrature points (quadrature_state/components/" +
                               saved.names.back() +
                               ") holds values that are not finite numbers (NaN or Inf): a "
                               "damaged checkpoint");
  }
  return saved;
}

/// The names of `names` that `others` lacks, joined ("a, b"), or "".
std::string missing_from(const std::vector<std::string> &names,
                         const std::vector<std::string> &others)
{
  std::string missing;
  for (const std::string &name : names)
    if (std::find(others.begin(), others.end(), name) == others.end())
      missing += (missing.empty() ? "" : ", ") + name;
  return missing;
}

/// `saved` (read from `path`, written by Kiln `version`) into `qs` (null: the run has no state),
/// checked against it: InputErrors on every rank naming `path`. Collective.
void restore_quadrature_state(const std::string &path, const std::string &version,
                              const SavedQuadratureState &saved, QuadratureState *qs,
                              const Teuchos::Comm<int> &comm)
{
  const std::vector<std::string> none;
  const std::vector<std::string> &names = qs != nullptr ? qs->names() : none;
  const std::string start_anew = "; continue it with the Kiln that wrote it (" + version +
                                 "), or start this run anew (without --restart)";
  check_collectively(comm, saved.present || qs == nullptr, path,
                     "the checkpoint holds no state at the quadrature points, which this run's "
                     "constitutive models need (components " +
                         missing_from(names, {}) +
                         "): it was written by a run whose models kept none" + start_anew);
  check_collectively(comm, !saved.present || qs != nullptr, path,
                     "the checkpoint holds state at the quadrature points (components " +
                         missing_from(saved.names, {}) +
                         ") that this run's constitutive models do not declare: the run would "
                         "not continue as the one that wrote it" +
                         start_anew);
  if (qs == nullptr)
    return;
  const std::string lacking = missing_from(names, saved.names);
  check_collectively(comm, lacking.empty(), path,
                     "the checkpoint's state at the quadrature points lacks the components " +
                         lacking + " that this run's constitutive models need" + start_anew);
  const std::string extra = missing_from(saved.names, names);
  check_collectively(comm, extra.empty(), path,
                     "the checkpoint's state at the quadrature points has the components " + extra +
                         " that this run's constitutive models do not declare" + start_anew);
  const std::vector<GO> offsets = point_offsets(saved.points);
  std::string differs;
  for (int c = 0; c < qs->n_cells() && differs.empty(); ++c)
  {
    const int g = qs->cells()[c];
    if (saved.points[static_cast<std::size_t>(g)] != qs->n_points(c))
      differs = "cell " + std::to_string(g) + " (from 0) has " +
                std::to_string(saved.points[static_cast<std::size_t>(g)]) +
                " quadrature points with state in the checkpoint and " +
                std::to_string(qs->n_points(c)) + " in this run: its element or its model differs" +
                start_anew;
  }
  check_collectively(comm, differs.empty(), path, differs);
  for (int k = 0; k < qs->n_state(); ++k)
  {
    const auto at = std::find(saved.names.begin(), saved.names.end(), qs->names()[k]);
    const std::vector<double> &all =
        saved.components[static_cast<std::size_t>(at - saved.names.begin())];
    std::vector<double> values;
    values.reserve(static_cast<std::size_t>(qs->n_points()));
    for (int c = 0; c < qs->n_cells(); ++c)
      for (int q = 0; q < qs->n_points(c); ++q)
        values.push_back(all[static_cast<std::size_t>(offsets[qs->cells()[c]] + q)]);
    qs->set_component(k, values);
  }
}
} // namespace internal

RunFingerprint RunFingerprint::of(const Mesh &mesh, const DofLayout &layout,
                                  const Teuchos::ParameterList &input)
{
  RunFingerprint f;
  f.n_nodes = mesh.n_nodes();
  f.n_cells = mesh.n_cells();
  f.n_pairs = static_cast<int>(mesh.gap_pairs.size());
  // The first gap's side set (0: none); the mesh's counts tell several gaps apart.
  f.gap_side_set = mesh.gap_side_sets.empty() ? 0 : mesh.gap_side_sets.front();
  std::vector<double> coordinates;
  for (const Point &x : mesh.coordinates)
    coordinates.insert(coordinates.end(), x.begin(), x.end());
  const std::vector<int> &cells = mesh.cell_node_ids;
  std::uint64_t hash = fnv1a(coordinates.data(), coordinates.size());
  hash = fnv1a(cells.data(), cells.size(), hash);
  hash = fnv1a(mesh.block_id.data(), mesh.block_id.size(), hash);
  std::ostringstream hex;
  hex << std::hex << std::setw(16) << std::setfill('0') << hash;
  f.mesh_hash = hex.str();
  f.layout = std::string(layout.temperature ? "temperature " : "") +
             (layout.displacement ? "displacement " : "") + (layout.contact ? "contact" : "");
  f.physics.emplace_back("Kiln/\"Physics\"", input.get<std::string>("Physics"));
  for (const char *block : internal::physics_blocks)
  {
    std::ostringstream xml;
    // A list the input lacks (a deck not read through validated()) counts as empty.
    Teuchos::writeParameterListToXmlOStream(
        input.isSublist(block) ? input.sublist(block) : Teuchos::ParameterList(block), xml);
    f.physics.emplace_back(std::string("Kiln/") + block, xml.str());
  }
  return f;
}

std::string RunFingerprint::difference(const RunFingerprint &saved) const
{
  std::ostringstream d;
  if (n_nodes != saved.n_nodes || n_cells != saved.n_cells || n_pairs != saved.n_pairs ||
      gap_side_set != saved.gap_side_set)
    d << "the mesh differs: the checkpoint's has " << saved.n_cells << " cells, " << saved.n_nodes
      << " nodes and " << saved.n_pairs << " gap pairs (gap side set " << saved.gap_side_set
      << "); this input's has " << n_cells << " cells, " << n_nodes << " nodes and " << n_pairs
      << " gap pairs (gap side set " << gap_side_set << ")";
  else if (mesh_hash != saved.mesh_hash)
    d << "the mesh differs: it has the checkpoint's sizes but other coordinates or cells "
         "(fingerprint "
      << mesh_hash << ", the checkpoint's " << saved.mesh_hash << ")";
  else if (layout != saved.layout)
    d << "the unknowns differ: the checkpoint has " << saved.layout << ", this input " << layout;
  else
    for (std::size_t i = 0; i < physics.size() && i < saved.physics.size(); ++i)
      if (physics[i] != saved.physics[i])
      {
        d << physics[i].first
          << " differs from the checkpoint's; a restart may change the time stepping, the "
             "solver, the output and the checkpoints, not the problem";
        break;
      }
  return d.str();
}

std::string RunFingerprint::digest() const
{
  std::ostringstream all;
  all << n_nodes << ' ' << n_cells << ' ' << n_pairs << ' ' << gap_side_set << ' ' << mesh_hash
      << ' ' << layout;
  for (const auto &[name, block] : physics)
    all << '\n' << name << '\n' << block;
  const std::string text = all.str();
  std::ostringstream hex;
  hex << std::hex << std::setw(16) << std::setfill('0') << fnv1a(text.data(), text.size());
  return hex.str();
}

void write_checkpoint(const std::string &path, const TimeStepper::State &state,
                      const CheckpointInfo &info, const RunFingerprint &fingerprint,
                      const Teuchos::Comm<int> &comm, const QuadratureState *quadrature_state)
{
  using namespace internal;
  // Gathered on rank 0 in global-id order (node-major: the file's rows are nodes).
  const std::vector<std::vector<double>> states =
      gather({state.x.get(), state.x_1.get(), state.x_2.get()});
  const std::vector<double> &x = states[0], &x_1 = states[1], &x_2 = states[2];
  const hsize_t F = static_cast<hsize_t>(state.x->getMap()->getGlobalNumElements()) /
                    static_cast<hsize_t>(fingerprint.n_nodes);
  int origin_length = 0;
  const std::vector<double> origins =
      gather_records(info.preconditioner_origin, comm, origin_length);
  // The state at quadrature points, likewise, per component.
  std::vector<int> points;
  std::vector<std::vector<double>> components;
  if (quadrature_state != nullptr)
  {
    points = points_per_cell(*quadrature_state, fingerprint.n_cells, comm);
    components = gather_quadrature_state(*quadrature_state, points, state.x->getMap()->getComm());
  }
  std::vector<const std::vector<double> *> all_values = {&x, &x_1, &x_2};
  for (const auto &component : components)
    all_values.push_back(&component);
  std::ostringstream time;
  time << state.time;
  check_run_collectively(
      comm, all_finite(all_values) && std::isfinite(state.time),
      path + ": the state at t = " + time.str() +
          " s holds values that are not finite numbers (NaN or Inf); it is not written as a "
          "checkpoint, and the checkpoints written before are kept");
  quiet_hdf5_errors();
  std::string error;
  if (comm.getRank() == 0)
  {
    const std::string tmp = path + ".tmp";
    try
    {
      // Built in memory (HDF5's core driver, no backing store) and written to disk by
      // write_file(): HDF5 itself never meets a full disk, whose failed close would leave the
      // file open in the library (and MPI_Finalize crashing in HDF5's clean-up).
      const H5 fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "file access properties");
      check(H5Pset_fapl_core(fapl, std::size_t{1} << 20, false), "the in-memory file");
      H5 file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl), H5Fclose,
              "cannot create the file");
      {
        write_attribute(file, "format", std::string("kiln checkpoint"));
        write_attribute(file, "format_version", checkpoint_format_version);
        write_attribute(file, "kiln_version", info.kiln_version);
        write_attribute(file, "created", info.created);
        write_attribute(file, "input_path", info.input_path);
        // As the results carry it: which run wrote the file, without reading the fingerprint.
        write_attribute(file, "run_fingerprint", fingerprint.digest());
        write_string(file, "input", info.input_xml);

        const H5 print(H5Gcreate2(file, "fingerprint", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                       H5Gclose, "group fingerprint");
        write_attribute(print, "n_nodes", fingerprint.n_nodes);
        write_attribute(print, "n_cells", fingerprint.n_cells);
        write_attribute(print, "n_pairs", fingerprint.n_pairs);
        write_attribute(print, "gap_side_set", fingerprint.gap_side_set);
        write_attribute(print, "mesh_hash", fingerprint.mesh_hash);
        write_attribute(print, "layout", fingerprint.layout);
        write_attribute(print, "n_physics", static_cast<int>(fingerprint.physics.size()));
        for (std::size_t i = 0; i < fingerprint.physics.size(); ++i)
        {
          write_attribute(print, "physics_name_" + std::to_string(i), fingerprint.physics[i].first);
          write_string(print, "physics_" + std::to_string(i), fingerprint.physics[i].second);
        }

        const H5 s(H5Gcreate2(file, "state", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                   "group state");
        write_attribute(s, "time", state.time);
        write_attribute(s, "next_step", state.next_step);
        write_attribute(s, "last_step", state.last_step);
        write_attribute(s, "step_before", state.step_before);
        write_attribute(s, "accepted", state.accepted);
        write_attribute(s, "attempts", state.attempts);
        write_attribute(s, "newton_failed", state.newton_failed ? 1 : 0);
        const TimeStepper::Statistics &stats = state.statistics;
        write_attribute(s, "steps", stats.steps);
        write_attribute(s, "error_rejections", stats.error_rejections);
        write_attribute(s, "newton_failures", stats.newton_failures);
        write_attribute(s, "newton_iterations", stats.newton_iterations);
        write_attribute(s, "linear_iterations", stats.linear_iterations);
        write_attribute(s, "output_steps", info.output_steps);
        write_array(s, "x", x, F);
        write_array(s, "x_1", x_1, F);
        write_array(s, "x_2", x_2, F);

        const H5 contact(H5Gcreate2(file, "contact", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                         H5Gclose, "group contact");
        write_array(contact, "active", info.active, 1);
        write_array(contact, "gap_normal_traction", info.traction, 1);
        if (!origins.empty())
        {
          // One row per rank (NewtonSolver::preconditioner_origin()).
          const H5 solver(H5Gcreate2(file, "solver", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                          H5Gclose, "group solver");
          write_array(solver, "preconditioner_origin", origins,
                      static_cast<hsize_t>(origin_length));
        }
        if (quadrature_state != nullptr)
        {
          const H5 q(H5Gcreate2(file, "quadrature_state", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                     H5Gclose, "group quadrature_state");
          write_attribute(q, "n_components", quadrature_state->n_state());
          write_array(q, "points_per_cell", points, 1);
          const H5 values(H5Gcreate2(q, "components", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                          H5Gclose, "group quadrature_state/components");
          for (int k = 0; k < quadrature_state->n_state(); ++k)
          {
            const std::string &name = quadrature_state->names()[k];
            write_attribute(q, "component_" + std::to_string(k), name);
            write_array(values, name, components[static_cast<std::size_t>(k)], 1);
          }
        }
      }
      check(H5Fflush(file, H5F_SCOPE_LOCAL), "flushing the file");
      const ssize_t size = H5Fget_file_image(file, nullptr, 0);
      if (size < 0)
        throw std::runtime_error("the file's image" + in_parentheses(hdf5_failure_reason()));
      std::vector<char> image(static_cast<std::size_t>(size));
      if (H5Fget_file_image(file, image.data(), image.size()) != size)
        throw std::runtime_error("the file's image" + in_parentheses(hdf5_failure_reason()));
      file.close("closing the file");
      write_file(tmp, image);
      std::vector<std::pair<std::string, const std::vector<double> *>> written_components;
      for (std::size_t k = 0; k < components.size(); ++k)
        written_components.emplace_back(quadrature_state->names()[k], &components[k]);
      verify_checkpoint(tmp, state.time, {&x, &x_1, &x_2}, written_components);
      std::filesystem::rename(tmp, path);
    }
    catch (const std::exception &e)
    {
      std::error_code ignored;
      std::filesystem::remove(tmp, ignored);
      error = e.what();
    }
  }
  check_write_collectively(comm, error.empty(), path,
                           "cannot write the checkpoint: " + error +
                               "; nothing was put in its place. Check that its folder exists and "
                               "is writable (Kiln/Checkpoint/\"File Base\"), that the disk is "
                               "not full and that no file-size limit (ulimit -f) stops it");
}

Checkpoint read_checkpoint(const std::string &path, const RunFingerprint &run,
                           const Teuchos::RCP<const Map> &map, const Teuchos::Comm<int> &comm,
                           QuadratureState *quadrature_state)
{
  using namespace internal;
  Checkpoint c;
  SavedQuadratureState saved_state;
  std::string error, difference;
  std::vector<double> x, x_1, x_2;
  // The failures below become one message; HDF5's own error stack stays quiet.
  H5E_auto2_t old_function = nullptr;
  void *old_data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &old_function, &old_data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  try
  {
    if (!std::filesystem::is_regular_file(path))
      throw std::runtime_error("no such file");
    const H5 file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                  "not an HDF5 file, or a damaged (truncated) one");
    if (H5Aexists(file, "format") <= 0 || read_string(file, "format", true) != "kiln checkpoint")
      throw std::runtime_error("not a Kiln checkpoint (a results file? checkpoints are written "
                               "by Kiln/Checkpoint)");
    const int version = read_attribute<int>(file, "format_version");
    if (version != checkpoint_format_version)
      throw std::runtime_error("format version " + std::to_string(version) +
                               ", but this Kiln reads version " +
                               std::to_string(checkpoint_format_version));
    c.info.kiln_version = read_string(file, "kiln_version", true);
    c.info.created = read_string(file, "created", true);
    c.info.input_path = read_string(file, "input_path", true);
    c.info.input_xml = read_string(file, "input", false);

    const H5 print(H5Gopen2(file, "fingerprint", H5P_DEFAULT), H5Gclose, "group fingerprint");
    RunFingerprint &f = c.fingerprint;
    f.n_nodes = read_attribute<int>(print, "n_nodes");
    f.n_cells = read_attribute<int>(print, "n_cells");
    f.n_pairs = read_attribute<int>(print, "n_pairs");
    f.gap_side_set = read_attribute<int>(print, "gap_side_set");
    f.mesh_hash = read_string(print, "mesh_hash", true);
    f.layout = read_string(print, "layout", true);
    const int n_physics = read_attribute<int>(print, "n_physics");
    for (int i = 0; i < n_physics; ++i)
      f.physics.emplace_back(read_string(print, "physics_name_" + std::to_string(i), true),
                             read_string(print, "physics_" + std::to_string(i), false));
    difference = run.difference(f);
    if (!difference.empty())
      throw std::runtime_error("another run's");

    const H5 s(H5Gopen2(file, "state", H5P_DEFAULT), H5Gclose, "group state");
    TimeStepper::State &state = c.state;
    state.time = read_attribute<double>(s, "time");
    state.next_step = read_attribute<double>(s, "next_step");
    state.last_step = read_attribute<double>(s, "last_step");
    state.step_before = read_attribute<double>(s, "step_before");
    state.accepted = read_attribute<int>(s, "accepted");
    state.attempts = read_attribute<int>(s, "attempts");
    state.newton_failed = read_attribute<int>(s, "newton_failed") != 0;
    state.statistics.steps = read_attribute<int>(s, "steps");
    state.statistics.error_rejections = read_attribute<int>(s, "error_rejections");
    state.statistics.newton_failures = read_attribute<int>(s, "newton_failures");
    state.statistics.newton_iterations = read_attribute<int>(s, "newton_iterations");
    state.statistics.linear_iterations = read_attribute<int>(s, "linear_iterations");
    c.info.output_steps = read_attribute<int>(s, "output_steps");
    const std::size_t n = map->getGlobalNumElements();
    if (n % static_cast<std::size_t>(std::max(f.n_nodes, 1)) != 0)
      throw std::runtime_error("its " + std::to_string(f.n_nodes) +
                               " nodes do not fit this run's " + std::to_string(n) + " unknowns");
    check_ranges(state, c.info.output_steps);
    x = read_array<double>(s, "x", n);
    x_1 = read_array<double>(s, "x_1", n);
    x_2 = read_array<double>(s, "x_2", n);
    if (!all_finite({&x, &x_1, &x_2}))
      throw std::runtime_error("its state (state/x, x_1 or x_2) holds values that are not finite "
                               "numbers (NaN or Inf): a damaged checkpoint");

    const H5 contact(H5Gopen2(file, "contact", H5P_DEFAULT), H5Gclose, "group contact");
    c.info.active = read_array<int>(contact, "active", f.n_pairs);
    c.info.traction = read_array<double>(contact, "gap_normal_traction", f.n_pairs);
    for (std::size_t i = 0; i < c.info.active.size(); ++i)
      if ((c.info.active[i] != 0 && c.info.active[i] != 1) || !std::isfinite(c.info.traction[i]))
        throw std::runtime_error("its contact state of gap pair " + std::to_string(i) +
                                 " is out of range (active not 0 or 1, or a traction that is not "
                                 "a finite number): a damaged checkpoint");
    if (H5Lexists(file, "solver", H5P_DEFAULT) > 0)
    {
      const H5 solver(H5Gopen2(file, "solver", H5P_DEFAULT), H5Gclose, "group solver");
      c.info.preconditioner_origin =
          read_row(solver, "preconditioner_origin", comm.getSize(), comm.getRank());
    }
    saved_state = read_saved_quadrature_state(file, f.n_cells);
  }
  catch (const std::exception &e)
  {
    error = e.what();
  }
  H5Eset_auto2(H5E_DEFAULT, old_function, old_data);
  check_collectively(comm, difference.empty(), path,
                     "cannot continue this run from the checkpoint: " + difference +
                         " (the checkpoint was written by " + c.info.input_path + ")");
  check_collectively(comm, error.empty(), path,
                     "cannot read the checkpoint: " + error +
                         ". Give a checkpoint written by Kiln/Checkpoint (a file NAME-NNNNNN.h5 "
                         "or NAME.h5 of its \"File Base\")");
  restore_quadrature_state(path, c.info.kiln_version, saved_state, quadrature_state, comm);
  // The owned unknowns.
  TimeStepper::State &state = c.state;
  for (auto *target : {&state.x, &state.x_1, &state.x_2})
    *target = Teuchos::rcp(new Tpetra::Vector<>(map));
  const std::vector<double> *sources[] = {&x, &x_1, &x_2};
  Teuchos::RCP<Tpetra::Vector<>> targets[] = {state.x, state.x_1, state.x_2};
  for (int v = 0; v < 3; ++v)
  {
    auto values = targets[v]->getDataNonConst();
    for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
      values[i] = (*sources[v])[map->getGlobalElement(static_cast<LO>(i))];
  }
  return c;
}
} // namespace kiln
