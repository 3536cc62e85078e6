// Tests src/contact/mortar_pairing.cpp: the rows of a contact pair between separately meshed
// bodies (issue 30). On two flat bodies (4x4 against 5x3 faces, rotated): a row per secondary
// node, sum D_jj = the area to 1e-14, the weights summing to 1, g0_j = the gap = n_j . (X_j -
// sum_k w_jk X_k) and the twin point on the primary plane to 1e-12. On the box generator's two
// halves meshed apart (4x4x4 against 5x3x6 cells, rotated by phi = 45, theta = -30), touching
// and apart by "Gap Width". On two curved shells: rows with radial normals and the gap within
// the facets' sag. Each row's small-sliding limit: Search Update Fraction times the smallest
// diameter of its node's faces. Each input error once. Every rank computes the same rows (np 2).
// KILN_TEST_NP: 1 2
#include "base/errors.hpp"
#include "contact/mortar_pairing.hpp"
#include "contact/pair_research.hpp"
#include "contact/pair_search_again.hpp"
#include "contact/small_sliding.hpp"
#include "contact/surface_displacement.hpp"

#include "mesh/box_mesh_generator.hpp"
#include "mesh/contact_surface.hpp"
#include "support/parameter_lists.hpp"
#include "support/two_body_mesh.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_Tuple.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace
{
using kiln::ContactRow;
using kiln::dot;
using kiln::Mesh;
using kiln::MortarPairing;
using kiln::MortarPairingOptions;
using kiln::Point;
using testing::HasSubstr;

const std::string pair = "in.xml: Mechanics/Contact/Pairs/\"Halves\"";

Point operator-(const Point &a, const Point &b)
{
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

/// The twin point sum_k w_jk X_k of a row.
Point twin_point(const Mesh &mesh, const ContactRow &row)
{
  Point y{0, 0, 0};
  for (std::size_t k = 0; k < row.partners.size(); ++k)
    for (int d = 0; d < 3; ++d)
      y[d] += row.weights[k] * mesh.coordinates[row.partners[k]][d];
  return y;
}

/// The checks of a pair of flat surfaces: the primary in the plane through `on_primary` with
/// unit normal `normal` (from the primary to the secondary), the secondary `gap` beyond it,
/// both of area `area`; every node of the secondary side set has a row.
void expect_flat_rows(const Mesh &mesh, const MortarPairing &pairing, const int secondary,
                      const Point &normal, const Point &on_primary, const double gap,
                      const double area)
{
  const kiln::ContactSurface surface(mesh, secondary, pair);
  ASSERT_EQ(pairing.rows().size(), surface.nodes().size());
  double sum_D = 0.0;
  for (std::size_t r = 0; r < pairing.rows().size(); ++r)
  {
    const ContactRow &row = pairing.rows()[r];
    SCOPED_TRACE("secondary node " + std::to_string(row.node));
    EXPECT_EQ(row.node, surface.nodes()[r]);
    sum_D += row.area;
    EXPECT_GT(row.area, 0.0);
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(row.normal[d], normal[d], 1e-14);
    ASSERT_EQ(row.partners.size(), row.weights.size());
    ASSERT_FALSE(row.partners.empty());
    double sum_w = 0.0;
    for (std::size_t k = 0; k < row.weights.size(); ++k)
    {
      sum_w += row.weights[k];
      if (k > 0)
      {
        EXPECT_LT(row.partners[k - 1], row.partners[k]);
      }
    }
    EXPECT_NEAR(sum_w, 1.0, 1e-14);
    EXPECT_NEAR(row.gap0, gap, 1e-12);
    const Point twin = twin_point(mesh, row);
    EXPECT_NEAR(row.gap0, dot(row.normal, mesh.coordinates[row.node] - twin), 1e-12);
    EXPECT_NEAR(dot(normal, twin - on_primary), 0.0, 1e-12); // on the primary plane
  }
  EXPECT_NEAR(sum_D, area, 1e-14 * area);
}

/// The rows are the same on every rank: rank 0's count and sums, broadcast and compared.
void expect_same_on_every_rank(const MortarPairing &pairing)
{
  double mine[3] = {static_cast<double>(pairing.rows().size()), 0.0, 0.0};
  for (const ContactRow &row : pairing.rows())
  {
    mine[1] += row.area * (row.node + 1) + row.gap0;
    for (std::size_t k = 0; k < row.partners.size(); ++k)
      mine[2] += row.weights[k] * (row.partners[k] + 1);
  }
  double first[3] = {mine[0], mine[1], mine[2]};
  MPI_Bcast(first, 3, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(mine[i], first[i]) << "sum " << i;
}

/// The message of the InputError that the pairing throws, or "".
std::string pairing_error(const Mesh &mesh, const int primary, const int secondary,
                          const MortarPairingOptions &options = {})
{
  return kiln_test::input_error_message(
      [&] { MortarPairing(mesh, primary, secondary, options, pair); });
}

/// The rotation of the box tests (kiln_test::box_halves_parameters's).
constexpr double phi = 45.0, theta = -30.0;

Point rotated(const Point &x)
{
  return kiln_test::rotated(x, phi, theta);
}
} // namespace

TEST(MortarPairing, FlatBodiesRotated)
{
  const double gap = 0.01;
  Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {5, 3}, gap);
  kiln_test::rotate(mesh, phi, theta);
  // Side set 1: body 1's top (z = 0) facing +z; 2: body 2's bottom.
  const MortarPairing pairing(mesh, 1, 2, {}, pair);
  expect_flat_rows(mesh, pairing, 2, rotated({0, 0, 1}), {0, 0, 0}, gap, 1.0);
  expect_same_on_every_rank(pairing);
  // The default reach: one secondary face diameter.
  EXPECT_NEAR(pairing.search_distance(), std::sqrt(0.2 * 0.2 + 1.0 / 9), 1e-15);

  // The other way round: the 4x4 side is the secondary.
  const MortarPairing reversed(mesh, 2, 1, {}, pair);
  expect_flat_rows(mesh, reversed, 1, rotated({0, 0, -1}), rotated({0, 0, gap}), gap, 1.0);
}

TEST(MortarPairing, FlatBodiesTouchingAndPartners)
{
  const Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {5, 3}, 0.0);
  const MortarPairing pairing(mesh, 1, 2, {}, pair);
  expect_flat_rows(mesh, pairing, 2, {0, 0, 1}, {0, 0, 0}, 0.0, 1.0);
  // The corner node (0, 0) of the secondary lies on the primary's corner node: its twin point
  // is that node, though its partners are the nodes of the primary face it lies on.
  const ContactRow &corner = pairing.rows().front();
  const Point twin = twin_point(mesh, corner);
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(twin[d], mesh.coordinates[corner.node][d], 1e-14);
  const kiln::ContactSurface primary(mesh, 1, pair);
  for (const ContactRow &row : pairing.rows())
    for (const int k : row.partners)
      EXPECT_GE(primary.surface_node(k), 0) << "partner " << k << " of node " << row.node;
}

