#include "contact/mortar_segments.hpp"

#include "base/errors.hpp"
#include "elements/finite_element.hpp"
#include "elements/quadrature_rules.hpp"
#include "mesh/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace kiln
{
namespace internal
{
std::vector<Point2> clip_polygon(const std::vector<Point2> &subject,
                                 const std::vector<Point2> &window)
{
  std::vector<Point2> out = subject;
  for (std::size_t e = 0; e < window.size() && out.size() >= 3; ++e)
  {
    const Point2 a = window[e], b = window[(e + 1) % window.size()];
    const auto inside = [&](const Point2 &p)
    { return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]); };
    const std::vector<Point2> in = std::move(out);
    out.clear();
    for (std::size_t i = 0; i < in.size(); ++i)
    {
      const Point2 p = in[i], q = in[(i + 1) % in.size()];
      const double sp = inside(p), sq = inside(q);
      if (sp >= 0)
        out.push_back(p);
      if ((sp >= 0) != (sq >= 0))
      {
        const double w = sp / (sp - sq);
        out.push_back({p[0] + w * (q[0] - p[0]), p[1] + w * (q[1] - p[1])});
      }
    }
  }
  return out.size() >= 3 ? out : std::vector<Point2>{};
}

double signed_area(const std::vector<Point2> &polygon)
{
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i)
  {
    const Point2 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
    twice += p[0] * q[1] - p[1] * q[0];
  }
  return 0.5 * twice;
}
} // namespace internal

namespace
{
using internal::Point2;

Point cross(const Point &a, const Point &b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Point unit(const Point &a)
{
  const double length = std::sqrt(dot(a, a));
  return {a[0] / length, a[1] / length, a[2] / length};
}

/// The point of `face` at xi and its two tangents dx/dxi_0, dx/dxi_1.
void map_face(const MortarFace &face, const Point &xi, Point &x, Point &dx_ds, Point &dx_dt)
{
  const FiniteElement &fe = FiniteElement::of(face.type);
  KILN_ASSERT(fe.cell().dim() == 2 && fe.cell().degree() == 1 && fe.n_shape() == face.x.size(),
              "MortarSegments: a linear face with its nodes, not a " << fe.cell().name());
  std::array<double, max_cell_nodes> N{};
  std::array<Point, max_cell_nodes> dN{};
  fe.values(xi, N.data());
  fe.gradients(xi, dN.data());
  x = dx_ds = dx_dt = {0, 0, 0};
  for (int i = 0; i < fe.n_shape(); ++i)
    for (int d = 0; d < 3; ++d)
    {
      x[d] += N[i] * face.x[i][d];
      dx_ds[d] += dN[i][0] * face.x[i][d];
      dx_dt[d] += dN[i][1] * face.x[i][d];
    }
}

/// The reference centre of a face type (the mean of its vertices).
Point reference_centre(const CellType type)
{
  const ReferenceCell &cell = ReferenceCell::of(type);
  Point c{0, 0, 0};
  for (int i = 0; i < cell.n_vertices(); ++i)
    for (int d = 0; d < 3; ++d)
      c[d] += cell.node(i)[d] / cell.n_vertices();
  return c;
}

/// The reference coordinates of the point of `face` on the line y + l n (Newton on
/// x(xi) - l n = y from the face's centre; one step for an affine face). InternalError if it
/// does not converge (a face nearly parallel to n): never a wrong point without a word.
Point project_along(const MortarFace &face, const Point &y, const Point &n)
{
  Point xi = reference_centre(face.type);
  double step = 1.0;
  for (int iteration = 0; iteration < 30 && !(step < 1e-15); ++iteration)
  {
    Point x, a, b;
    map_face(face, xi, x, a, b);
    const Point r{x[0] - y[0], x[1] - y[1], x[2] - y[2]};
    const Point c{-n[0], -n[1], -n[2]}; // the columns a, b, c of the Jacobian
    const double det = dot(a, cross(b, c));
    KILN_ASSERT(std::abs(det) > 0, "MortarSegments: a face parallel to the projection");
    const double ds = dot(r, cross(b, c)) / det, dt = dot(a, cross(r, c)) / det;
    xi[0] -= ds;
    xi[1] -= dt;
    step = std::abs(ds) + std::abs(dt);
  }
  if (!(step < 1e-12))
    throw InternalError("MortarSegments: the projection onto a " +
                        ReferenceCell::of(face.type).name() +
                        " face along the secondary normal did not converge (last step " +
                        std::to_string(step) + ")");
  return xi;
}
} // namespace

Point face_point(const MortarFace &face, const Point &xi)
{
  Point x, dx_ds, dx_dt;
  map_face(face, xi, x, dx_ds, dx_dt);
  return x;
}

MortarSegments::MortarSegments(const MortarFace &secondary, const MortarFace &primary)
{
  Point centre, dx_ds, dx_dt;
  map_face(secondary, reference_centre(secondary.type), centre, dx_ds, dx_dt);
  normal_ = unit(cross(dx_ds, dx_dt));
  const Point t1 = unit(dx_ds), t2 = cross(normal_, t1);
  const auto on_plane = [&](const Point &p)
  {
    const Point d{p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]};
    return Point2{dot(d, t1), dot(d, t2)};
  };
  const auto polygon_of = [&](const MortarFace &face)
  {
    std::vector<Point2> polygon;
    for (int i = 0; i < ReferenceCell::of(face.type).n_vertices(); ++i)
      polygon.push_back(on_plane(face.x[i]));
    if (internal::signed_area(polygon) < 0) // a facing primary face is clockwise here
      std::reverse(polygon.begin(), polygon.end());
    return polygon;
  };
  const std::vector<Point2> window = polygon_of(secondary);
  const std::vector<Point2> overlap = internal::clip_polygon(polygon_of(primary), window);
  const double overlap_area = internal::signed_area(overlap);
  if (!(overlap_area > overlap_fraction() * internal::signed_area(window)))
    return;

  Point2 m{0, 0};
  for (const Point2 &p : overlap)
    for (int d = 0; d < 2; ++d)
      m[d] += p[d] / static_cast<double>(overlap.size());
  const auto in_space = [&](const Point2 &p)
  {
    return Point{centre[0] + p[0] * t1[0] + p[1] * t2[0], centre[1] + p[0] * t1[1] + p[1] * t2[1],
                 centre[2] + p[0] * t1[2] + p[1] * t2[2]};
  };
  for (const Point2 &p : overlap)
    polygon_.push_back(in_space(p));
  static const Quadrature rule = quadrature::triangle_degree5();
  for (std::size_t k = 0; k < overlap.size(); ++k)
  {
    const Point2 p = overlap[k], q = overlap[(k + 1) % overlap.size()];
    const double triangle = internal::signed_area({m, p, q});
    if (!(triangle > 0))
      continue; // a repeated vertex of the clipped polygon
    area_ += triangle;
    for (int g = 0; g < rule.size(); ++g)
    {
      const double a = rule.points[g][0], b = rule.points[g][1];
      const Point y = in_space({m[0] + a * (p[0] - m[0]) + b * (q[0] - m[0]),
                                m[1] + a * (p[1] - m[1]) + b * (q[1] - m[1])});
      points_.push_back({project_along(secondary, y, normal_), project_along(primary, y, normal_),
                         2 * triangle * rule.weights[g]});
    }
  }
}
} // namespace kiln
