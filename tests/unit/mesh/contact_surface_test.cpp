// Tests src/mesh/contact_surface.cpp: a boundary side set as a contact surface (QUAD4 and
// TRI3 faces): its own node numbering, nodal areas and area-weighted normals, face diameters
// and boxes, in the reference configuration and moved (translated, rotated, stretched); a
// curved surface's normals; the InputErrors for side sets that cannot be contact surfaces,
// each naming the pair.
// KILN_TEST_NP: 1
#include "mesh/contact_surface.hpp"

#include "base/errors.hpp"
#include "mesh/box_mesh_generator.hpp"
#include "mesh/gap_splitter.hpp"
#include "mesh/hex_geometry.hpp"
#include "support/parameter_lists.hpp"
#include "support/two_body_mesh.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace
{
using kiln::ContactSurface;
using kiln::Mesh;
using kiln::Point;
using testing::HasSubstr;

const std::string pair = "in.xml: Mechanics/Contact/Pairs/\"Pellet\"/\"Secondary Side Set\"";

/// A box of 2 x 2 x 2 cells of 1 x 1 x 1 m (side set 6: z = +1), rotated by phi, theta.
Mesh box(const std::string &cell_type, const double phi = 0.0, const double theta = 0.0)
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  p.set("Cells", Teuchos::Array<int>(Teuchos::tuple(2, 2, 2)));
  p.set("Size", Teuchos::Array<double>(Teuchos::tuple(2.0, 2.0, 2.0)));
  p.set("Phi", phi);
  p.set("Theta", theta);
  p.set("Cell Type", cell_type);
  return kiln::BoxMeshGenerator(p, "test/Box").generate();
}

/// e_z rotated as the box is.
Point rotated_z(const double phi, const double theta)
{
  const auto A = kiln::rotation_matrix(phi, theta);
  return {A[0][2], A[1][2], A[2][2]};
}

void expect_near(const Point &a, const Point &b, const double tolerance)
{
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(a[d], b[d], tolerance) << "component " << d;
}

std::string surface_error(const Mesh &mesh, const int side_set)
{
  const std::string message =
      kiln_test::input_error_message([&] { ContactSurface(mesh, side_set, pair); });
  if (message.empty())
    ADD_FAILURE() << "no InputError for side set " << side_set;
  EXPECT_THAT(message, HasSubstr(pair));
  return message;
}
} // namespace

TEST(ContactSurface, QuadFacesNumberingAreasNormals)
{
  const double phi = 30.0, theta = -20.0;
  const Mesh mesh = box("HEX8", phi, theta);
  const ContactSurface surface(mesh, 6, pair);
  EXPECT_EQ(surface.side_set_id(), 6);
  ASSERT_EQ(surface.n_faces(), 4);
  ASSERT_EQ(surface.n_nodes(), 9);
  // Its nodes in increasing mesh id, found back by surface_node; a node off the surface: -1.
  for (int j = 0; j < surface.n_nodes(); ++j)
  {
    EXPECT_EQ(surface.surface_node(surface.nodes()[j]), j);
    if (j > 0)
    {
      EXPECT_LT(surface.nodes()[j - 1], surface.nodes()[j]);
    }
  }
  EXPECT_EQ(surface.surface_node(0), -1); // a corner at z = -1
  double total_area = 0.0;
  int corners = 0, edges = 0, centres = 0;
  for (int f = 0; f < surface.n_faces(); ++f)
  {
    EXPECT_EQ(surface.face_type(f), kiln::CellType::quad4);
    const std::vector<int> mesh_nodes = mesh.face_nodes(surface.face_cell(f), surface.face_side(f));
    ASSERT_EQ(surface.face_nodes(f).size(), 4);
    for (int i = 0; i < 4; ++i)
      EXPECT_EQ(surface.nodes()[surface.face_nodes(f)[i]], mesh_nodes[i]);
    EXPECT_NEAR(surface.face_diameter(f), std::sqrt(2.0), 1e-14);
    expect_near(surface.face_area_vector(f), rotated_z(phi, theta), 1e-14);
  }
  for (int j = 0; j < surface.n_nodes(); ++j)
  {
    total_area += surface.nodal_area(j);
    expect_near(surface.normal(j), rotated_z(phi, theta), 1e-14);
    // A corner of the surface takes a quarter of a face, an edge node two quarters, the
    // centre four.
    const double a = surface.nodal_area(j);
    corners += std::abs(a - 0.25) < 1e-14;
    edges += std::abs(a - 0.5) < 1e-14;
    centres += std::abs(a - 1.0) < 1e-14;
  }
  EXPECT_NEAR(total_area, 4.0, 1e-13);
  EXPECT_EQ(corners, 4);
  EXPECT_EQ(edges, 4);
  EXPECT_EQ(centres, 1);
  EXPECT_NEAR(surface.max_face_diameter(), std::sqrt(2.0), 1e-14);
}