/// The contact box (0.04 m, rotated by phi, theta) with halves 4x4x4 and 5x3x6 meshed apart,
/// `gap` apart.
Mesh box_halves(const double gap)
{
  return kiln::BoxMeshGenerator(kiln_test::box_halves_parameters(gap), "test/Box").generate();
}

TEST(MortarPairing, BoxHalvesTouching)
{
  const Mesh mesh = box_halves(0.0);
  // Primary: block 1's cut face (4 x 4 faces); secondary: block 2's (3 x 6 faces, 4 x 7 nodes).
  const MortarPairing pairing(mesh, 10, 20, {}, pair);
  EXPECT_EQ(pairing.rows().size(), 28u);
  expect_flat_rows(mesh, pairing, 20, rotated({1, 0, 0}), {0, 0, 0}, 0.0, 0.04 * 0.04);
  expect_same_on_every_rank(pairing);
}

TEST(MortarPairing, SmallSlidingLimit)
{
  // The box halves: every secondary face 0.04/3 x 0.04/6 m, so every row's face size is its
  // diagonal, and the limit "Search Update Fraction" (default 0.25) times it.
  const Mesh mesh = box_halves(0.0);
  const double diagonal = std::hypot(0.04 / 3, 0.04 / 6);
  MortarPairingOptions half;
  half.search_update_fraction = 0.5;
  const MortarPairing pairing(mesh, 10, 20, {}, pair), larger(mesh, 10, 20, half, pair);
  ASSERT_EQ(larger.rows().size(), pairing.rows().size());
  for (std::size_t r = 0; r < pairing.rows().size(); ++r)
  {
    EXPECT_NEAR(pairing.rows()[r].face_size, diagonal, 1e-15);
    EXPECT_NEAR(pairing.rows()[r].slip_limit, 0.25 * diagonal, 1e-15);
    EXPECT_NEAR(larger.rows()[r].slip_limit, 0.5 * diagonal, 1e-15);
  }
  // Perturbed faces: the smallest diameter of the node's faces.
  Mesh perturbed = kiln_test::two_flat_bodies({4, 4}, {5, 3}, 0.1);
  kiln_test::perturb(perturbed, 0.02);
  const MortarPairing rows(perturbed, 1, 2, {}, pair);
  const kiln::ContactSurface secondary(perturbed, 2, pair);
  std::vector<double> smallest(secondary.n_nodes(), 1e300);
  for (int f = 0; f < secondary.n_faces(); ++f)
    for (const int n : secondary.face_nodes(f))
      smallest[n] = std::min(smallest[n], secondary.face_diameter(f));
  int differ = 0;
  for (const ContactRow &row : rows.rows())
  {
    const double size = smallest[secondary.surface_node(row.node)];
    EXPECT_EQ(row.face_size, size) << "node " << row.node;
    EXPECT_EQ(row.slip_limit, 0.25 * size) << "node " << row.node;
    differ += std::abs(size - rows.rows().front().face_size) > 1e-6;
  }
  EXPECT_GT(differ, 0) << "the perturbation leaves the sizes alike";
}

