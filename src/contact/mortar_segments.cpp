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
  // Two buffers swapped edge by edge (a convex window adds at most one vertex per edge).
  std::vector<Point2> out, in;
  out.reserve(subject.size() + window.size());
  in.reserve(subject.size() + window.size());
  out = subject;
  for (std::size_t e = 0; e < window.size() && out.size() >= 3; ++e)
  {
    const Point2 a = window[e], b = window[(e + 1) % window.size()];
    const auto inside = [&](const Point2 &p)
    { return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]); };
    std::swap(in, out);
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

/// A face's map seen on the auxiliary plane: the plane coordinates of its point at reference
/// coordinates (s, t) are a + b s + c t + d s t (a linear face is bilinear in its reference
/// coordinates; d = 0 for a TRI3). The point of the face on the line through the plane point y
/// along the plane's normal is the (s, t) where this equals y: the 3-d problem x(xi) - l n = y
/// with l eliminated, so planar and warped faces alike.
struct PlaneMap
{
  Point2 a{0, 0}, b{0, 0}, c{0, 0}, d{0, 0};
  Point centre{0, 0, 0}; ///< the reference centre, Newton's start when the closed form fails
  CellType type = CellType::quad4;
};

double cross2(const Point2 &u, const Point2 &v)
{
  return u[0] * v[1] - u[1] * v[0];
}

/// The closed-form (s, t) of a bilinear map a + b s + c t + d s t = y: with q = a - y, the
/// cross product with c + s d gives (b x d) s^2 + (q x d + b x c) s + q x c = 0 (the stable
/// root formula; of two roots the one nearer the reference centre), then t by least squares
/// from q + s b + t (c + s d) = 0. False if it has no finite root (Newton then starts from
/// the centre).
bool closed_form(const PlaneMap &map, const Point2 &y, Point &xi)
{
  const Point2 q{map.a[0] - y[0], map.a[1] - y[1]};
  const double A = cross2(map.b, map.d), B = cross2(q, map.d) + cross2(map.b, map.c),
               C = cross2(q, map.c);
  const double disc = B * B - 4 * A * C;
  if (!(disc >= 0))
    return false;
  const double h = -0.5 * (B + std::copysign(std::sqrt(disc), B));
  double s = h != 0 ? C / h : 0.0;
  if (A != 0)
  {
    const double other = h / A;
    if (std::abs(other - map.centre[0]) < std::abs(s - map.centre[0]))
      s = other;
  }
  const Point2 e{map.c[0] + s * map.d[0], map.c[1] + s * map.d[1]};
  const double ee = e[0] * e[0] + e[1] * e[1];
  if (!(ee > 0))
    return false;
  const double t = -((q[0] + s * map.b[0]) * e[0] + (q[1] + s * map.b[1]) * e[1]) / ee;
  if (!std::isfinite(s) || !std::isfinite(t))
    return false;
  xi = {s, t, 0};
  return true;
}

/// The reference coordinates of the point of the face of `map` on the line through the plane
/// point y along the plane's normal: the closed form polished by Newton (one step to
/// round-off; from the face's centre if the closed form fails, one step for an affine face).
/// InternalError if Newton does not converge (a face nearly parallel to the normal): never a
/// wrong point without a word.
Point project_along(const PlaneMap &map, const Point2 &y)
{
  Point xi = map.centre;
  if (!closed_form(map, y, xi))
    xi = map.centre;
  double step = 1.0;
  for (int iteration = 0; iteration < 30 && !(step < 1e-15); ++iteration)
  {
    const double s = xi[0], t = xi[1];
    const Point2 r{map.a[0] + map.b[0] * s + map.c[0] * t + map.d[0] * s * t - y[0],
                   map.a[1] + map.b[1] * s + map.c[1] * t + map.d[1] * s * t - y[1]};
    const Point2 js{map.b[0] + map.d[0] * t, map.b[1] + map.d[1] * t}; // the columns of the
    const Point2 jt{map.c[0] + map.d[0] * s, map.c[1] + map.d[1] * s}; // Jacobian
    const double det = cross2(js, jt);
    KILN_ASSERT(std::abs(det) > 0, "MortarSegments: a face parallel to the projection");
    const double ds = cross2(r, jt) / det, dt = cross2(js, r) / det;
    xi[0] -= ds;
    xi[1] -= dt;
    step = std::abs(ds) + std::abs(dt);
  }
  if (!(step < 1e-12))
    throw InternalError("MortarSegments: the projection onto a " +
                        ReferenceCell::of(map.type).name() +
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
  const std::vector<Point2> subject = polygon_of(primary);
  // Faces whose boxes on the plane are apart overlap by no area: skip the clipping.
  for (int d = 0; d < 2; ++d)
  {
    const auto by = [d](const Point2 &u, const Point2 &v) { return u[d] < v[d]; };
    const auto [w_lo, w_hi] = std::minmax_element(window.begin(), window.end(), by);
    const auto [s_lo, s_hi] = std::minmax_element(subject.begin(), subject.end(), by);
    if ((*s_hi)[d] < (*w_lo)[d] || (*w_hi)[d] < (*s_lo)[d])
      return;
  }
  const std::vector<Point2> overlap = internal::clip_polygon(subject, window);
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
  polygon_.reserve(overlap.size());
  for (const Point2 &p : overlap)
    polygon_.push_back(in_space(p));
  const auto plane_map = [&](const MortarFace &face)
  {
    // The bilinear coefficients from the map at (0, 0), (1, 0), (0, 1) and (1, 1).
    std::array<Point, 4> x;
    const std::array<Point, 4> at{Point{0, 0, 0}, Point{1, 0, 0}, Point{0, 1, 0}, Point{1, 1, 0}};
    for (int k = 0; k < 4; ++k)
    {
      Point dx_ds_k, dx_dt_k;
      map_face(face, at[k], x[k], dx_ds_k, dx_dt_k);
    }
    const auto along = [&](const Point &v) { return Point2{dot(v, t1), dot(v, t2)}; };
    PlaneMap map;
    map.a = on_plane(x[0]);
    map.b = along({x[1][0] - x[0][0], x[1][1] - x[0][1], x[1][2] - x[0][2]});
    map.c = along({x[2][0] - x[0][0], x[2][1] - x[0][1], x[2][2] - x[0][2]});
    if (ReferenceCell::of(face.type).n_vertices() == 4)
      map.d = along({x[3][0] - x[2][0] - x[1][0] + x[0][0], x[3][1] - x[2][1] - x[1][1] + x[0][1],
                     x[3][2] - x[2][2] - x[1][2] + x[0][2]});
    map.centre = reference_centre(face.type);
    map.type = face.type;
    return map;
  };
  const PlaneMap secondary_map = plane_map(secondary), primary_map = plane_map(primary);
  static const Quadrature rule = quadrature::triangle_degree5();
  points_.reserve(overlap.size() * static_cast<std::size_t>(rule.size()));
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
      const Point2 y{m[0] + a * (p[0] - m[0]) + b * (q[0] - m[0]),
                     m[1] + a * (p[1] - m[1]) + b * (q[1] - m[1])};
      points_.push_back({project_along(secondary_map, y), project_along(primary_map, y),
                         2 * triangle * rule.weights[g]});
    }
  }
}
} // namespace kiln
