// Tests the mortar geometry of src/contact (MortarSegments, DualBasis, MortarFaceIntegrals) on
// the cases of benchmarks/moertel_probe (doc/contact.md, "Separately meshed bodies (issue 30):
// design"): two non-matching surfaces on the unit square, the primary at z = 0 facing +z, the
// secondary at z = d facing it, every secondary face integrated against every primary face (no
// search). Checks: D diagonal, sum D = the covered area, the row sums of M = D_jj (flat), the
// weighted gap / D_jj = d, the twin point Σ M_jk x_k / D_jj; rotated in 3D, on a cylinder, with
// a column of faces partly covered, with triangles, with distorted quadrilaterals; the dual
// basis on a quarter of a face; and an overlap computed by hand.
#include "base/errors.hpp"
#include "contact/dual_basis.hpp"
#include "contact/mortar_face_integrals.hpp"
#include "contact/mortar_segments.hpp"
#include "elements/finite_element.hpp"
#include "support/tensors.hpp"
#include "support/two_body_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace
{
using kiln::CellType;
using kiln::MortarFace;
using kiln::Point;

/// A surface: nodes and faces (node numbers, in the face's own order).
struct Surface
{
  CellType type = CellType::quad4;
  std::vector<Point> x;
  std::vector<std::vector<int>> faces;
  /// Face f's nodes' coordinates (kept here so that the MortarFace's span stays valid).
  std::vector<std::vector<Point>> face_x;
  MortarFace face(const int f) const { return {type, face_x[f]}; }
  int n_faces() const { return static_cast<int>(faces.size()); }
};

using Placement = std::function<Point(double x, double y)>;

/// nx x ny faces on [0, 1]^2 placed by `place`, facing +z (or -z if `facing_down`), as QUAD4
/// or each cut into two TRI3.
Surface grid(const int nx, const int ny, const Placement &place, const bool facing_down,
             const bool triangles = false)
{
  Surface s;
  s.type = triangles ? CellType::tri3 : CellType::quad4;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      s.x.push_back(place(static_cast<double>(i) / nx, static_cast<double>(j) / ny));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
    {
      std::vector<int> c = {j * (nx + 1) + i, j * (nx + 1) + i + 1, (j + 1) * (nx + 1) + i + 1,
                            (j + 1) * (nx + 1) + i};
      if (facing_down)
        std::swap(c[1], c[3]);
      if (triangles)
      {
        s.faces.push_back({c[0], c[1], c[2]});
        s.faces.push_back({c[0], c[2], c[3]});
      }
      else
        s.faces.push_back(c);
    }
  for (const std::vector<int> &f : s.faces)
  {
    s.face_x.emplace_back();
    for (const int n : f)
      s.face_x.back().push_back(s.x[n]);
  }
  return s;
}

/// The rotation of the probe: by a about x, then by b about y.
Point rotate(const Point &p, const double a, const double b)
{
  const double y1 = std::cos(a) * p[1] - std::sin(a) * p[2],
               z1 = std::sin(a) * p[1] + std::cos(a) * p[2];
  return {std::cos(b) * p[0] + std::sin(b) * z1, y1, -std::sin(b) * p[0] + std::cos(b) * z1};
}

/// A pair of surfaces: the primary's and the secondary's faces (nx, ny, triangles or not).
struct Layout
{
  int nx_m = 4, ny_m = 4, nx_s = 5, ny_s = 3;
  bool triangles_m = false, triangles_s = false;
  double offset = 0.01; ///< d: the secondary's height above the primary (before the rotation)
  double shift = 0.0;   ///< the secondary moved along x by this
  double radius = 0.0;  ///< > 0: both on the cylinder z = R - sqrt(R^2 - (x - 1/2)^2)
  /// Moves the inner nodes in the plane (the primary's one way, the secondary's the other):
  /// quadrilaterals that are no parallelograms.
  double distortion = 0.0;
  double angles[2] = {0, 0};
};

/// The mortar integrals of a layout, summed by node: D (secondary x secondary), M (secondary x
/// primary), the weighted gap per secondary node.
struct Assembled
{
  Surface primary, secondary;
  std::vector<std::vector<double>> D, M;
  std::vector<double> gap;
  Point normal{0, 0, 1}; ///< the rotated z axis: from the primary to the secondary
};

Assembled assemble(const Layout &l)
{
  Assembled a;
  const auto placement = [&l](const double height, const double shift, const double distortion)
  {
    return [&l, height, shift, distortion](const double x0, const double y0)
    {
      const double pi = std::acos(-1.0);
      const double x = x0 + distortion * x0 * (1 - x0) * std::sin(2 * pi * y0),
                   y = y0 + distortion * y0 * (1 - y0) * std::sin(2 * pi * x0);
      const double d = x - 0.5;
      const double z = (l.radius > 0 ? l.radius - std::sqrt(l.radius * l.radius - d * d) : 0.0);
      return rotate({x + shift, y, z + height}, l.angles[0], l.angles[1]);
    };
  };
  a.primary = grid(l.nx_m, l.ny_m, placement(0.0, 0.0, l.distortion), false, l.triangles_m);
  a.secondary =
      grid(l.nx_s, l.ny_s, placement(l.offset, l.shift, -l.distortion), true, l.triangles_s);
  a.normal = rotate({0, 0, 1}, l.angles[0], l.angles[1]);
  const std::size_t n_s = a.secondary.x.size(), n_m = a.primary.x.size();
  a.D.assign(n_s, std::vector<double>(n_s, 0.0));
  a.M.assign(n_s, std::vector<double>(n_m, 0.0));
  a.gap.assign(n_s, 0.0);
  std::vector<MortarFace> primaries;
  for (int p = 0; p < a.primary.n_faces(); ++p)
    primaries.push_back(a.primary.face(p));
  for (int e = 0; e < a.secondary.n_faces(); ++e)
  {
    const kiln::MortarFaceIntegrals integrals(a.secondary.face(e), primaries);
    const std::vector<int> &nodes = a.secondary.faces[e];
    for (int i = 0; i < integrals.n_shape(); ++i)
    {
      for (int j = 0; j < integrals.n_shape(); ++j)
        a.D[nodes[i]][nodes[j]] += integrals.D(i, j);
      for (int p = 0; p < a.primary.n_faces(); ++p)
        for (std::size_t k = 0; k < a.primary.faces[p].size(); ++k)
          a.M[nodes[i]][a.primary.faces[p][k]] += integrals.M(i, p, static_cast<int>(k));
      a.gap[nodes[i]] += integrals.weighted_gap(i);
    }
  }
  return a;
}

double sum_D(const Assembled &a)
{
  double sum = 0;
  for (const auto &row : a.D)
    for (const double v : row)
      sum += v;
  return sum;
}

/// The checks of a flat pair with the secondary at height `offset`: D diagonal with D_jj > 0,
/// sum D = `area`, the row sums of M = D_jj, the weighted gap / D_jj = offset, and M
/// reproducing the primary's coordinates (linear in both bases): the twin point
/// Σ_k M_jk x_k / D_jj is x_j moved back across the gap, x_j - offset n.
void expect_flat_pair(const Assembled &a, const double offset, const double area,
                      const double twin_tolerance = 1e-12)
{
  EXPECT_NEAR(sum_D(a), area, 1e-14);
  for (std::size_t j = 0; j < a.D.size(); ++j)
  {
    const double Djj = a.D[j][j];
    EXPECT_GT(Djj, 0.0) << "node " << j;
    double off_diagonal = 0, row_M = 0;
    Point twin{0, 0, 0};
    for (std::size_t k = 0; k < a.D.size(); ++k)
      off_diagonal += k == j ? 0.0 : std::abs(a.D[j][k]);
    for (std::size_t k = 0; k < a.M[j].size(); ++k)
    {
      row_M += a.M[j][k];
      for (int d = 0; d < 3; ++d)
        twin[d] += a.M[j][k] * a.primary.x[k][d] / Djj;
    }
    // Round-off of the face's integrals (the surface's area is 1): D_jj is 4e-7 on a face
    // covered by 0.5%, its off-diagonal entries 2e-19.
    EXPECT_LT(off_diagonal, 1e-16 + 1e-14 * Djj) << "node " << j;
    EXPECT_NEAR(row_M, Djj, 1e-14) << "node " << j;
    EXPECT_NEAR(a.gap[j] / Djj, offset, 1e-12) << "node " << j;
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(twin[d], a.secondary.x[j][d] - offset * a.normal[d], twin_tolerance)
          << "node " << j << ", component " << d;
  }
}
} // namespace