TEST(MortarPairing, BoxHalvesApart)
{
  const double g = 2e-6;
  const Mesh mesh = box_halves(g);
  const MortarPairing pairing(mesh, 10, 20, {}, pair);
  expect_flat_rows(mesh, pairing, 20, rotated({1, 0, 0}), {0, 0, 0}, g, 0.04 * 0.04);
  // The other way round.
  const MortarPairing reversed(mesh, 20, 10, {}, pair);
  EXPECT_EQ(reversed.rows().size(), 25u);
  expect_flat_rows(mesh, reversed, 10, rotated({-1, 0, 0}), rotated({g, 0, 0}), g, 0.04 * 0.04);
}

TEST(MortarPairing, CurvedShells)
{
  // Body 1 (radii 1.5 .. 2) outer face = side set 1, body 2 (2 + gap .. 2.5) inner = 2.
  const double gap = 0.05;
  Mesh mesh = kiln_test::two_cylinder_shells({4, 4}, {5, 3}, gap);
  kiln_test::rotate(mesh, phi, theta);
  const MortarPairing pairing(mesh, 1, 2, {}, pair);
  const kiln::ContactSurface surface(mesh, 2, pair);
  ASSERT_EQ(pairing.rows().size(), surface.nodes().size());
  const Point axis = rotated({0, 0, 1});
  // The facets' sags: the primary's (radius 2, 0.25 rad) and the secondary's (2.05, 0.2 rad)
  // move the faceted gap off the radial one by at most their sum.
  const double sag = 2 * (1 - std::cos(0.125)) + (2 + gap) * (1 - std::cos(0.1));
  double sum_D = 0.0, faceted_area = 0.0;
  for (int f = 0; f < surface.n_faces(); ++f)
    faceted_area += std::sqrt(dot(surface.face_area_vector(f), surface.face_area_vector(f)));
  for (const ContactRow &row : pairing.rows())
  {
    SCOPED_TRACE("secondary node " + std::to_string(row.node));
    sum_D += row.area;
    double sum_w = 0.0;
    for (const double w : row.weights)
      sum_w += w;
    EXPECT_NEAR(sum_w, 1.0, 1e-14);
    // Radial: normal to the axis, along the node's position off it.
    const Point &x = mesh.coordinates[row.node];
    const double along = dot(x, axis);
    const Point radial{x[0] - along * axis[0], x[1] - along * axis[1], x[2] - along * axis[2]};
    EXPECT_NEAR(dot(row.normal, axis), 0.0, 1e-14);
    EXPECT_GT(dot(row.normal, radial) / std::sqrt(dot(radial, radial)), std::cos(0.1 + 1e-12));
    EXPECT_NEAR(row.gap0, gap, sag);
  }
  // The ends of the arc: the secondary's faces at angles 0 and 1 project slightly past the
  // primary's; the rest is covered.
  EXPECT_NEAR(sum_D, faceted_area, 0.01 * faceted_area);
  expect_same_on_every_rank(pairing);
}

