// The heat cells of a contact pair rebuilt at a search redone during a run (issue 30;
// PairGapHeat::rebuild, doc/heat.md "Heat across the gap of a mortar pairing"). Two flat bodies
// meshed alike (tests/support/two_body_mesh: 4 x 4 faces of 0.25 m each, the gap 0.01 m):
// rebuilt at u = 0 the cells are those of set-up bit for bit; with the secondary body shifted
// rigidly by one face along x each cell pairs a secondary face with the primary face one
// column over, whole (its weights summing to the face's area); shifted by two faces with a
// margin of one, a RunError naming the pair and what to change, the cells unchanged.
#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "mesh/contact_surface.hpp"
#include "physics/heat/mortar_gap_heat.hpp"
#include "physics/heat/pair_gap_heat.hpp"
#include "support/two_body_mesh.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace
{
using kiln::MortarGapCell;
using kiln::PairGapHeat;
using kiln::Point;

constexpr double face = 0.25; // the faces' edge [m]

/// The pair's heat: a constant conductance, primary side set 1, secondary 2, the search
/// within 0.05 m and `sliding` [m] more for the margins.
PairGapHeat heat_of(const kiln::Mesh &mesh, const double sliding)
{
  Teuchos::ParameterList user;
  user.set("Conductance", 10.0);
  const std::string where = "Kiln/Mechanics/Contact/Pairs/test/Heat Transfer";
  return PairGapHeat(
      mesh, 1, 2, 0.05, sliding,
      kiln::validated(user, kiln::MortarGapHeat::valid_parameters(), "test.xml", where), where);
}

/// u per surface node: the secondary body (z > 0) moved by `shift` along x.
std::vector<Point> shifted(const kiln::Mesh &mesh, const PairGapHeat &heat, const double shift)
{
  std::vector<Point> u;
  for (const int n : heat.surface_nodes())
    u.push_back({mesh.coordinates[n][2] > 0.0 ? shift : 0.0, 0.0, 0.0});
  return u;
}

bool same_bits(const double a, const double b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}

bool same_bits(const Point &a, const Point &b)
{
  return same_bits(a[0], b[0]) && same_bits(a[1], b[1]) && same_bits(a[2], b[2]);
}

/// The centre of face f of `surface` in the reference configuration [m].
Point centre(const kiln::ContactSurface &surface, const int f)
{
  Point c{0, 0, 0};
  const auto nodes = surface.face_nodes(f);
  for (const int j : nodes)
    for (int d = 0; d < 3; ++d)
      c[d] += surface.positions()[j][d] / nodes.size();
  return c;
}

TEST(PairGapHeatRebuild, AtZeroDisplacementTheSetUpCellsBitForBit)
{
  const kiln::Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {4, 4}, 0.01);
  PairGapHeat heat = heat_of(mesh, 0.0);
  const PairGapHeat::CellSet before = heat.cell_set();
  ASSERT_EQ(before.cells.size(), 16u);
  EXPECT_TRUE(heat.searched_displacement().empty());
  heat.rebuild(shifted(mesh, heat, 0.0), 1.0, "pair \"test\"");
  ASSERT_EQ(heat.cells().size(), before.cells.size());
  EXPECT_EQ(heat.searched_displacement().size(), heat.surface_nodes().size());
  for (std::size_t k = 0; k < before.cells.size(); ++k)
  {
    const MortarGapCell &a = before.cells[k];
    const MortarGapCell &b = heat.cells()[k];
    EXPECT_EQ(a.secondary_face, b.secondary_face);
    EXPECT_EQ(a.primary_face, b.primary_face);
    EXPECT_TRUE(same_bits(a.normal, b.normal));
    ASSERT_EQ(a.points.size(), b.points.size());
    for (std::size_t q = 0; q < a.points.size(); ++q)
    {
      EXPECT_TRUE(same_bits(a.points[q].xi_s, b.points[q].xi_s));
      EXPECT_TRUE(same_bits(a.points[q].xi_m, b.points[q].xi_m));
      EXPECT_TRUE(same_bits(a.points[q].weight, b.points[q].weight));
    }
    EXPECT_EQ(before.nodes[k], heat.cell_nodes(k));
    EXPECT_EQ(before.owning_cells[k], heat.owning_cell(k));
  }
}

TEST(PairGapHeatRebuild, ShiftedByAFaceThePairsOfShiftedFaces)
{
  const kiln::Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {4, 4}, 0.01);
  PairGapHeat heat = heat_of(mesh, face);
  heat.rebuild(shifted(mesh, heat, face), 2.0, "pair \"test\"");
  const kiln::ContactSurface primary(mesh, 1, "test");
  const kiln::ContactSurface secondary(mesh, 2, "test");
  // The last column of secondary faces lies beyond the primary surface (touching its edge).
  ASSERT_EQ(heat.cells().size(), 12u);
  for (const MortarGapCell &cell : heat.cells())
  {
    const Point s = centre(secondary, cell.secondary_face);
    const Point m = centre(primary, cell.primary_face);
    EXPECT_NEAR(m[0], s[0] + face, 1e-12);
    EXPECT_NEAR(m[1], s[1], 1e-12);
    double area = 0.0;
    for (const auto &point : cell.points)
      area += point.weight;
    EXPECT_NEAR(area, face * face, 1e-14);
  }
  // Every cell's nodes are in the Jacobian graph's blocks (margin_blocks()).
  const auto blocks = heat.margin_blocks();
  for (std::size_t k = 0; k < heat.cells().size(); ++k)
  {
    bool held = false;
    for (const auto &[cell, nodes] : blocks)
      held = held || (cell == heat.owning_cell(k) && nodes == heat.cell_nodes(k));
    EXPECT_TRUE(held) << "cell " << k;
  }
}

TEST(PairGapHeatRebuild, BeyondTheMarginARunErrorAndTheCellsKept)
{
  const kiln::Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {4, 4}, 0.01);
  PairGapHeat heat = heat_of(mesh, 0.0); // the margin: the faces touching each one's box
  const std::size_t n_cells = heat.cells().size();
  try
  {
    heat.rebuild(shifted(mesh, heat, 2 * face), 3.0, "pair \"test\"");
    FAIL() << "no RunError";
  }
  catch (const kiln::RunError &e)
  {
    using testing::HasSubstr;
    const std::string message = e.what();
    EXPECT_THAT(message, HasSubstr("pair \"test\": at t = 3 s the heat across the gap"));
    EXPECT_THAT(message, HasSubstr("outside its margin of set-up"));
    EXPECT_THAT(message, HasSubstr("small-sliding limit"));
    EXPECT_THAT(message, HasSubstr("raise the pair's \"Sliding Distance\""));
  }
  EXPECT_EQ(heat.cells().size(), n_cells);
  EXPECT_TRUE(heat.searched_displacement().empty());
}
} // namespace