TEST(ContactSurface, FaceBoxesUnrotated)
{
  const Mesh mesh = box("HEX8");
  const ContactSurface surface(mesh, 6, pair);
  for (int f = 0; f < surface.n_faces(); ++f)
  {
    const kiln::BoundingBox &b = surface.face_box(f);
    EXPECT_DOUBLE_EQ(b.lo[2], 1.0);
    EXPECT_DOUBLE_EQ(b.hi[2], 1.0);
    EXPECT_DOUBLE_EQ(b.hi[0] - b.lo[0], 1.0);
    EXPECT_DOUBLE_EQ(b.hi[1] - b.lo[1], 1.0);
    // The face's nodes lie in its box, on its corners.
    for (const int j : surface.face_nodes(f))
      for (int d = 0; d < 3; ++d)
      {
        const double x = surface.positions()[j][d];
        EXPECT_TRUE(x == b.lo[d] || x == b.hi[d]) << "face " << f << ", node " << j;
      }
  }
}

TEST(ContactSurface, TriangleFaces)
{
  const double phi = 45.0, theta = 10.0;
  const Mesh mesh = box("TETRA4", phi, theta);
  const ContactSurface surface(mesh, 6, pair);
  ASSERT_EQ(surface.n_faces(), 8); // two triangles per square
  EXPECT_EQ(surface.n_nodes(), 9);
  double total_area = 0.0;
  for (int f = 0; f < surface.n_faces(); ++f)
  {
    EXPECT_EQ(surface.face_type(f), kiln::CellType::tri3);
    EXPECT_EQ(surface.face_nodes(f).size(), 3);
    EXPECT_NEAR(surface.face_diameter(f), std::sqrt(2.0), 1e-14); // the diagonal
    const Point &a = surface.face_area_vector(f);
    EXPECT_NEAR(std::sqrt(kiln::dot(a, a)), 0.5, 1e-14);
  }
  for (int j = 0; j < surface.n_nodes(); ++j)
  {
    total_area += surface.nodal_area(j);
    expect_near(surface.normal(j), rotated_z(phi, theta), 1e-14);
  }
  EXPECT_NEAR(total_area, 4.0, 1e-13);
}

TEST(ContactSurface, QuadAndTriangleFacesTogether)
{
  // The MIXED box: HEX8 for x < 0, tetrahedra (and pyramids on x = 0) for x > 0; its top
  // z = +1 has two QUAD4 and four TRI3 faces.
  const double phi = 20.0, theta = 35.0;
  const ContactSurface surface(box("MIXED", phi, theta), 6, pair);
  int quads = 0, triangles = 0;
  for (int f = 0; f < surface.n_faces(); ++f)
  {
    quads += surface.face_type(f) == kiln::CellType::quad4;
    triangles += surface.face_type(f) == kiln::CellType::tri3;
  }
  EXPECT_EQ(quads, 2);
  EXPECT_EQ(triangles, 4);
  EXPECT_EQ(surface.n_nodes(), 9);
  double total_area = 0.0;
  for (int j = 0; j < surface.n_nodes(); ++j)
  {
    total_area += surface.nodal_area(j);
    expect_near(surface.normal(j), rotated_z(phi, theta), 1e-14);
  }
  EXPECT_NEAR(total_area, 4.0, 1e-13);
}