TEST(MortarSegments, ClipsTwoUnitSquaresOffsetByHalfAndAQuarter)
{
  using kiln::internal::Point2;
  const std::vector<Point2> a = {{0, 0}, {1, 0}, {1, 1}, {0, 1}},
                            b = {{0.5, 0.25}, {1.5, 0.25}, {1.5, 1.25}, {0.5, 1.25}};
  const std::vector<Point2> overlap = kiln::internal::clip_polygon(b, a);
  EXPECT_DOUBLE_EQ(kiln::internal::signed_area(overlap), 0.375);
  ASSERT_EQ(overlap.size(), 4u);
  for (const Point2 &corner : {Point2{0.5, 0.25}, Point2{1, 0.25}, Point2{1, 1}, Point2{0.5, 1}})
    EXPECT_EQ(std::count(overlap.begin(), overlap.end(), corner), 1)
        << "(" << corner[0] << ", " << corner[1] << ")";
  // Apart, or touching along an edge: no overlap.
  const std::vector<Point2> apart = {{2, 0}, {3, 0}, {3, 1}, {2, 1}};
  EXPECT_TRUE(kiln::internal::clip_polygon(apart, a).empty());
}

TEST(MortarSegments, OverlapOfTwoFacingUnitSquaresIsTheHandComputedRectangle)
{
  // The secondary: the unit square at z = 0.1 facing down; the primary: the unit square moved
  // by (0.5, 0.25) at z = 0, facing up. Overlap [0.5, 1] x [0.25, 1], area 0.375.
  const std::vector<Point> xs = {{0, 0, 0.1}, {0, 1, 0.1}, {1, 1, 0.1}, {1, 0, 0.1}};
  const std::vector<Point> xm = {{0.5, 0.25, 0}, {1.5, 0.25, 0}, {1.5, 1.25, 0}, {0.5, 1.25, 0}};
  const MortarFace secondary{CellType::quad4, xs}, primary{CellType::quad4, xm};
  const kiln::MortarSegments segments(secondary, primary);
  EXPECT_NEAR(segments.area(), 0.375, 1e-15);
  EXPECT_NEAR(segments.normal()[2], -1.0, 1e-15);
  ASSERT_EQ(segments.polygon().size(), 4u);
  for (const Point &p : segments.polygon())
  {
    EXPECT_NEAR(p[2], 0.1, 1e-15); // on the secondary's plane
    EXPECT_TRUE(std::abs(p[0] - 0.5) < 1e-15 || std::abs(p[0] - 1) < 1e-15) << p[0];
    EXPECT_TRUE(std::abs(p[1] - 0.25) < 1e-15 || std::abs(p[1] - 1) < 1e-15) << p[1];
  }
  double weights = 0, first_moment_x = 0;
  for (const kiln::MortarPoint &q : segments.points())
  {
    weights += q.weight;
    const Point x_s = kiln::face_point(secondary, q.xi_s), x_m = kiln::face_point(primary, q.xi_m);
    EXPECT_NEAR(x_s[0], x_m[0], 1e-15); // the same point, seen on each face
    EXPECT_NEAR(x_s[1], x_m[1], 1e-15);
    EXPECT_NEAR(x_s[2] - x_m[2], 0.1, 1e-15);
    EXPECT_GE(x_s[0], 0.5 - 1e-15);
    EXPECT_GE(x_s[1], 0.25 - 1e-15);
    first_moment_x += q.weight * x_s[0];
  }
  EXPECT_NEAR(weights, 0.375, 1e-15);
  EXPECT_NEAR(first_moment_x / weights, 0.75, 1e-15); // the overlap's centroid
  // Moved apart: no segment.
  const std::vector<Point> far = {{2, 0, 0}, {3, 0, 0}, {3, 1, 0}, {2, 1, 0}};
  EXPECT_TRUE(kiln::MortarSegments(secondary, MortarFace{CellType::quad4, far}).empty());
}

