#include "elements/quadrature_rules.hpp"

#include "base/errors.hpp"

#include <cmath>
#include <string>

namespace kiln::quadrature
{
Quadrature gauss_line(const int n)
{
  if (n == 1)
    return {{{0, 0, 0}}, {2.0}};
  if (n == 2)
  {
    const double g = 1.0 / std::sqrt(3.0);
    return {{{-g, 0, 0}, {g, 0, 0}}, {1.0, 1.0}};
  }
  if (n == 3)
  {
    const double g = std::sqrt(0.6);
    return {{{-g, 0, 0}, {0, 0, 0}, {g, 0, 0}}, {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}};
  }
  throw InternalError("quadrature::gauss_line: no " + std::to_string(n) + "-point rule");
}

Quadrature gauss_at_corners(const ReferenceCell &cell)
{
  const double g = 1.0 / std::sqrt(3.0);
  Quadrature q;
  for (int i = 0; i < cell.n_vertices(); ++i)
  {
    const Point &r = cell.node(i);
    q.points.push_back({g * r[0], g * r[1], g * r[2]});
    q.weights.push_back(1.0);
  }
  return q;
}

Quadrature gauss_tensor(const int dim, const int n)
{
  const Quadrature line = gauss_line(n);
  Quadrature q;
  const int nz = dim == 3 ? n : 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        q.points.push_back(
            {line.points[i][0], line.points[j][0], dim == 3 ? line.points[k][0] : 0});
        q.weights.push_back(line.weights[i] * line.weights[j] * (dim == 3 ? line.weights[k] : 1));
      }
  return q;
}

namespace
{
/// Adds the points of the barycentric orbit of (a, a, 1 - 2a) (three points) with weight w.
void add_triangle_orbit(Quadrature &q, const double a, const double w)
{
  const double b = 1 - 2 * a;
  for (const Point &p : {Point{a, a, 0}, Point{b, a, 0}, Point{a, b, 0}})
  {
    q.points.push_back(p);
    q.weights.push_back(w);
  }
}

/// Adds the tetrahedron points with barycentric coordinates (a, a, a, 1 - 3a) permuted (four).
void add_tet_orbit4(Quadrature &q, const double a, const double w)
{
  const double b = 1 - 3 * a;
  for (const Point &p : {Point{a, a, a}, Point{b, a, a}, Point{a, b, a}, Point{a, a, b}})
  {
    q.points.push_back(p);
    q.weights.push_back(w);
  }
}
} // namespace

Quadrature triangle_degree2()
{
  Quadrature q;
  add_triangle_orbit(q, 1.0 / 6.0, 1.0 / 6.0);
  return q;
}

Quadrature triangle_degree5()
{
  const double s = std::sqrt(15.0);
  Quadrature q{{{1.0 / 3.0, 1.0 / 3.0, 0}}, {9.0 / 80.0}};
  add_triangle_orbit(q, (6 - s) / 21, (155 - s) / 2400);
  add_triangle_orbit(q, (6 + s) / 21, (155 + s) / 2400);
  return q;
}

Quadrature tetrahedron_degree2()
{
  Quadrature q;
  add_tet_orbit4(q, (5 - std::sqrt(5.0)) / 20, 1.0 / 24.0);
  return q;
}

Quadrature tetrahedron_degree5()
{
  // Walkington's 14-point rule (the weights below sum to 1/6, the unit simplex's volume).
  Quadrature q;
  add_tet_orbit4(q, 0.0927352503108912264, 0.0122488405193936582);
  add_tet_orbit4(q, 0.3108859192633006097, 0.0187813209530026417);
  // The six points with barycentric coordinates (c, c, 1/2 - c, 1/2 - c) permuted.
  const double c = 0.0455037041256496494, d = 0.5 - c, w = 0.0070910034628469110;
  for (const Point &p : {Point{c, c, d}, Point{c, d, c}, Point{d, c, c}, Point{c, d, d},
                         Point{d, c, d}, Point{d, d, c}})
  {
    q.points.push_back(p);
    q.weights.push_back(w);
  }
  return q;
}

Quadrature wedge(const Quadrature &triangle, const int n)
{
  const Quadrature line = gauss_line(n);
  Quadrature q;
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < triangle.size(); ++i)
    {
      q.points.push_back({triangle.points[i][0], triangle.points[i][1], line.points[k][0]});
      q.weights.push_back(triangle.weights[i] * line.weights[k]);
    }
  return q;
}

Quadrature pyramid_collapsed()
{
  // Gauss-Jacobi on [0, 1] with weight (1 - z)^2: the roots of z^2 - 2z/3 + 1/15 (orthogonal
  // to 1 and z under that weight), the weights from the moments 1/3 and 1/12.
  const double r = std::sqrt(10.0) / 15.0;
  const double z[2] = {1.0 / 3.0 - r, 1.0 / 3.0 + r};
  const double wz1 = (1.0 / 12.0 - z[0] / 3.0) / (z[1] - z[0]);
  const double wz[2] = {1.0 / 3.0 - wz1, wz1};
  const Quadrature line = gauss_line(2);
  Quadrature q;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
      {
        const double s = 1 - z[k];
        q.points.push_back({line.points[i][0] * s, line.points[j][0] * s, z[k]});
        q.weights.push_back(line.weights[i] * line.weights[j] * wz[k]);
      }
  return q;
}
} // namespace kiln::quadrature
