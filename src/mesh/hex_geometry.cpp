#include "mesh/hex_geometry.hpp"

#include "elements/finite_element.hpp"

#include <cmath>

namespace kiln
{
namespace internal
{
Point cross(const Point &a, const Point &b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Point &a)
{
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}
} // namespace internal

HexNodes cell_nodes(const Mesh &mesh, const int cell)
{
  HexNodes x;
  for (int i = 0; i < n_hex_nodes; ++i)
    x[i] = mesh.coordinates[mesh.cell_nodes(cell)[i]];
  return x;
}

QuadNodes face_nodes(const Mesh &mesh, const int cell, const int face)
{
  QuadNodes x;
  for (int i = 0; i < 4; ++i)
    x[i] = mesh.coordinates[mesh.face_node(cell, face, i)];
  return x;
}

Point hex_reference_node(const int i)
{
  static constexpr double r[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                     {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  return {r[i][0], r[i][1], r[i][2]};
}

double hex_jacobian_determinant(const HexNodes &x, const Point &xi)
{
  double J[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}; // J[d][r] = dx_d/dxi_r
  for (int i = 0; i < n_hex_nodes; ++i)
  {
    const Point r = hex_reference_node(i);
    const double f[3] = {1 + r[0] * xi[0], 1 + r[1] * xi[1], 1 + r[2] * xi[2]};
    const double dN[3] = {0.125 * r[0] * f[1] * f[2], 0.125 * r[1] * f[0] * f[2],
                          0.125 * r[2] * f[0] * f[1]};
    for (int d = 0; d < 3; ++d)
      for (int k = 0; k < 3; ++k)
        J[d][k] += x[i][d] * dN[k];
  }
  return J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
         J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
}

const std::array<Point, 8> &hex_gauss_points()
{
  static const std::array<Point, 8> points = []
  {
    const double g = 1.0 / std::sqrt(3.0);
    std::array<Point, 8> p;
    for (int i = 0; i < 8; ++i)
    {
      const Point r = hex_reference_node(i);
      p[i] = {g * r[0], g * r[1], g * r[2]};
    }
    return p;
  }();
  return points;
}

double hex_volume(const HexNodes &x)
{
  double v = 0.0;
  for (const Point &xi : hex_gauss_points())
    v += hex_jacobian_determinant(x, xi);
  return v;
}

bool append_orthonormal(std::vector<Point> &basis, Point v)
{
  const double length = std::sqrt(dot(v, v));
  for (int pass = 0; pass < 2; ++pass)
    for (const Point &q : basis)
    {
      const double c = dot(v, q);
      for (int d = 0; d < 3; ++d)
        v[d] -= c * q[d];
    }
  const double rest = std::sqrt(dot(v, v));
  if (rest <= 1e-6 * length)
    return false;
  for (double &x : v)
    x /= rest;
  basis.push_back(v);
  return true;
}

FaceNodalAreas face_nodal_areas(const CellType face_type, const Point *x)
{
  const ReferenceValues &ref = ReferenceValues::of(face_type);
  const int n = ref.n_shape;
  FaceNodalAreas out;
  out.area_vector.assign(n, Point{0.0, 0.0, 0.0});
  out.area.assign(n, 0.0);
  for (int q = 0; q < ref.n_qpoints; ++q)
  {
    const double *N = ref.shape.data() + q * n;
    const Point *dN = ref.grad.data() + q * n;
    Point dx_ds{0, 0, 0}, dx_dt{0, 0, 0};
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d)
      {
        dx_ds[d] += x[i][d] * dN[i][0];
        dx_dt[d] += x[i][d] * dN[i][1];
      }
    Point da = internal::cross(dx_ds, dx_dt);
    for (double &v : da)
      v *= ref.weights[q];
    const double da_norm = internal::norm(da);
    for (int i = 0; i < n; ++i)
    {
      for (int d = 0; d < 3; ++d)
        out.area_vector[i][d] += N[i] * da[d];
      out.area[i] += N[i] * da_norm;
    }
  }
  return out;
}

FaceNodalAreas face_nodal_areas(const Mesh &mesh, const int c, const int face)
{
  std::vector<Point> x;
  for (const int n : mesh.face_nodes(c, face))
    x.push_back(mesh.coordinates[n]);
  return face_nodal_areas(mesh.reference_cell(c).face_type(face), x.data());
}

std::array<std::array<double, 3>, 3> rotation_matrix(const double phi_degrees,
                                                     const double theta_degrees)
{
  const double pi = std::acos(-1.0);
  const double p = phi_degrees * pi / 180.0, t = theta_degrees * pi / 180.0;
  const double cp = std::cos(p), sp = std::sin(p), ct = std::cos(t), st = std::sin(t);
  // Rx(theta) Ry(phi), Ry = [[c,0,s],[0,1,0],[-s,0,c]], Rx = [[1,0,0],[0,c,-s],[0,s,c]].
  return {{{cp, 0.0, sp}, {st * sp, ct, -st * cp}, {-ct * sp, st, ct * cp}}};
}
} // namespace kiln