TEST(MortarPairing, OneSideSetTwice)
{
  const Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {5, 3}, 0.01);
  EXPECT_THAT(pairing_error(mesh, 2, 2),
              HasSubstr(pair + ": \"Primary Side Set\" and \"Secondary Side Set\" are both side "
                               "set 2"));
}

TEST(MortarPairing, AbsentSideSet)
{
  const Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {5, 3}, 0.01);
  EXPECT_THAT(pairing_error(mesh, 1, 7),
              HasSubstr(pair + "/\"Secondary Side Set\": side set 7 is not in the mesh"));
}

TEST(MortarPairing, QuadraticFaces)
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  p.set("Cells", Teuchos::Array<int>(Teuchos::tuple(2, 2, 2)));
  p.set("Cell Type", "HEX20");
  const Mesh mesh = kiln::BoxMeshGenerator(p, "test/Box").generate();
  EXPECT_THAT(pairing_error(mesh, 5, 6),
              HasSubstr(pair + "/\"Primary Side Set\": side set 5 has a QUAD8 face"));
}

TEST(MortarPairing, SurfacesThatDoNotFace)
{
  const Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {5, 3}, 0.5);
  MortarPairingOptions options;
  options.search_distance = 0.2;
  EXPECT_THAT(pairing_error(mesh, 1, 2, options),
              HasSubstr(pair + ": side sets 1 (primary) and 2 (secondary) do not face each other"));
}

TEST(MortarPairing, InterpenetratingBodies)
{
  // Body 2 starts 1 mm inside body 1.
  const Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {5, 3}, -0.001);
  const std::string message = pairing_error(mesh, 1, 2);
  EXPECT_THAT(message, HasSubstr(pair + ": the bodies interpenetrate: secondary node "));
  EXPECT_THAT(message, HasSubstr("(side set 2) at (0, 0, -0.001) m lies 0.001 m inside the "
                                 "primary body (side set 1), more than \"Penetration "
                                 "Tolerance\" 1e-09 m"));
  // Within a tolerance, accepted.
  MortarPairingOptions options;
  options.penetration_tolerance = 0.002;
  EXPECT_EQ(pairing_error(mesh, 1, 2, options), "");
}

TEST(MortarPairing, NoSecondaryNodeCovered)
{
  // Body 2 moved along x past body 1's edge by 0.05 m: within reach, facing, no overlap.
  Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {5, 3}, 0.01);
  std::vector<bool> in_body_2(mesh.n_nodes(), false);
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (mesh.block_id[c] == 2)
      for (const int n : mesh.cell_nodes(c))
        in_body_2[n] = true;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (in_body_2[n])
      mesh.coordinates[n][0] += 1.05;
  const std::string message = pairing_error(mesh, 1, 2);
  EXPECT_THAT(message, HasSubstr(pair + ": no node of the secondary side set 2 is covered by "
                                        "the primary side set 1"));
}

/// The displacement per mesh node: `a` on the nodes of block `block`'s cells, 0 elsewhere.
std::vector<Point> moved_block(const Mesh &mesh, const int block, const Point &a)
{
  std::vector<Point> u(static_cast<std::size_t>(mesh.n_nodes()), Point{0, 0, 0});
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (mesh.block_id[c] == block)
      for (const int n : mesh.cell_nodes(c))
        u[n] = a;
  return u;
}

TEST(MortarPairing, MarginsHoldThePartnersAndGrowWithTheSlidingDistance)
{
  const Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {5, 3}, 0.01);
  MortarPairingOptions wider;
  wider.sliding_distance = 0.3;
  const MortarPairing pairing(mesh, 1, 2, {}, pair), wide(mesh, 1, 2, wider, pair);
  ASSERT_EQ(pairing.margins().size(), pairing.rows().size());
  ASSERT_EQ(wide.rows().size(), pairing.rows().size());
  std::size_t grown = 0;
  for (std::size_t r = 0; r < pairing.rows().size(); ++r)
  {
    const std::vector<int> &margin = pairing.margins()[r];
    EXPECT_TRUE(std::is_sorted(margin.begin(), margin.end()));
    for (const int k : pairing.rows()[r].partners)
      EXPECT_TRUE(std::binary_search(margin.begin(), margin.end(), k))
          << "partner " << k << " of row " << r << " outside its margin";
    EXPECT_TRUE(std::includes(wide.margins()[r].begin(), wide.margins()[r].end(), margin.begin(),
                              margin.end()));
    grown += wide.margins()[r].size() > margin.size() ? 1 : 0;
  }
  EXPECT_GT(grown, 0u);
}