TEST(ContactSurface, PartsOfASurfaceSumToTheWhole)
{
  // The top of a 2 x 2 x 2 box in two parts by its cells, as two ranks would own them (and an
  // empty part): each keeps its faces and their nodes; the nodal areas of the parts sum to
  // the whole surface's at every node, the normals agree.
  const Mesh mesh = box("HEX8", 30.0, -20.0);
  const ContactSurface whole(mesh, 6, pair);
  std::vector<int> first, second;
  for (int f = 0; f < whole.n_faces(); ++f)
    (f < 1 ? first : second).push_back(whole.face_cell(f));
  std::sort(second.begin(), second.end());
  const ContactSurface part_1(mesh, 6, pair, first);
  const ContactSurface part_2(mesh, 6, pair, second);
  const ContactSurface none(mesh, 6, pair, std::vector<int>{});
  EXPECT_EQ(part_1.n_faces(), 1);
  EXPECT_EQ(part_1.n_nodes(), 4);
  EXPECT_EQ(part_2.n_faces(), 3);
  EXPECT_EQ(part_2.n_nodes(), 8);
  EXPECT_EQ(none.n_faces(), 0);
  EXPECT_EQ(none.n_nodes(), 0);
  for (int j = 0; j < whole.n_nodes(); ++j)
  {
    const int node = whole.nodes()[j];
    double area = 0.0;
    for (const ContactSurface *part : {&part_1, &part_2})
      if (const int k = part->surface_node(node); k >= 0)
      {
        area += part->nodal_area(k);
        expect_near(part->normal(k), whole.normal(j), 1e-14);
      }
    EXPECT_NEAR(area, whole.nodal_area(j), 1e-14) << "node " << node;
  }
  // The checks are on the whole side set, whatever the part.
  EXPECT_THAT(kiln_test::input_error_message([&] { ContactSurface(mesh, 10, pair, first); }),
              HasSubstr("side set 10 is not on the boundary"));
}

TEST(ContactSurface, MovedSurface)
{
  const Mesh mesh = box("HEX8");
  ContactSurface surface(mesh, 6, pair);
  // Rotated by 90 degrees about x (y -> z, z -> -y) and translated by (1, 2, 3): the normal
  // becomes -e_y, the diameters stay; then stretched by 2 in x: diameters sqrt(5).
  std::vector<Point> u;
  for (const int n : surface.nodes())
  {
    const Point &X = mesh.coordinates[n];
    u.push_back(Point{1.0, -X[2] - X[1] + 2.0, X[1] - X[2] + 3.0});
  }
  surface.set_displacement(u);
  for (int j = 0; j < surface.n_nodes(); ++j)
  {
    expect_near(surface.normal(j), {0.0, -1.0, 0.0}, 1e-14);
    const Point &X = mesh.coordinates[surface.nodes()[j]];
    expect_near(surface.positions()[j], {X[0] + 1.0, -X[2] + 2.0, X[1] + 3.0}, 1e-14);
  }
  for (int f = 0; f < surface.n_faces(); ++f)
  {
    EXPECT_NEAR(surface.face_diameter(f), std::sqrt(2.0), 1e-14);
    EXPECT_NEAR(surface.face_box(f).lo[1], 1.0, 1e-14); // y = -1 + 2
  }
  for (int j = 0; j < surface.n_nodes(); ++j)
    u[j] = Point{mesh.coordinates[surface.nodes()[j]][0], 0.0, 0.0};
  surface.set_displacement(u);
  for (int f = 0; f < surface.n_faces(); ++f)
    EXPECT_NEAR(surface.face_diameter(f), std::sqrt(5.0), 1e-14);
  EXPECT_NEAR(surface.max_face_diameter(), std::sqrt(5.0), 1e-14);
}

