#pragma once
/// The mortar segments of one secondary face and one primary face (doc/contact.md, "Separately
/// meshed bodies (issue 30): design"; Puso and Laursen 2004): both faces projected along the
/// secondary face's centre normal onto its auxiliary plane (through its centre), the primary's
/// polygon clipped against the secondary's (Sutherland-Hodgman), the overlap cut into triangles
/// about its vertex centroid, and on each triangle the 7-point degree-5 rule; each point carries
/// its reference coordinates on both faces (found along the same normal) and its weight on the
/// plane. Linear faces (QUAD4, TRI3); the faces' bases are FiniteElement::of(type)'s.
#include "base/span.hpp"
#include "elements/reference_cell.hpp"

#include <array>
#include <vector>

namespace kiln
{
/// A face of a contact surface: its type (QUAD4 or TRI3) and its nodes' coordinates [m] in
/// ReferenceCell::face_nodes order (the right-hand rule gives its outward normal).
struct MortarFace
{
  CellType type = CellType::quad4;
  Span<const Point> x{nullptr, 0};
};

/// An integration point of a segment: the reference coordinates on the secondary and the
/// primary face of one point of their overlap, and its weight on the auxiliary plane [m^2].
struct MortarPoint
{
  Point xi_s{0, 0, 0};
  Point xi_m{0, 0, 0};
  double weight = 0.0;
};

class MortarSegments
{
public:
  /// The overlap of `primary` with `secondary` on the secondary's auxiliary plane. An overlap
  /// smaller than overlap_fraction() of the secondary face's area (faces that touch along an
  /// edge or a corner) counts as none.
  MortarSegments(const MortarFace &secondary, const MortarFace &primary);

  /// The threshold of an empty overlap, relative to the secondary face's projected area [-].
  static constexpr double overlap_fraction() { return 1e-12; }

  bool empty() const { return points_.empty(); }
  /// The overlap polygon's vertices on the auxiliary plane [m], counterclockwise about normal().
  const std::vector<Point> &polygon() const { return polygon_; }
  /// The overlap's area on the plane [m^2] (the sum of the points' weights).
  double area() const { return area_; }
  /// The unit normal of the plane: the secondary face's outward normal at its centre [-].
  const Point &normal() const { return normal_; }
  const std::vector<MortarPoint> &points() const { return points_; }

private:
  Point normal_{0, 0, 0};
  std::vector<Point> polygon_;
  double area_ = 0.0;
  std::vector<MortarPoint> points_;
};

/// The physical point of `face` at reference coordinates xi [m].
Point face_point(const MortarFace &face, const Point &xi);

namespace internal
{
using Point2 = std::array<double, 2>;
/// Sutherland-Hodgman: the part of `subject` inside the convex polygon `window` (both
/// counterclockwise; a point on an edge is inside). Empty, or fewer than 3 vertices, when
/// they do not overlap.
std::vector<Point2> clip_polygon(const std::vector<Point2> &subject,
                                 const std::vector<Point2> &window);
/// The signed area of a polygon (positive when counterclockwise) [m^2].
double signed_area(const std::vector<Point2> &polygon);
} // namespace internal
} // namespace kiln
