// Tests src/mesh/mesh_checks.cpp: a good mesh passes; inverted cells, unused nodes, node ids and
// side-set entries out of range are InputErrors naming the entity.
// KILN_TEST_NP: 1
#include "mesh/mesh_checks.hpp"

#include "base/errors.hpp"
#include "mesh/box_mesh_generator.hpp"
#include "mesh/gap_splitter.hpp"
#include "support/parameter_lists.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <utility>

namespace
{
using kiln::Mesh;
using testing::HasSubstr;

/// 4 x 4 x 4 rotated box, 125 nodes, 64 cells (32 per block).
Mesh box()
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  p.set("Phi", 45.0);
  p.set("Theta", -30.0);
  return kiln::BoxMeshGenerator(p, "test/Box").generate();
}

std::string check_error(const Mesh &mesh)
{
  const std::string message =
      kiln_test::input_error_message([&] { kiln::check_mesh(mesh, "mesh.exo"); });
  if (message.empty())
    ADD_FAILURE() << "no InputError";
  return message;
}

TEST(MeshChecks, GoodMeshesPass)
{
  Mesh mesh = box();
  EXPECT_NO_THROW(kiln::check_mesh(mesh, "mesh.exo"));
  kiln::split_gap(mesh, 10, "test");
  EXPECT_NO_THROW(kiln::check_mesh(mesh, "mesh.exo"));
}

TEST(MeshChecks, MirroredCellIsRejected)
{
  // Cell 40 (0-based; block 2) with its bottom and top faces exchanged: a reflection, so the
  // Jacobian determinant is negative everywhere.
  Mesh mesh = box();
  const auto cell = mesh.cell_nodes(40);
  for (int i = 0; i < 4; ++i)
    std::swap(cell[i], cell[i + 4]);
  const std::string message = check_error(mesh);
  EXPECT_THAT(message, HasSubstr("mesh.exo"));
  EXPECT_THAT(message, HasSubstr("cell 41 (block 2)"));
  EXPECT_THAT(message, HasSubstr("Jacobian"));
}

TEST(MeshChecks, CellWithTwoNodesSwappedIsRejected)
{
  // Nodes 0 and 1 exchanged: near the edge 0-1 the map is folded; for a unit cube det(J) is
  // about -0.0305 at the two Gauss points nearest that edge (computed by hand with the HEX8
  // shape functions), while the other six stay positive.
  Mesh mesh = box();
  std::swap(mesh.cell_nodes(5)[0], mesh.cell_nodes(5)[1]);
  const std::string message = check_error(mesh);
  EXPECT_THAT(message, HasSubstr("cell 6 (block 1)"));
  EXPECT_THAT(message, HasSubstr("Jacobian"));
}

TEST(MeshChecks, FlatCellIsRejected)
{
  // The top face moved onto the bottom one: zero volume, det(J) = 0.
  Mesh mesh = box();
  const auto cell = mesh.cell_nodes(0);
  for (int i = 0; i < 4; ++i)
    mesh.coordinates[cell[i + 4]] = mesh.coordinates[cell[i]];
  const std::string message = check_error(mesh);
  EXPECT_THAT(message, HasSubstr("cell 1 (block 1)"));
  EXPECT_THAT(message, HasSubstr("non-positive Jacobian"));
}

TEST(MeshChecks, UnusedNodeIsRejected)
{
  Mesh mesh = box();
  mesh.coordinates.push_back({1.0, 1.0, 1.0});
  const std::string message = check_error(mesh);
  EXPECT_THAT(message, HasSubstr("mesh.exo"));
  EXPECT_THAT(message, HasSubstr("node 126 belongs to no cell"));
}

TEST(MeshChecks, NodeIdOutOfRangeIsRejected)
{
  Mesh mesh = box();
  mesh.cell_nodes(3)[2] = 125; // one past the last node (0-based)
  const std::string message = check_error(mesh);
  EXPECT_THAT(message, HasSubstr("mesh.exo"));
  EXPECT_THAT(message, HasSubstr("cell 4 (block 1) refers to node 126"));
  EXPECT_THAT(message, HasSubstr("125 nodes"));

  Mesh negative = box();
  negative.cell_nodes(63)[7] = -1;
  EXPECT_THAT(check_error(negative), HasSubstr("cell 64 (block 2) refers to node 0"));
}