TEST(MortarPairing, InTheCurrentConfiguration)
{
  // Both bodies moved alike: the same rows as in the reference configuration.
  const Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {5, 3}, 0.01);
  const MortarPairing reference(mesh, 1, 2, {}, pair);
  // u is asked for at the surfaces' nodes only (the search holds no per-mesh-node vector).
  const kiln::PairResearch research(mesh, 1, 2, {}, pair, "pair \"test\"", reference.margins());
  const std::vector<int> &surfaces = research.surface_nodes();
  ASSERT_LT(surfaces.size(), static_cast<std::size_t>(mesh.n_nodes()));
  int off_surfaces = 0;
  const MortarPairing moved(mesh, 1, 2, {}, pair,
                            [&](const int node)
                            {
                              if (!std::binary_search(surfaces.begin(), surfaces.end(), node))
                                ++off_surfaces;
                              return Point{0.03, -0.02, 0.05};
                            });
  EXPECT_EQ(off_surfaces, 0);
  EXPECT_TRUE(moved.margins().empty());
  ASSERT_EQ(moved.rows().size(), reference.rows().size());
  for (std::size_t r = 0; r < moved.rows().size(); ++r)
  {
    const ContactRow &a = moved.rows()[r], &b = reference.rows()[r];
    EXPECT_EQ(a.node, b.node);
    EXPECT_EQ(a.partners, b.partners);
    EXPECT_NEAR(a.area, b.area, 1e-14);
    EXPECT_NEAR(a.gap0, b.gap0, 1e-14);
    for (std::size_t k = 0; k < a.weights.size(); ++k)
      EXPECT_NEAR(a.weights[k], b.weights[k], 1e-12);
  }
}

/// `u` (per mesh node) at the nodes of `research`'s surfaces, in their order (rows_at's u).
std::vector<Point> on_surfaces(const kiln::PairResearch &research, const std::vector<Point> &u)
{
  std::vector<Point> values;
  for (const int n : research.surface_nodes())
    values.push_back(u[n]);
  return values;
}

/// The search of the flat bodies' pair (side sets 1 and 2) redone within `pairing`'s margins.
kiln::PairResearch research_of(const Mesh &mesh, const MortarPairing &pairing,
                               const MortarPairingOptions &options)
{
  return kiln::PairResearch(mesh, 1, 2, options, pair, "pair \"test\"", pairing.margins());
}

TEST(PairResearch, RowsRebuiltAfterASlideKeepTheGapContinuous)
{
  // Body 2 (the secondary, 5 x 3 faces) slid by 0.1 m along x and 0.004 m towards body 1:
  // the new rows pair each node with the primary nodes under its current position, the gap
  // at that state is the old rows' (g0' + n.d' = g0 + n.d) and the slip is measured from it.
  const Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {5, 3}, 0.01);
  MortarPairingOptions options;
  options.sliding_distance = 0.3;
  const MortarPairing pairing(mesh, 1, 2, options, pair);
  const kiln::PairResearch research = research_of(mesh, pairing, options);
  const std::vector<Point> u = moved_block(mesh, 2, {0.1, 0.0, -0.004});
  const auto u_of = [&u](const int node) { return u[node]; };
  const std::vector<ContactRow> rows =
      research.rows_at(pairing.rows(), on_surfaces(research, u), 3.0);
  ASSERT_EQ(rows.size(), pairing.rows().size());
  int moved_partners = 0;
  for (std::size_t r = 0; r < rows.size(); ++r)
  {
    const ContactRow &old = pairing.rows()[r], &row = rows[r];
    EXPECT_EQ(row.node, old.node);
    EXPECT_EQ(row.normal, old.normal);
    EXPECT_EQ(row.slip_limit, old.slip_limit);
    const Point d_old = kiln::row_relative_displacement(old, u_of);
    const Point d_new = kiln::row_relative_displacement(row, u_of);
    EXPECT_NEAR(row.gap0 + dot(row.normal, d_new), old.gap0 + dot(old.normal, d_old), 1e-15);
    EXPECT_NEAR(row.gap0 + dot(row.normal, d_new), 0.006, 1e-14);
    EXPECT_EQ(row.slip0, d_new);
    EXPECT_EQ(kiln::row_slip(row, u_of), 0.0);
    // The twin point of the new weights in X + u: below node j's current position.
    Point twin{0, 0, 0};
    for (std::size_t k = 0; k < row.partners.size(); ++k)
      for (int i = 0; i < 2; ++i)
        twin[i] += row.weights[k] * (mesh.coordinates[row.partners[k]][i] + u[row.partners[k]][i]);
    for (int i = 0; i < 2; ++i)
      EXPECT_NEAR(twin[i], mesh.coordinates[row.node][i] + u[row.node][i], 1e-12) << "row " << r;
    moved_partners += row.partners != old.partners ? 1 : 0;
  }
  EXPECT_GT(moved_partners, 0);
  // The same from the rows of that search, for a state that has not moved since: unchanged.
  const std::vector<ContactRow> again = research.rows_at(rows, on_surfaces(research, u), 4.0);
  for (std::size_t r = 0; r < rows.size(); ++r)
  {
    EXPECT_EQ(again[r].partners, rows[r].partners);
    EXPECT_NEAR(again[r].gap0, rows[r].gap0, 1e-15);
  }
}