TEST(DualBasis, IsBiorthogonalOnTheCoveredPart)
{
  // A quarter of the face covered: ∫ psi_i N_j = δ_ij ∫ N_j over the quarter, with the
  // quarter's integrals, not the whole face's.
  const std::vector<Point> xs = {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
  const std::vector<Point> xm = {{0.5, 0.5, -1}, {1.5, 0.5, -1}, {1.5, 1.5, -1}, {0.5, 1.5, -1}};
  const MortarFace secondary{CellType::quad4, xs};
  const kiln::MortarSegments segments(secondary, MortarFace{CellType::quad4, xm});
  ASSERT_NEAR(segments.area(), 0.25, 1e-15);
  const kiln::DualBasis dual(CellType::quad4, segments.points());
  const kiln::FiniteElement &fe = kiln::FiniteElement::of(CellType::quad4);
  double D[4][4] = {}, integral_N[4] = {};
  for (const kiln::MortarPoint &q : segments.points())
  {
    double psi[4], N[4];
    dual.values(q.xi_s, psi);
    fe.values(q.xi_s, N);
    for (int i = 0; i < 4; ++i)
    {
      integral_N[i] += N[i] * q.weight;
      for (int j = 0; j < 4; ++j)
        D[i][j] += psi[i] * N[j] * q.weight;
    }
  }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      EXPECT_NEAR(D[i][j], i == j ? integral_N[i] : 0.0, 1e-15) << i << ", " << j;
  // The node at the covered corner (1, 1) carries most, the opposite one least, all > 0.
  EXPECT_NEAR(integral_N[2], 0.25 * 0.75 * 0.75, 1e-15);
  EXPECT_NEAR(integral_N[0], 0.25 * 0.25 * 0.25, 1e-15);
  EXPECT_THROW(kiln::DualBasis(CellType::quad4, std::vector<kiln::MortarPoint>{}),
               kiln::InternalError);
}

TEST(MortarFaceIntegrals, Flat4x4Against5x3)
{
  for (const double d : {0.01, -0.01})
  {
    Layout l;
    l.offset = d;
    expect_flat_pair(assemble(l), d, 1.0);
  }
}

TEST(MortarFaceIntegrals, RotatedIn3D)
{
  for (const auto &[a, b] : {std::pair{0.3, 0.2}, std::pair{1.1, -0.7}})
    for (const double d : {0.01, -0.01})
    {
      SCOPED_TRACE("angles " + std::to_string(a) + ", " + std::to_string(b));
      Layout l;
      l.angles[0] = a;
      l.angles[1] = b;
      l.offset = d;
      expect_flat_pair(assemble(l), d, 1.0);
    }
}

TEST(MortarFaceIntegrals, MatchingFacesGiveTheNodalAreas)
{
  Layout l;
  l.nx_s = l.ny_s = 4;
  l.angles[0] = 0.3;
  l.angles[1] = 0.2;
  const Assembled a = assemble(l);
  expect_flat_pair(a, l.offset, 1.0);
  // Node by node: M = D on the twin (the node below), corners 1/64, edges 1/32, inside 1/16.
  for (std::size_t j = 0; j < a.D.size(); ++j)
  {
    const int i = static_cast<int>(j) % 5, k = static_cast<int>(j) / 5;
    const double expected = (i == 0 || i == 4 ? 0.5 : 1.0) * (k == 0 || k == 4 ? 0.5 : 1.0) / 16;
    EXPECT_NEAR(a.D[j][j], expected, 1e-15);
    EXPECT_NEAR(a.M[j][j], expected, 1e-15);
  }
}

TEST(MortarFaceIntegrals, Cylinder)
{
  // Both surfaces on the cylinder of radius 2 (axis along y), their nodes on one circle: sum D
  // is the secondary's faceted area; the weighted gaps are <= 0 (the secondary's nodes lie on
  // the circle, under the primary's chords) and above minus the primary facets' sagitta
  // h^2 / (8 R).
  Layout l;
  l.radius = 2.0;
  l.offset = 0.0;
  l.angles[0] = 0.3;
  l.angles[1] = 0.2;
  const Assembled a = assemble(l);
  double faceted_area = 0;
  for (int i = 0; i < l.nx_s; ++i)
  {
    const auto z = [&](const double x)
    { return l.radius - std::sqrt(l.radius * l.radius - (x - 0.5) * (x - 0.5)); };
    const double x0 = static_cast<double>(i) / l.nx_s, x1 = static_cast<double>(i + 1) / l.nx_s;
    faceted_area += std::hypot(x1 - x0, z(x1) - z(x0));
  }
  EXPECT_NEAR(sum_D(a), faceted_area, 1e-14);
  EXPECT_GT(faceted_area, 1.01); // not the flat area
  const double sagitta = 0.25 * 0.25 / (8 * l.radius);
  for (std::size_t j = 0; j < a.D.size(); ++j)
  {
    double row_M = 0, off_diagonal = 0;
    for (const double v : a.M[j])
      row_M += v;
    for (std::size_t k = 0; k < a.D.size(); ++k)
      off_diagonal += k == j ? 0.0 : std::abs(a.D[j][k]);
    EXPECT_LT(off_diagonal, 1e-16 + 1e-14 * a.D[j][j]);
    EXPECT_NEAR(row_M, a.D[j][j], 1e-14) << "node " << j;
    const double g = a.gap[j] / a.D[j][j];
    EXPECT_LT(g, 1e-15) << "node " << j;
    EXPECT_LT(std::abs(g), sagitta) << "node " << j;
    // On the end faces both facets are chords from the same point of the circle: the gap is
    // linear there, which the dual basis reproduces, and 0 at the end nodes.
    const int i = static_cast<int>(j) % (l.nx_s + 1);
    if (i == 0 || i == l.nx_s)
    {
      EXPECT_NEAR(g, 0.0, 1e-15) << "node " << j;
    }
  }
}

TEST(MortarFaceIntegrals, PartlyCoveredColumnOfFaces)
{
  // The secondary moved along x: its last column of faces (0.2 wide) half covered, then 0.5%.
  for (const double shift : {0.1, 0.199})
  {
    SCOPED_TRACE("shift " + std::to_string(shift));
    Layout l;
    l.shift = shift;
    l.angles[0] = 0.3;
    l.angles[1] = 0.2;
    expect_flat_pair(assemble(l), l.offset, 1.0 - shift);
  }
}

TEST(MortarFaceIntegrals, TrianglesAgainstQuadrilaterals)
{
  for (const bool secondary_triangles : {true, false})
  {
    SCOPED_TRACE(secondary_triangles ? "TRI3 secondary" : "TRI3 primary");
    Layout l;
    l.triangles_s = secondary_triangles;
    l.triangles_m = !secondary_triangles;
    l.angles[0] = 0.3;
    l.angles[1] = 0.2;
    expect_flat_pair(assemble(l), l.offset, 1.0);
  }
  Layout both;
  both.triangles_s = both.triangles_m = true;
  both.offset = -0.02;
  expect_flat_pair(assemble(both), both.offset, 1.0);
}

TEST(MortarFaceIntegrals, DistortedQuadrilaterals)
{
  // The inner nodes moved in the plane by up to 0.15 / 4 (faces that are no parallelograms:
  // xi on each face by Newton), rotated: still D diagonal, sum D = 1, the gap exact.
  Layout l;
  l.distortion = 0.6;
  l.angles[0] = 0.3;
  l.angles[1] = 0.2;
  const Assembled a = assemble(l);
  const Point moved = rotate({0.25, 0.25, 0}, 0.3, 0.2); // where inner node 6 was
  EXPECT_GT(kiln_test::norm({a.primary.x[6][0] - moved[0], a.primary.x[6][1] - moved[1],
                             a.primary.x[6][2] - moved[2]}),
            0.05);
  expect_flat_pair(a, l.offset, 1.0);
  for (const bool triangles : {true, false})
  {
    SCOPED_TRACE(triangles ? "TRI3 secondary" : "TRI3 primary");
    Layout t = l;
    t.triangles_s = triangles;
    t.triangles_m = !triangles;
    t.offset = -0.02;
    expect_flat_pair(assemble(t), t.offset, 1.0);
  }
}

TEST(MortarFaceIntegrals, NodesDownToTheMultiplierThreshold)
{
  // The last column of faces covered by a fraction c of its width: the far nodes get
  // D_jj / ∫ N_j (over their faces) = c^2, and the gap stays exact down to c^2 = 1e-6, the
  // design's threshold below which a node carries no multiplier. (Measured further: the gap
  // error is 8e-12 at c^2 = 1e-10, 1.4e-10 at 1e-12, 1.1e-9 at 1e-14; doc/contact.md.)
  for (const double c : {1e-2, 1e-3})
  {
    SCOPED_TRACE("coverage " + std::to_string(c));
    Layout l;
    l.shift = 0.2 * (1 - c);
    l.angles[0] = 0.3;
    l.angles[1] = 0.2;
    const Assembled a = assemble(l);
    // The twin point's position along the surface is less exact than the gap across it: off
    // by up to 4.8e-12 at c = 1e-3 (the gap by 7e-14).
    expect_flat_pair(a, l.offset, 1.0 - l.shift, 1e-11);
    for (int k = 0; k <= l.ny_s; ++k) // the far nodes, x = 1 + shift
    {
      const int j = k * (l.nx_s + 1) + l.nx_s;
      const double integral_N = (k == 0 || k == l.ny_s ? 0.5 : 1.0) * 0.2 / (2.0 * l.ny_s);
      EXPECT_NEAR(a.D[j][j] / integral_N, c * c, 1e-9 * c * c) << "node " << j;
    }
  }
}

TEST(MortarSegments, PointsOfDistortedAndWarpedFacesLieOnTheNormalLine)
{
  // The points' reference coordinates (in closed form on the auxiliary plane, polished by
  // Newton) on strongly distorted, warped (non-planar) and near-parallelogram QUAD4 and on TRI3
  // primary faces, in a general orientation: each point's positions on the two faces differ
  // along the segments' normal only, and lie inside both faces (no shape value below 0).
  const auto place = [](const Point &p)
  { return kiln_test::rotated(p, 37.0, -23.0); }; // a general orientation
  const std::vector<Point> xs = {place({0, 0, 0.1}), place({0, 1, 0.1}), place({1, 1.1, 0.1}),
                                 place({1.05, 0, 0.1})};
  const MortarFace secondary{CellType::quad4, xs};
  const std::vector<std::vector<Point>> primaries = {
      // a kite-like distorted quadrilateral
      {place({-0.2, -0.1, 0}), place({1.3, 0.1, 0}), place({0.9, 0.7, 0}), place({0.1, 1.2, 0})},
      // warped: one corner 0.05 off the plane of the others
      {place({-0.1, -0.2, 0}), place({1.2, -0.1, 0.05}), place({1.1, 1.2, 0}),
       place({-0.2, 1.1, 0})},
      // a parallelogram up to 1e-9 (the quadratic's leading coefficient nearly 0)
      {place({-0.3, -0.2, 0}), place({0.9, -0.2, 0}), place({1.3, 1.2, 0}),
       place({0.1, 1.2 + 1e-9, 0})}};
  const std::vector<Point> triangle = {place({-0.4, -0.3, 0}), place({1.8, 0.2, 0}),
                                       place({0.3, 1.6, 0})};
  std::vector<MortarFace> faces;
  for (const std::vector<Point> &x : primaries)
    faces.push_back({CellType::quad4, x});
  faces.push_back({CellType::tri3, triangle});
  for (const MortarFace &primary : faces)
  {
    const kiln::MortarSegments segments(secondary, primary);
    ASSERT_FALSE(segments.empty());
    const Point &n = segments.normal();
    const kiln::FiniteElement &fe_s = kiln::FiniteElement::of(secondary.type);
    const kiln::FiniteElement &fe_m = kiln::FiniteElement::of(primary.type);
    for (const kiln::MortarPoint &q : segments.points())
    {
      const Point x_s = kiln::face_point(secondary, q.xi_s),
                  x_m = kiln::face_point(primary, q.xi_m);
      Point d{x_s[0] - x_m[0], x_s[1] - x_m[1], x_s[2] - x_m[2]};
      const double along = kiln::dot(d, n);
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(d[k], along * n[k], 1e-14) << "off the normal line";
      std::array<double, kiln::max_cell_nodes> N{};
      fe_s.values(q.xi_s, N.data());
      for (int i = 0; i < fe_s.n_shape(); ++i)
        EXPECT_GE(N[i], -1e-14);
      fe_m.values(q.xi_m, N.data());
      for (int i = 0; i < fe_m.n_shape(); ++i)
        EXPECT_GE(N[i], -1e-14);
    }
  }
}