TEST(ContactSurface, CurvedSurfaceNormalsAreRadial)
{
  // The outer face of a shell of radius 2 over [0, 1] rad: at every node not on the arc's
  // two ends, the faces on either side are mirror images, so the area-weighted normal is
  // radial; at the ends it is the one face's normal, half a cell's angle off.
  const Mesh mesh = kiln_test::two_cylinder_shells({12, 4}, {9, 5}, 0.01);
  const ContactSurface outer(mesh, 1, pair);
  const ContactSurface inner(mesh, 2, pair);
  EXPECT_EQ(outer.n_nodes(), 13 * 5);
  EXPECT_EQ(inner.n_nodes(), 10 * 6);
  int radial = 0;
  for (const ContactSurface *surface : {&outer, &inner})
    for (int j = 0; j < surface->n_nodes(); ++j)
    {
      const Point &x = surface->positions()[j];
      const double angle = std::atan2(x[1], x[0]);
      if (angle < 1e-12 || angle > 1.0 - 1e-12)
        continue;
      const double sign = surface == &outer ? 1.0 : -1.0;
      expect_near(surface->normal(j), {sign * std::cos(angle), sign * std::sin(angle), 0.0}, 1e-14);
      ++radial;
    }
  EXPECT_EQ(radial, 11 * 5 + 8 * 6);
  // The faceted area: 12 chords of 2 * 2 sin(1/24) by 1.
  double area = 0.0;
  for (int j = 0; j < outer.n_nodes(); ++j)
    area += outer.nodal_area(j);
  EXPECT_NEAR(area, 12 * 4 * std::sin(1.0 / 24), 1e-13);
}

TEST(ContactSurface, SideSetNotInTheMesh)
{
  const std::string message = surface_error(box("HEX8"), 7);
  EXPECT_THAT(message, HasSubstr("side set 7 is not in the mesh (side sets present: 1, 2, 3, "
                                 "4, 5, 6, 10)"));
}

TEST(ContactSurface, SideSetInsideTheMesh)
{
  // The box's side set 10 is the plane x = 0 between its two blocks, not split.
  const std::string message = surface_error(box("HEX8"), 10);
  EXPECT_THAT(message, HasSubstr("side set 10 is not on the boundary"));
  EXPECT_THAT(message, HasSubstr("\"Gap Side Set\""));
}

TEST(ContactSurface, SideSetThatIsAGap)
{
  Mesh mesh = box("HEX8");
  kiln::split_gap(mesh, 10, "test");
  const std::string message = surface_error(mesh, 10);
  EXPECT_THAT(message, HasSubstr("side set 10 is a gap the mesh was split at"));
}

TEST(ContactSurface, EmptySideSet)
{
  Mesh mesh = box("HEX8");
  kiln::SideSet empty;
  empty.id = 20;
  mesh.side_sets.push_back(empty);
  EXPECT_THAT(surface_error(mesh, 20), HasSubstr("side set 20 has no faces"));
}

TEST(ContactSurface, FaceListedTwice)
{
  Mesh mesh = box("HEX8");
  kiln::SideSet twice = *mesh.find_side_set(6);
  twice.id = 20;
  twice.cells.push_back(twice.cells[1]);
  twice.faces.push_back(twice.faces[1]);
  mesh.side_sets.push_back(twice);
  EXPECT_THAT(surface_error(mesh, 20),
              HasSubstr("side set 20 lists cell " +
                        std::to_string(mesh.find_side_set(6)->cells[1] + 1) + ", side 6 twice"));
}

TEST(ContactSurface, QuadraticFaces)
{
  const std::string message = surface_error(box("HEX20"), 6);
  EXPECT_THAT(message, HasSubstr("side set 6 has a QUAD8 face"));
  EXPECT_THAT(message, HasSubstr("linear faces only"));
}
