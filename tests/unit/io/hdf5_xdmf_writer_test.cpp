// Tests Hdf5XdmfWriter: collective writes of non-contiguous owned rows give the same file
// on any number of ranks (read back serially), the XDMF file matches the HDF5 file,
// and an output path that cannot be created is an InputError on every rank.
// KILN_TEST_NP: 1 2 3
#include "io/hdf5_xdmf_writer.hpp"

#include "base/errors.hpp"
#include "cmake/xdmf_check.hpp"
#include "support/parallel.hpp"
#include "support/parameter_lists.hpp"
#include "support/results_files.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>
#include <mpi.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace
{
using kiln::Mesh;
using kiln_test::rank_of;
using kiln_test::same;
using kiln_test::shared_test_folder;
using kiln_test::step_cycle;
using kiln_test::step_dt;
using kiln_test::step_time;

constexpr int nx = 3; // cells along x, y, z
constexpr int ny = 2;
constexpr int nz = 2;
constexpr int n_steps = 2;
const double nan = std::numeric_limits<double>::quiet_NaN();

int size_of(const MPI_Comm comm)
{
  int s = 0;
  MPI_Comm_size(comm, &s);
  return s;
}

/// A structured nx x ny x nz grid of unit-ish hexahedra in Exodus HEX8 order;
/// cells with x index 0 are block 1, the others block 7.
Mesh box_mesh()
{
  Mesh mesh;
  const auto node = [](const int i, const int j, const int k)
  { return i + (nx + 1) * (j + (ny + 1) * k); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        mesh.coordinates.push_back({0.5 * i, 0.25 * j, 2.0 * k});
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        mesh.add_cell(kiln::CellType::hex8,
                      {node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                       node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                       node(i, j + 1, k + 1)},
                      i == 0 ? 1 : 7);
      }
  return mesh;
}

/// Who owns what: a rule giving each cell's rank; a node belongs to the lowest rank
/// among its cells.
struct Ownership
{
  std::vector<int> cell_rank;
  std::vector<int> owned_cells;
  std::vector<int> owned_nodes;
};

Ownership make_ownership(const Mesh &mesh, const int rank,
                         const std::function<int(int)> &cell_owner)
{
  Ownership o;
  std::vector<int> node_rank(mesh.n_nodes(), std::numeric_limits<int>::max());
  for (int c = 0; c < mesh.n_cells(); ++c)
  {
    o.cell_rank.push_back(cell_owner(c));
    for (const int n : mesh.cell_nodes(c))
      node_rank[n] = std::min(node_rank[n], o.cell_rank[c]);
    if (o.cell_rank[c] == rank)
      o.owned_cells.push_back(c);
  }
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (node_rank[n] == rank)
      o.owned_nodes.push_back(n);
  return o;
}

// The field values, as functions of the step (step_time, step_dt, step_cycle), the global id
// and the coordinates.
double temperature(const int step, const int node, const kiln::Point &x)
{
  if (node % 7 == 3 && step == 1)
    return nan;
  return 300.0 + x[0] + 10.0 * x[1] + 100.0 * x[2] + 1000.0 * step;
}

double displacement(const int step, const int node, const kiln::Point &x, const int component)
{
  if (node == 5 && component == 1)
    return nan;
  return 1e-3 * (step + 1) * x[component] + 1e-6 * component;
}

double stress(const int step, const int cell, const int component)
{
  if (cell == 4 && component == 2)
    return nan;
  return 1e6 * cell + 10.0 * component - 0.5 * step;
}

/// Writes the mesh and n_steps steps, each rank giving the values of its owned rows; with
/// `finish`, completes the files (else they keep their running names, as after a crash).
void write_results(const MPI_Comm comm, const std::string &base, const Mesh &mesh,
                   const Ownership &o, const bool finish = true)
{
  kiln::Hdf5XdmfWriter writer(
      comm, base, mesh, o.owned_nodes, o.owned_cells, o.cell_rank,
      {"9.9.9", "2026-01-01T00:00:00Z", "test.xml", "<Kiln/>", "0123456789abcdef"});
  EXPECT_EQ(writer.h5_path(), base + ".running.h5");
  EXPECT_EQ(writer.xdmf_path(), base + ".running.xmf");
  MPI_Barrier(comm);
  if (rank_of(comm) == 0) // before any step: a valid mesh-only XDMF file
  {
    EXPECT_EQ(kiln::check_xdmf(writer.xdmf_path()), "");
  }
  for (int s = 0; s < n_steps; ++s)
  {
    writer.begin_step(step_time(s), step_cycle(s), step_dt(s));
    std::vector<double> t;
    std::vector<double> u;
    for (const int n : o.owned_nodes)
    {
      t.push_back(temperature(s, n, mesh.coordinates[n]));
      for (int d = 0; d < 3; ++d)
        u.push_back(displacement(s, n, mesh.coordinates[n], d));
    }
    std::vector<double> sigma;
    for (const int c : o.owned_cells)
      for (int v = 0; v < 6; ++v)
        sigma.push_back(stress(s, c, v));
    writer.write_node_field("temperature", 1, t);
    writer.write_node_field("displacement", 3, u);
    writer.write_cell_field("stress", 6, sigma);
    writer.end_step();
  }
  if (!finish)
    return;
  writer.finish("complete");
  EXPECT_EQ(writer.h5_path(), base + ".h5");
  EXPECT_EQ(writer.xdmf_path(), base + ".xmf");
}

// ---- serial read-back helpers (rank 0) ----

std::vector<hsize_t> dataset_dims(const hid_t file, const std::string &path)
{
  const hid_t dataset = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (dataset < 0)
    return {};
  const hid_t space = H5Dget_space(dataset);
  std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  H5Sclose(space);
  H5Dclose(dataset);
  return dims;
}

template <typename T>
std::vector<T> read_all(const hid_t file, const std::string &path, const hid_t memory_type)
{
  std::size_t n = 1;
  for (const hsize_t d : dataset_dims(file, path))
    n *= d;
  std::vector<T> values(n);
  const hid_t dataset = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  EXPECT_GE(H5Dread(dataset, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0) << path;
  H5Dclose(dataset);
  return values;
}

template <typename T>
T read_attribute(const hid_t file, const std::string &group, const char *name,
                 const hid_t memory_type)
{
  T value{};
  const hid_t attribute = H5Aopen_by_name(file, group.c_str(), name, H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(attribute, 0) << group << " attribute " << name;
  if (attribute >= 0)
  {
    EXPECT_GE(H5Aread(attribute, memory_type, &value), 0);
    H5Aclose(attribute);
  }
  return value;
}

/// A text attribute of the object at `path` (rank 0 reads), or "" if missing.
std::string text_attribute(const std::string &file_path, const std::string &path,
                           const std::string &name)
{
  const hid_t file = H5Fopen(file_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t object = H5Oopen(file, path.c_str(), H5P_DEFAULT);
  std::string value;
  if (object >= 0 && H5Aexists(object, name.c_str()) > 0)
  {
    const hid_t attribute = H5Aopen(object, name.c_str(), H5P_DEFAULT);
    const hid_t type = H5Aget_type(attribute);
    value.assign(H5Tget_size(type), '\0');
    H5Aread(attribute, type, value.data());
    value.resize(std::min(value.size(), value.find('\0')));
    H5Tclose(type);
    H5Aclose(attribute);
  }
  if (object >= 0)
    H5Oclose(object);
  H5Fclose(file);
  return value;
}

/// Checks every value of the file against the functions above.
void check_h5_contents(const std::string &h5_path, const Mesh &mesh,
                       const std::vector<int> &cell_rank)
{
  const hsize_t n_nodes = mesh.n_nodes();
  const hsize_t n_cells = mesh.n_cells();
  const hid_t file = H5Fopen(h5_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0) << h5_path;

  using Dims = std::vector<hsize_t>;
  EXPECT_EQ(dataset_dims(file, "/mesh/coordinates"), (Dims{n_nodes, 3}));
  EXPECT_EQ(dataset_dims(file, "/mesh/connectivity"), (Dims{n_cells, 8}));
  EXPECT_EQ(dataset_dims(file, "/mesh/block_id"), (Dims{n_cells}));
  EXPECT_EQ(dataset_dims(file, "/mesh/cell_rank"), (Dims{n_cells}));

  const auto x = read_all<double>(file, "/mesh/coordinates", H5T_NATIVE_DOUBLE);
  const auto connectivity = read_all<std::int64_t>(file, "/mesh/connectivity", H5T_NATIVE_INT64);
  const auto block_id = read_all<std::int32_t>(file, "/mesh/block_id", H5T_NATIVE_INT32);
  const auto ranks = read_all<std::int32_t>(file, "/mesh/cell_rank", H5T_NATIVE_INT32);
  for (hsize_t n = 0; n < n_nodes; ++n)
    for (int d = 0; d < 3; ++d)
      EXPECT_EQ(x[3 * n + d], mesh.coordinates[n][d]) << "node " << n;
  for (hsize_t c = 0; c < n_cells; ++c)
  {
    for (int k = 0; k < 8; ++k)
      EXPECT_EQ(connectivity[8 * c + k], mesh.cell_nodes(c)[k]) << "cell " << c;
    EXPECT_EQ(block_id[c], mesh.block_id[c]) << "cell " << c;
    EXPECT_EQ(ranks[c], cell_rank[c]) << "cell " << c;
  }
  // The type of connectivity is 64-bit integer, as the XDMF file says.
  {
    const hid_t dataset = H5Dopen2(file, "/mesh/connectivity", H5P_DEFAULT);
    const hid_t type = H5Dget_type(dataset);
    EXPECT_EQ(H5Tget_class(type), H5T_INTEGER);
    EXPECT_EQ(H5Tget_size(type), 8u);
    H5Tclose(type);
    H5Dclose(dataset);
  }

  for (int s = 0; s < n_steps; ++s)
  {
    char group[32];
    std::snprintf(group, sizeof group, "/steps/%06d", s);
    EXPECT_EQ(read_attribute<double>(file, group, "time", H5T_NATIVE_DOUBLE), step_time(s));
    EXPECT_EQ(read_attribute<double>(file, group, "dt", H5T_NATIVE_DOUBLE), step_dt(s));
    EXPECT_EQ(read_attribute<int>(file, group, "cycle", H5T_NATIVE_INT), step_cycle(s));
    const std::string g(group);
    EXPECT_EQ(dataset_dims(file, g + "/temperature"), (Dims{n_nodes}));
    EXPECT_EQ(dataset_dims(file, g + "/displacement"), (Dims{n_nodes, 3}));
    EXPECT_EQ(dataset_dims(file, g + "/stress"), (Dims{n_cells, 6}));
    const auto t = read_all<double>(file, g + "/temperature", H5T_NATIVE_DOUBLE);
    const auto u = read_all<double>(file, g + "/displacement", H5T_NATIVE_DOUBLE);
    const auto sigma = read_all<double>(file, g + "/stress", H5T_NATIVE_DOUBLE);
    for (hsize_t n = 0; n < n_nodes; ++n)
    {
      const auto &p = mesh.coordinates[n];
      EXPECT_PRED2(same, t[n], temperature(s, n, p)) << "step " << s << " node " << n;
      for (int d = 0; d < 3; ++d)
        EXPECT_PRED2(same, u[3 * n + d], displacement(s, n, p, d))
            << "step " << s << " node " << n << " component " << d;
    }
    for (hsize_t c = 0; c < n_cells; ++c)
      for (int v = 0; v < 6; ++v)
        EXPECT_PRED2(same, sigma[6 * c + v], stress(s, c, v))
            << "step " << s << " cell " << c << " component " << v;
  }
  H5G_info_t steps_info{};
  EXPECT_GE(H5Gget_info_by_name(file, "/steps", &steps_info, H5P_DEFAULT), 0);
  EXPECT_EQ(steps_info.nlinks, static_cast<hsize_t>(n_steps));
  H5Fclose(file);
}

/// Counts the Uniform grids in the Temporal collection of the XDMF file.
int n_xdmf_steps(const std::string &xmf_path)
{
  const Teuchos::XMLObject root = Teuchos::FileInputSource(xmf_path).getObject();
  const Teuchos::XMLObject &domain = root.getChild(root.findFirstChild("Domain"));
  const Teuchos::XMLObject &collection = domain.getChild(domain.findFirstChild("Grid"));
  if (!collection.hasAttribute("CollectionType") ||
      collection.getAttribute("CollectionType") != "Temporal")
    return -1;
  int n = 0;
  for (int c = 0; c < collection.numChildren(); ++c)
    n += collection.getChild(c).getTag() == "Grid" ? 1 : 0;
  return n;
}

void write_and_check(const std::string &name, const std::function<int(int, int)> &cell_owner)
{
  const MPI_Comm comm = MPI_COMM_WORLD;
  const int rank = rank_of(comm);
  const int np = size_of(comm);
  const Mesh mesh = box_mesh();
  const Ownership o = make_ownership(mesh, rank, [&](const int c) { return cell_owner(c, np); });
  const std::string folder = shared_test_folder(comm, name);
  const std::string base = folder + "/out";

  write_results(comm, base, mesh, o);
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0); // nothing left open
  MPI_Barrier(comm);                                        // the writer is closed on every rank
  if (rank == 0)
  {
    check_h5_contents(base + ".h5", mesh, o.cell_rank);
    EXPECT_EQ(kiln::check_xdmf(base + ".xmf"), "");
    EXPECT_EQ(n_xdmf_steps(base + ".xmf"), n_steps);
    EXPECT_FALSE(std::filesystem::exists(base + ".xmf.tmp"));
    // finish() renamed both; the index points at the final file.
    EXPECT_FALSE(std::filesystem::exists(base + ".running.h5"));
    EXPECT_FALSE(std::filesystem::exists(base + ".running.xmf"));
    std::ifstream xmf(base + ".xmf");
    const std::string index((std::istreambuf_iterator<char>(xmf)),
                            std::istreambuf_iterator<char>());
    EXPECT_NE(index.find(">out.h5:/steps/"), std::string::npos);
    EXPECT_EQ(index.find("running"), std::string::npos);
    // The run's metadata and the fields' units and components.
    EXPECT_EQ(text_attribute(base + ".h5", "/", "status"), "complete");
    EXPECT_EQ(text_attribute(base + ".h5", "/", "kiln_version"), "9.9.9");
    EXPECT_EQ(text_attribute(base + ".h5", "/", "input"), "<Kiln/>");
    EXPECT_EQ(text_attribute(base + ".h5", "/steps/000000/stress", "unit"), "Pa");
    EXPECT_EQ(text_attribute(base + ".h5", "/steps/000000/stress", "components"),
              "xx,yy,zz,xy,yz,xz");
    EXPECT_EQ(text_attribute(base + ".h5", "/steps/000000/displacement", "unit"), "m");
    EXPECT_NE(index.find("Name=\"stress\" AttributeType=\"Matrix\""), std::string::npos);
    if (!::testing::Test::HasFailure())
      std::filesystem::remove_all(folder);
  }
  MPI_Barrier(comm);
}
} // namespace

TEST(Hdf5XdmfWriter, AnUnfinishedRunKeepsItsRunningNames)
{
  // A run that ends without finish() (a crash) leaves BASE.running.h5 and .xmf, readable up to
  // its last step, and no BASE.h5 that would look complete.
  const MPI_Comm comm = MPI_COMM_WORLD;
  const Mesh mesh = box_mesh();
  const Ownership o =
      make_ownership(mesh, rank_of(comm), [&](const int c) { return c % size_of(comm); });
  const std::string folder = shared_test_folder(comm, "h5_unfinished");
  const std::string base = folder + "/out";
  write_results(comm, base, mesh, o, false);
  MPI_Barrier(comm);
  if (rank_of(comm) == 0)
  {
    EXPECT_FALSE(std::filesystem::exists(base + ".h5"));
    EXPECT_FALSE(std::filesystem::exists(base + ".xmf"));
    check_h5_contents(base + ".running.h5", mesh, o.cell_rank);
    EXPECT_EQ(kiln::check_xdmf(base + ".running.xmf"), "");
    EXPECT_EQ(n_xdmf_steps(base + ".running.xmf"), n_steps);
    if (!::testing::Test::HasFailure())
      std::filesystem::remove_all(folder);
  }
  MPI_Barrier(comm);
}

TEST(Hdf5XdmfWriter, NonContiguousOwnedRowsGiveTheSameFileOnAnyNumberOfRanks)
{
  write_and_check("h5_round_robin", [](const int cell, const int np) { return cell % np; });
}

TEST(Hdf5XdmfWriter, RanksWithoutRowsTakePart)
{
  // Every row on the last rank: the others select nothing but join every collective call.
  write_and_check("h5_last_rank", [](const int, const int np) { return np - 1; });
}

TEST(Hdf5XdmfWriter, XdmfCheckerFindsAWrongDimension)
{
  const MPI_Comm comm = MPI_COMM_WORLD;
  const Mesh mesh = box_mesh();
  const Ownership o =
      make_ownership(mesh, rank_of(comm), [&](const int c) { return c % size_of(comm); });
  const std::string folder = shared_test_folder(comm, "h5_bad_xdmf");
  write_results(comm, folder + "/out", mesh, o);
  MPI_Barrier(comm);
  if (rank_of(comm) == 0)
  {
    // Break the XDMF file by hand: the checker must notice.
    const std::string xmf = folder + "/out.xmf";
    std::ifstream in(xmf);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string good = "Dimensions=\"36 3\"";
    const auto at = text.rfind(good);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, good.size(), "Dimensions=\"35 3\"");
    std::ofstream(folder + "/bad.xmf") << text;
    const std::string problem = kiln::check_xdmf(folder + "/bad.xmf");
    EXPECT_NE(problem.find("35 3"), std::string::npos) << problem;
    if (!::testing::Test::HasFailure())
      std::filesystem::remove_all(folder);
  }
  MPI_Barrier(comm);
}

TEST(Hdf5XdmfWriter, MissingFolderIsAnInputErrorOnEveryRank)
{
  const MPI_Comm comm = MPI_COMM_WORLD;
  const Mesh mesh = box_mesh();
  const Ownership o =
      make_ownership(mesh, rank_of(comm), [&](const int c) { return c % size_of(comm); });
  const std::string base = "/nonexistent_kiln_folder/sub/out";
  const std::string message = kiln_test::input_error_message(
      [&] {
        kiln::Hdf5XdmfWriter writer(comm, base, mesh, o.owned_nodes, o.owned_cells, o.cell_rank);
      });
  if (message.empty())
    ADD_FAILURE() << "no exception";
  EXPECT_NE(message.find(base + ".running.h5"), std::string::npos) << message;
  EXPECT_NE(message.find("exists and is writable"), std::string::npos) << message;
  // Every rank got here: the test did not hang.
  MPI_Barrier(comm);
}

TEST(Hdf5XdmfWriter, ErrorsInAStepAreThrownOnEveryRankAndCloseEverything)
{
  const MPI_Comm comm = MPI_COMM_WORLD;
  const int rank = rank_of(comm);
  const Mesh mesh = box_mesh();
  const Ownership o = make_ownership(mesh, rank, [&](const int c) { return c % size_of(comm); });
  const std::string folder = shared_test_folder(comm, "h5_step_errors");
  const std::string base = folder + "/out";
  std::string bad_name;
  std::string bad_size;
  try
  {
    kiln::Hdf5XdmfWriter writer(comm, base, mesh, o.owned_nodes, o.owned_cells, o.cell_rank);
    writer.begin_step(0.0, 0, 0.1);
    try
    {
      writer.write_node_field("bad/name", 1, std::vector<double>(o.owned_nodes.size()));
    }
    catch (const kiln::InputError &e)
    {
      bad_name = e.what();
    }
    // Only rank 0 passes a wrong number of values: every rank must throw.
    const std::size_t n = o.owned_cells.size() + (rank == 0 ? 1 : 0);
    writer.write_cell_field("stress", 1, std::vector<double>(n));
    ADD_FAILURE() << "no exception for a wrong number of values";
  }
  catch (const kiln::InternalError &e)
  {
    bad_size = e.what();
  }
  EXPECT_NE(bad_name.find("\"bad/name\" is not valid"), std::string::npos) << bad_name;
  EXPECT_NE(bad_size.find("cell field \"stress\""), std::string::npos) << bad_size;
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0); // the unwinding closed the file
  MPI_Barrier(comm);
  if (rank == 0)
  {
    // The mesh-only index written at creation; the files keep their running names.
    EXPECT_EQ(kiln::check_xdmf(base + ".running.xmf"), "");
    EXPECT_FALSE(std::filesystem::exists(base + ".h5"));
    if (!::testing::Test::HasFailure())
      std::filesystem::remove_all(folder);
  }
  MPI_Barrier(comm);
}
