// Tests src/mesh/exodus_reader.cpp and exodus_writer.cpp: reading the contact-box Cubit meshes, a
// write/read round trip, the names, node sets and metres record of a written mesh, and the
// InputError messages for bad files.
// KILN_TEST_NP: 1
#include "mesh/exodus_io.hpp"

#include "base/errors.hpp"
#include "mesh/box_mesh_generator.hpp"
#include "support/parameter_lists.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>
#include <exodusII.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
using kiln::Mesh;
using testing::HasSubstr;

const std::string mesh_dir = std::string(KILN_SHARED_DIR) + "/meshes/";
constexpr double cm = 0.01; // the Cubit meshes are in cm
constexpr double half_side = 2 * cm;

/// A file name in the working directory, unique per process and per tag; removed at scope end.
class TempFile
{
public:
  explicit TempFile(const std::string &tag)
      : path_("kiln-exodus-io-test-" + tag + "-" + std::to_string(::getpid()) + ".exo")
  {
  }
  ~TempFile() { std::remove(path_.c_str()); }
  TempFile(const TempFile &) = delete;
  TempFile &operator=(const TempFile &) = delete;
  const std::string &path() const { return path_; }

private:
  std::string path_;
};

double distance(const kiln::Point &a, const kiln::Point &b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

/// Checks what both reference meshes share: sizes, blocks, side sets, cube extent, edge lengths.
void expect_contact_box_mesh(const Mesh &mesh)
{
  ASSERT_EQ(mesh.n_nodes(), 125);
  ASSERT_EQ(mesh.n_cells(), 64);
  ASSERT_EQ(mesh.block_ids(), (std::vector<int>{1, 2}));
  EXPECT_EQ(std::count(mesh.block_id.begin(), mesh.block_id.end(), 1), 32);
  EXPECT_EQ(std::count(mesh.block_id.begin(), mesh.block_id.end(), 2), 32);

  std::vector<int> ids;
  for (const auto &set : mesh.side_sets)
    ids.push_back(set.id);
  ASSERT_EQ(ids, (std::vector<int>{1, 2, 3, 4, 5, 6, 10}));
  for (const auto &set : mesh.side_sets)
  {
    EXPECT_EQ(set.name, "") << "the Cubit files carry no side set names";
    ASSERT_EQ(set.faces.size(), set.cells.size());
    // The cut plane is listed from both sides: 16 faces of block 1 and 16 of block 2.
    EXPECT_EQ(set.n_sides(), set.id == 10 ? 32 : 16) << "side set " << set.id;
    for (int i = 0; i < set.n_sides(); ++i)
    {
      EXPECT_TRUE(set.cells[i] >= 0 && set.cells[i] < mesh.n_cells());
      EXPECT_TRUE(set.faces[i] >= 0 && set.faces[i] < kiln::n_hex_faces);
    }
  }
  const kiln::SideSet &gap = *mesh.find_side_set(10);
  EXPECT_EQ(std::count_if(gap.cells.begin(), gap.cells.end(),
                          [&](const int c) { return mesh.block_id[c] == 1; }),
            16);

  const double radius = half_side * std::sqrt(3.0);
  for (const auto &p : mesh.coordinates)
    EXPECT_LE(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), radius * (1 + 1e-14));

  // The 12 edges of a HEX8 (bottom, top, vertical): all 1 cm long.
  const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                            {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (const auto &e : edges)
      EXPECT_NEAR(distance(mesh.coordinates[mesh.cell_nodes(c)[e[0]]],
                           mesh.coordinates[mesh.cell_nodes(c)[e[1]]]),
                  cm, 1e-14)
          << "cell " << c << " edge " << e[0] << "-" << e[1];
}

TEST(ExodusIo, ReadsRotatedCube)
{
  const Mesh mesh = kiln::read_exodus_mesh(mesh_dir + "rotated-cube.exo", cm);
  expect_contact_box_mesh(mesh);
}

TEST(ExodusIo, ReadsAlignedCubeWithSideSetsOnTheCubeFaces)
{
  const Mesh mesh = kiln::read_exodus_mesh(mesh_dir + "aligned-cube.exo", cm);
  expect_contact_box_mesh(mesh);

  // Side set id -> the axis its face nodes share and the value there
  // (1 left, 2 right, 3 front, 4 back, 5 bottom, 6 top; 10 the cut plane x = 0).
  struct Plane
  {
    int id;
    int axis;
    double value;
  };
  const Plane planes[] = {{1, 0, -half_side}, {2, 0, half_side},  {3, 1, -half_side},
                          {4, 1, half_side},  {5, 2, -half_side}, {6, 2, half_side},
                          {10, 0, 0.0}};
  for (const Plane &plane : planes)
  {
    const kiln::SideSet &set = *mesh.find_side_set(plane.id);
    for (int i = 0; i < set.n_sides(); ++i)
    {
      const auto &cell = mesh.cell_nodes(set.cells[i]);
      const int *face = kiln::hex_face_nodes[set.faces[i]];
      for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(mesh.coordinates[cell[face[k]]][plane.axis], plane.value, 1e-15)
            << "side set " << plane.id << " entry " << i;
      if (plane.id == 10)
        continue;
      // The face table's right-hand rule gives the outward normal: +-axis direction.
      const kiln::Point &p0 = mesh.coordinates[cell[face[0]]];
      const kiln::Point &p1 = mesh.coordinates[cell[face[1]]];
      const kiln::Point &p3 = mesh.coordinates[cell[face[3]]];
      const double a[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
      const double b[3] = {p3[0] - p0[0], p3[1] - p0[1], p3[2] - p0[2]};
      const double normal[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                a[0] * b[1] - a[1] * b[0]};
      EXPECT_GT(normal[plane.axis] * plane.value, 0.0)
          << "side set " << plane.id << " entry " << i << ": normal not outward";
    }
  }
  // Block 1 is the x < 0 half.
  for (int c = 0; c < mesh.n_cells(); ++c)
  {
    double x_sum = 0.0;
    for (const int node : mesh.cell_nodes(c))
      x_sum += mesh.coordinates[node][0];
    EXPECT_EQ(x_sum < 0.0, mesh.block_id[c] == 1) << "cell " << c;
  }
}

/// Writes `mesh`, reads it back and expects the same nodes, cells, blocks and side sets.
void expect_round_trip(const Mesh &mesh, const std::string &tag)
{
  const TempFile file(tag);
  kiln::write_exodus_mesh(mesh, file.path());
  const Mesh back = kiln::read_exodus_mesh(file.path(), 1.0);

  ASSERT_EQ(back.n_nodes(), mesh.n_nodes());
  for (int i = 0; i < mesh.n_nodes(); ++i)
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(back.coordinates[i][d], mesh.coordinates[i][d],
                  1e-15 * std::abs(mesh.coordinates[i][d]))
          << "node " << i;
  EXPECT_EQ(back.cell_node_ids, mesh.cell_node_ids);
  EXPECT_TRUE(back.cell_types == mesh.cell_types);
  EXPECT_EQ(back.block_id, mesh.block_id);
  ASSERT_EQ(back.side_sets.size(), mesh.side_sets.size());
  for (std::size_t s = 0; s < mesh.side_sets.size(); ++s)
  {
    EXPECT_EQ(back.side_sets[s].id, mesh.side_sets[s].id);
    // Names are kept; side sets without one are named after their id.
    const std::string name = mesh.side_sets[s].name.empty()
                                 ? "sideset_" + std::to_string(mesh.side_sets[s].id)
                                 : mesh.side_sets[s].name;
    EXPECT_EQ(back.side_sets[s].name, name);
    EXPECT_EQ(back.side_sets[s].cells, mesh.side_sets[s].cells);
    EXPECT_EQ(back.side_sets[s].faces, mesh.side_sets[s].faces);
  }
}

TEST(ExodusIo, WriteThenReadGivesTheSameMesh)
{
  Mesh mesh = kiln::read_exodus_mesh(mesh_dir + "rotated-cube.exo", cm);
  mesh.side_sets.front().name = "left";
  mesh.side_sets.back().name = "gap, a name longer than thirty-two characters";
  expect_round_trip(mesh, "round-trip");
}

// The generated pyramids and the mixed mesh (HEX8, PYRAMID5, TETRA4 in blocks 1, 2, 3).
TEST(ExodusIo, GeneratedPyramidAndMixedMeshesRoundTrip)
{
  for (const std::string type : {"PYRAMID5", "MIXED"})
  {
    SCOPED_TRACE(type);
    Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
    p.set("Cells", Teuchos::Array<int>(Teuchos::tuple(4, 2, 3)));
    p.set("Cell Type", type);
    expect_round_trip(kiln::BoxMeshGenerator(p, "test/Box").generate(), "round-trip-" + type);
  }
}

/// Names of the n objects of `type` in an open Exodus file.
std::vector<std::string> exodus_names(const int exo, const ex_entity_type type, const int n)
{
  const int length = static_cast<int>(ex_inquire_int(exo, EX_INQ_DB_MAX_USED_NAME_LENGTH));
  ex_set_max_name_length(exo, length);
  std::vector<std::vector<char>> buffers(n, std::vector<char>(length + 1, '\0'));
  std::vector<char *> pointers;
  for (auto &b : buffers)
    pointers.push_back(b.data());
  EXPECT_GE(ex_get_names(exo, type, pointers.data()), 0);
  std::vector<std::string> names;
  for (const auto &b : buffers)
    names.emplace_back(b.data());
  return names;
}

// What meshio and ParaView list: named blocks, named side sets, node sets with the side
// sets' ids, names and face nodes; and the record that says the file is in metres.
TEST(ExodusIo, WrittenMeshHasBlockAndSetNamesNodeSetsAndTheMetresRecord)
{
  Mesh mesh = kiln::read_exodus_mesh(mesh_dir + "aligned-cube.exo", cm);
  mesh.side_sets.front().name = "left";
  const TempFile file("names");
  kiln::write_exodus_mesh(mesh, file.path(), {10}); // side set 10 is the gap

  int comp_ws = sizeof(double), io_ws = 0;
  float version = 0.0F;
  const int exo = ex_open(file.path().c_str(), EX_READ, &comp_ws, &io_ws, &version);
  ASSERT_GE(exo, 0);
  EXPECT_EQ(ex_inquire_int(exo, EX_INQ_ELEM_BLK), 2);
  EXPECT_EQ(exodus_names(exo, EX_ELEM_BLOCK, 2), (std::vector<std::string>{"block_1", "block_2"}));
  const std::vector<std::string> set_names = {"left",      "sideset_2", "sideset_3", "sideset_4",
                                              "sideset_5", "sideset_6", "gap"};
  ASSERT_EQ(ex_inquire_int(exo, EX_INQ_SIDE_SETS), 7);
  ASSERT_EQ(ex_inquire_int(exo, EX_INQ_NODE_SETS), 7);
  EXPECT_EQ(exodus_names(exo, EX_SIDE_SET, 7), set_names);
  EXPECT_EQ(exodus_names(exo, EX_NODE_SET, 7), set_names);
  std::vector<int> node_set_ids(7);
  ASSERT_GE(ex_get_node_set_ids(exo, node_set_ids.data()), 0);
  EXPECT_EQ(node_set_ids, (std::vector<int>{1, 2, 3, 4, 5, 6, 10}));
  for (const auto &set : mesh.side_sets)
  {
    int n_nodes = 0, n_dist = 0;
    ASSERT_GE(ex_get_node_set_param(exo, set.id, &n_nodes, &n_dist), 0);
    std::vector<int> nodes(n_nodes);
    ASSERT_GE(ex_get_node_set(exo, set.id, nodes.data()), 0);
    // Each cube face and the cut plane hold 5 x 5 nodes (the mesh is not split).
    EXPECT_EQ(n_nodes, 25) << "node set " << set.id;
    std::vector<int> expected;
    for (int i = 0; i < set.n_sides(); ++i)
      for (const int k : kiln::hex_face_nodes[set.faces[i]])
        expected.push_back(mesh.cell_nodes(set.cells[i])[k] + 1);
    std::sort(expected.begin(), expected.end());
    expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
    EXPECT_EQ(nodes, expected) << "node set " << set.id;
  }
  ex_close(exo);

  EXPECT_TRUE(kiln::exodus_file_in_metres(file.path()));
  EXPECT_FALSE(kiln::exodus_file_in_metres(mesh_dir + "aligned-cube.exo")); // Cubit, cm
  // Kiln reads the names back; the gap's name "gap" stays "gap".
  const Mesh back = kiln::read_exodus_mesh(file.path(), 1.0);
  for (std::size_t s = 0; s < back.side_sets.size(); ++s)
    EXPECT_EQ(back.side_sets[s].name, set_names[s]);
}

/// Writes a one-element Exodus file with the C API (to make files Kiln must reject).
/// side_set_side < 0: no side set.
void write_one_element_file(const std::string &path, const int n_dim, const char *type,
                            const int block_id, const int side_set_side)
{
  int comp_ws = 8, io_ws = 8;
  const int exo = ex_create(path.c_str(), EX_CLOBBER, &comp_ws, &io_ws);
  ASSERT_GE(exo, 0);
  const std::string element_type = type;
  const int n_nodes = element_type == "SHELL4"  ? 4
                      : element_type == "QUAD4" ? 4
                      : element_type == "BAR2"  ? 2
                                                : 8;
  const int n_side_sets = side_set_side < 0 ? 0 : 1;
  ASSERT_GE(ex_put_init(exo, "test", n_dim, n_nodes, 1, 1, 0, n_side_sets), 0);
  std::vector<double> x = {0, 1, 1, 0, 0, 1, 1, 0}, y = {0, 0, 1, 1, 0, 0, 1, 1},
                      z = {0, 0, 0, 0, 1, 1, 1, 1};
  x.resize(n_nodes, 0.5);
  y.resize(n_nodes, 0.5);
  z.resize(n_nodes, 0.5);
  ASSERT_GE(ex_put_coord(exo, x.data(), y.data(), n_dim == 3 ? z.data() : nullptr), 0);
  ASSERT_GE(ex_put_elem_block(exo, block_id, type, 1, n_nodes, 0), 0);
  std::vector<int> conn(n_nodes);
  for (int i = 0; i < n_nodes; ++i)
    conn[i] = i + 1;
  ASSERT_GE(ex_put_elem_conn(exo, block_id, conn.data()), 0);
  if (n_side_sets == 1)
  {
    const int elem = 1;
    ASSERT_GE(ex_put_side_set_param(exo, 4, 1, 0), 0);
    ASSERT_GE(ex_put_side_set(exo, 4, &elem, &side_set_side), 0);
  }
  ASSERT_GE(ex_close(exo), 0);
}

std::string read_error(const std::string &path)
{
  const std::string message =
      kiln_test::input_error_message([&] { kiln::read_exodus_mesh(path, 1.0); });
  if (message.empty())
    ADD_FAILURE() << "no InputError for " << path;
  return message;
}

TEST(ExodusIo, MissingFileNamesThePath)
{
  const std::string path = "no-such-folder/no-such-mesh.exo";
  EXPECT_THROW(kiln::read_exodus_mesh(path, 1.0), kiln::InputError);
  const std::string message = read_error(path);
  EXPECT_THAT(message, HasSubstr("cannot open Exodus file"));
  EXPECT_THAT(message, HasSubstr(path));
}

TEST(ExodusIo, FileThatIsNotExodusNamesThePath)
{
  const TempFile file("not-exodus");
  std::ofstream(file.path()) << "this is not a netCDF file\n";
  const std::string message = read_error(file.path());
  EXPECT_THAT(message, HasSubstr(file.path()));
  EXPECT_THAT(message, HasSubstr("not an Exodus II"));
}

TEST(ExodusIo, ShellBlockIsRejected)
{
  const TempFile file("shell");
  write_one_element_file(file.path(), 3, "SHELL4", 3, -1);
  const std::string message = read_error(file.path());
  EXPECT_THAT(message, HasSubstr(file.path()));
  EXPECT_THAT(message, HasSubstr("element block 3"));
  EXPECT_THAT(message, HasSubstr("\"SHELL4\""));
  // The supported list.
  EXPECT_THAT(message, HasSubstr("Kiln supports the volume elements HEX8"));
}

TEST(ExodusIo, TwoDimensionalMeshIsRejected)
{
  const TempFile file("2d");
  write_one_element_file(file.path(), 2, "QUAD4", 1, -1);
  const std::string message = read_error(file.path());
  EXPECT_THAT(message, HasSubstr(file.path()));
  EXPECT_THAT(message, HasSubstr("2-dimensional"));
}

TEST(ExodusIo, SideNumberOutsideHexSidesIsRejected)
{
  const TempFile file("bad-side");
  write_one_element_file(file.path(), 3, "HEX8", 1, 7);
  const std::string message = read_error(file.path());
  EXPECT_THAT(message, HasSubstr(file.path()));
  EXPECT_THAT(message, HasSubstr("side set 4"));
  EXPECT_THAT(message, HasSubstr("side number 7 is outside 1..6"));

  // The same file with a valid side is read: side 6 is local face 5.
  write_one_element_file(file.path(), 3, "hex", 1, 6);
  const Mesh mesh = kiln::read_exodus_mesh(file.path(), 2.0);
  ASSERT_EQ(mesh.side_sets.size(), 1U);
  EXPECT_EQ(mesh.side_sets[0].cells, std::vector<int>{0});
  EXPECT_EQ(mesh.side_sets[0].faces, std::vector<int>{5});
  EXPECT_EQ(mesh.coordinates[6], (kiln::Point{2.0, 2.0, 2.0}));
}

TEST(ExodusIo, NonPositiveScaleIsRejected)
{
  EXPECT_THROW(kiln::read_exodus_mesh(mesh_dir + "aligned-cube.exo", 0.0), kiln::InputError);
}

TEST(ExodusIo, WritingIntoMissingFolderNamesThePath)
{
  const Mesh mesh = kiln::read_exodus_mesh(mesh_dir + "aligned-cube.exo", cm);
  const std::string path = "no-such-folder-" + std::to_string(::getpid()) + "/out.exo";
  try
  {
    kiln::write_exodus_mesh(mesh, path);
    ADD_FAILURE() << "no InputError";
  }
  catch (const kiln::InputError &e)
  {
    EXPECT_THAT(e.what(), HasSubstr(path));
    EXPECT_THAT(e.what(), HasSubstr("cannot create Exodus file"));
  }
}
TEST(ExodusIo, HexahedronWithEightNodesIsRead)
{
  // Some writers type 8-node hexahedra "HEXAHEDRON"; Kiln refused them as "not HEX8".
  const TempFile file("hexahedron");
  for (const char *type : {"HEXAHEDRON", "hexahedron", "HEX8", "HEX"})
  {
    write_one_element_file(file.path(), 3, type, 1, 2);
    const Mesh mesh = kiln::read_exodus_mesh(file.path(), 1.0);
    EXPECT_EQ(mesh.n_cells(), 1) << type;
    EXPECT_EQ(mesh.n_nodes(), 8) << type;
  }
}

TEST(ExodusIo, BeamBlockIsRejected)
{
  const TempFile file("beam");
  write_one_element_file(file.path(), 3, "BAR2", 2, -1);
  const std::string message = read_error(file.path());
  EXPECT_THAT(message, HasSubstr("element block 2 has element type \"BAR2\" with 2 nodes per "
                                 "element; Kiln supports the volume elements"));
}

TEST(ExodusIo, TruncatedFileIsReportedAsTruncated)
{
  // It was reported as a side set holding edges (side 0 read from the missing bytes).
  std::ifstream in(mesh_dir + "rotated-cube.exo", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const TempFile file("truncated");
  for (const std::size_t n : {std::size_t(13000), std::size_t(10000), bytes.size() - 1})
  {
    std::ofstream(file.path(), std::ios::binary).write(bytes.data(), static_cast<long>(n));
    const std::string message = read_error(file.path());
    EXPECT_THAT(message, HasSubstr("the file is truncated")) << n;
    EXPECT_THAT(message, testing::Not(HasSubstr("side set"))) << n;
  }
}
TEST(ExodusIo, OverlongElementTypeIsRejected)
{
  // Found by fuzz_exodus: Exodus copies the type name whole into a 33-byte buffer.
  const TempFile file("long-type");
  write_one_element_file(file.path(), 3, "HEX8", 5, -1);
  // ex_put_elem_block overflows as well with such a name: set it with netCDF.
  int nc = -1, varid = -1;
  ASSERT_EQ(nc_open(file.path().c_str(), NC_WRITE, &nc), NC_NOERR);
  ASSERT_EQ(nc_redef(nc), NC_NOERR);
  ASSERT_EQ(nc_inq_varid(nc, "connect1", &varid), NC_NOERR);
  const std::string type = "HEX8" + std::string(201, 'X');
  ASSERT_EQ(nc_put_att_text(nc, varid, "elem_type", type.size(), type.c_str()), NC_NOERR);
  ASSERT_EQ(nc_close(nc), NC_NOERR);
  EXPECT_THAT(read_error(file.path()),
              HasSubstr("element block 5: its element type name is 205 characters long, more "
                        "than the 32 Exodus II allows; the file is damaged"));
}
TEST(ExodusIo, IdGivenTwiceIsRejected)
{
  // Exodus finds a side set by its id: with one id twice it reads one side set's data with
  // the other's count.
  const TempFile file("twice");
  kiln::write_exodus_mesh(kiln::read_exodus_mesh(mesh_dir + "rotated-cube.exo", cm), file.path());
  int nc = -1, varid = -1;
  ASSERT_EQ(nc_open(file.path().c_str(), NC_WRITE, &nc), NC_NOERR);
  ASSERT_EQ(nc_inq_varid(nc, "ss_prop1", &varid), NC_NOERR);
  const std::size_t second = 1;
  const int id = 1;
  ASSERT_EQ(nc_put_var1_int(nc, varid, &second, &id), NC_NOERR);
  ASSERT_EQ(nc_close(nc), NC_NOERR);
  EXPECT_THAT(read_error(file.path()),
              HasSubstr("side set id 1 is given twice; the file is damaged: re-export it"));
}
} // namespace