TEST(MeshChecks, SideSetEntryOutOfRangeIsRejected)
{
  Mesh mesh = box();
  mesh.side_sets[2].cells[1] = 64;
  std::string message = check_error(mesh);
  EXPECT_THAT(message, HasSubstr("side set 3 entry 2 (cell 65"));
  EXPECT_THAT(message, HasSubstr("is not a face of the mesh"));

  mesh = box();
  mesh.side_sets[6].faces[0] = 6;
  message = check_error(mesh);
  EXPECT_THAT(message, HasSubstr("side set 10 entry 1"));
  EXPECT_THAT(message, HasSubstr("side 7"));
}

TEST(MeshChecks, EmptyMeshIsRejected)
{
  EXPECT_THAT(check_error(Mesh{}), HasSubstr("no cells"));
}
TEST(MeshChecks, CellsOfTheWrongScaleNameTheParameter)
{
  // A tiny Coordinate Scale was reported as an inverted cell (det 0) or crashed later on a
  // zero-area face; now the cell size and the parameter are named.
  Mesh mesh = box();
  for (auto &p : mesh.coordinates)
    for (double &x : p)
      x *= 1e-100;
  try
  {
    kiln::check_mesh(mesh, "mesh.exo", "in.xml: Kiln/Mesh/Exodus/\"Coordinate Scale\" = 1e-100");
    ADD_FAILURE() << "no InputError";
  }
  catch (const kiln::InputError &e)
  {
    EXPECT_THAT(e.what(), HasSubstr("mesh.exo: cell "));
    EXPECT_THAT(e.what(), HasSubstr("m across, below 1e-09 m: Kiln takes coordinates in metres"));
    EXPECT_THAT(e.what(),
                HasSubstr("check in.xml: Kiln/Mesh/Exodus/\"Coordinate Scale\" = 1e-100"));
  }
  Mesh large = box();
  for (auto &p : large.coordinates)
    for (double &x : p)
      x *= 1e9;
  EXPECT_THAT(check_error(large), HasSubstr("m across, above 1e+06 m"));
  EXPECT_THAT(check_error(large), HasSubstr("fix the mesh"));
}

TEST(MeshChecks, NonFiniteNodeIsRejected)
{
  Mesh mesh = box();
  mesh.coordinates[7][1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(check_error(mesh), HasSubstr("mesh.exo: node 8 is at ("));
  EXPECT_THAT(check_error(mesh), HasSubstr("not a finite point"));
}

/// The unit cube as a HEX8 (cell 1, block 1) and [1,2] x [0,1]^2 as six tets
/// on the same nodes; with `tets`, the hex face at x = 1 is met by two tets' faces (not
/// conforming); without, the right cube is a HEX8 too (conforming).
Mesh hex_and_tets(const bool tets)
{
  Mesh mesh;
  mesh.coordinates = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1},
                      {1, 1, 1}, {0, 1, 1}, {2, 0, 0}, {2, 1, 0}, {2, 0, 1}, {2, 1, 1}};
  mesh.add_cell(kiln::CellType::hex8, {0, 1, 2, 3, 4, 5, 6, 7}, 1);
  if (!tets)
  {
    mesh.add_cell(kiln::CellType::hex8, {1, 8, 9, 2, 5, 10, 11, 6}, 2);
    return mesh;
  }
  // Kuhn's six tets of the right cube along its diagonal 1 -> 11 (positive orientation).
  const int paths[6][4] = {{1, 8, 9, 11}, {1, 8, 10, 11}, {1, 2, 9, 11},
                           {1, 2, 6, 11}, {1, 5, 10, 11}, {1, 5, 6, 11}};
  for (const auto &p : paths)
  {
    const auto &x = mesh.coordinates;
    double a[3][3];
    for (int d = 0; d < 3; ++d)
      for (int r = 0; r < 3; ++r)
        a[r][d] = x[p[r + 1]][d] - x[p[0]][d];
    const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                       a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                       a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    if (det > 0)
      mesh.add_cell(kiln::CellType::tet4, {p[0], p[1], p[2], p[3]}, 2);
    else
      mesh.add_cell(kiln::CellType::tet4, {p[0], p[2], p[1], p[3]}, 2);
  }
  return mesh;
}

TEST(MeshChecks, NonConformingMeshIsRejected)
{
  EXPECT_NO_THROW(kiln::check_mesh(hex_and_tets(false), "mesh.exo"));
  const std::string message = check_error(hex_and_tets(true));
  EXPECT_THAT(message, HasSubstr("mesh.exo: the mesh is not conforming: cell "));
  EXPECT_THAT(message, HasSubstr("(block 2, TETRA4) side "));
  EXPECT_THAT(message, HasSubstr("cell 1 (block 1, HEX8) side 2 share corner nodes"));
}
} // namespace
