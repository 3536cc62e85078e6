#include "discretization/face_values.hpp"

#include "base/errors.hpp"

#include <cmath>
#include <sstream>

namespace kiln
{
namespace internal
{
namespace
{
/// Reference coordinates of the quad nodes, counterclockwise.
constexpr double quad_reference_node[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

/// The 2x2 Gauss points, in node order.
std::array<std::array<double, 2>, 4> quad_gauss_points()
{
  const double g = 1.0 / std::sqrt(3.0);
  std::array<std::array<double, 2>, 4> p{};
  for (int q = 0; q < 4; ++q)
    p[q] = {g * quad_reference_node[q][0], g * quad_reference_node[q][1]};
  return p;
}
} // namespace
} // namespace internal

const FaceValues::ShapeTable &FaceValues::reference_shape()
{
  static const ShapeTable table = []
  {
    ShapeTable t{};
    const auto st = internal::quad_gauss_points();
    for (int q = 0; q < n_points; ++q)
      for (int i = 0; i < 4; ++i)
      {
        const double *r = internal::quad_reference_node[i];
        t[q][i] = 0.25 * (1 + r[0] * st[q][0]) * (1 + r[1] * st[q][1]);
      }
    return t;
  }();
  return table;
}

const FaceValues::GradTable &FaceValues::reference_grad()
{
  static const GradTable table = []
  {
    GradTable t{};
    const auto st = internal::quad_gauss_points();
    for (int q = 0; q < n_points; ++q)
      for (int i = 0; i < 4; ++i)
      {
        const double *r = internal::quad_reference_node[i];
        t[q][i] = {0.25 * r[0] * (1 + r[1] * st[q][1]), 0.25 * r[1] * (1 + r[0] * st[q][0])};
      }
    return t;
  }();
  return table;
}

void FaceValues::reinit(const QuadNodes &x)
{
  const ShapeTable &N = reference_shape();
  const GradTable &dN = reference_grad();
  for (int q = 0; q < n_points; ++q)
  {
    Point xq{0, 0, 0}, dx_ds{0, 0, 0}, dx_dt{0, 0, 0};
    for (int i = 0; i < 4; ++i)
      for (int d = 0; d < 3; ++d)
      {
        xq[d] += N[q][i] * x[i][d];
        dx_ds[d] += dN[q][i][0] * x[i][d];
        dx_dt[d] += dN[q][i][1] * x[i][d];
      }
    const Point a{dx_ds[1] * dx_dt[2] - dx_ds[2] * dx_dt[1],
                  dx_ds[2] * dx_dt[0] - dx_ds[0] * dx_dt[2],
                  dx_ds[0] * dx_dt[1] - dx_ds[1] * dx_dt[0]};
    const double area = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    if (!(area > 0.0))
    {
      std::ostringstream msg;
      msg << "FaceValues::reinit: zero area element at Gauss point " << q
          << " (a degenerate face; node 0 at (" << x[0][0] << ", " << x[0][1] << ", " << x[0][2]
          << "))";
      throw InternalError(msg.str());
    }
    JxW_[q] = area; // the 2x2 Gauss weights are 1
    normal_[q] = {a[0] / area, a[1] / area, a[2] / area};
    quadrature_point_[q] = xq;
  }
}
} // namespace kiln