TEST(PairResearch, SurfaceDisplacementGatheredFromTheOwners)
{
  // The surfaces' nodes owned in turn by the ranks (a surface split across all of them): every
  // rank gets each node's u from its owner, aligned with surface_nodes(), and u is asked for
  // at the nodes this rank owns only.
  const Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {5, 3}, 0.01);
  const MortarPairing pairing(mesh, 1, 2, {}, pair);
  const kiln::PairResearch research = research_of(mesh, pairing, {});
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const int rank = comm->getRank(), n_ranks = comm->getSize();
  std::vector<int> owner(static_cast<std::size_t>(mesh.n_nodes()));
  for (int n = 0; n < mesh.n_nodes(); ++n)
    owner[n] = (n / 3) % n_ranks;
  const auto exact = [](const int n) { return Point{1e-3 * n, -2e-3 * n, 0.5 + n}; };
  int not_owned = 0;
  const std::vector<Point> u = kiln::gather_displacement(
      research.surface_nodes(),
      [&](const int n)
      {
        not_owned += owner[n] != rank ? 1 : 0;
        return exact(n);
      },
      owner, *comm);
  EXPECT_EQ(not_owned, 0);
  ASSERT_EQ(u.size(), research.surface_nodes().size());
  for (std::size_t i = 0; i < u.size(); ++i)
  {
    const int n = research.surface_nodes()[i];
    EXPECT_EQ(u[i], exact(n)) << "node " << n;
    EXPECT_EQ(research.surface_index(n), i);
  }
}

TEST(PairResearch, PartnersBeyondTheMarginEndTheRun)
{
  // A reach of 0.011 m and no sliding distance: the margins are the primary faces within
  // 0.011 m of each node's faces, and a slide by 0.45 m along x (almost two primary faces)
  // pairs nodes with primary nodes outside them (or off the primary surface).
  const Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {5, 3}, 0.01);
  MortarPairingOptions options;
  options.search_distance = 0.011;
  const MortarPairing pairing(mesh, 1, 2, options, pair);
  const kiln::PairResearch research = research_of(mesh, pairing, options);
  try
  {
    (void)research.rows_at(pairing.rows(),
                           on_surfaces(research, moved_block(mesh, 2, {0.45, 0.0, 0.0})), 7.5);
    ADD_FAILURE() << "no error";
  }
  catch (const kiln::RunError &e)
  {
    const std::string what = e.what();
    EXPECT_THAT(what, HasSubstr("pair \"test\": at t = 7.5 s secondary node "));
    EXPECT_THAT(what, testing::AnyOf(HasSubstr("outside the margin of primary faces"),
                                     HasSubstr("has slid off the primary surface")));
    EXPECT_THAT(what, HasSubstr("\"Sliding Distance\""));
  }
  // Within the margin of a larger sliding distance: no error.
  options.sliding_distance = 0.5;
  const MortarPairing wide(mesh, 1, 2, options, pair);
  const kiln::PairResearch within = research_of(mesh, wide, options);
  EXPECT_NO_THROW((void)within.rows_at(
      wide.rows(), on_surfaces(within, moved_block(mesh, 2, {0.05, 0.0, 0.0})), 1.0));
}
