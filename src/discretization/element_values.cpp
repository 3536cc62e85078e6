#include "discretization/element_values.hpp"

#include "base/errors.hpp"

#include <sstream>

namespace kiln
{
const ElementValues::ShapeTable &ElementValues::reference_shape()
{
  static const ShapeTable table = []
  {
    ShapeTable t{};
    const auto &xi = hex_gauss_points();
    for (int q = 0; q < n_points; ++q)
      for (int i = 0; i < n_hex_nodes; ++i)
      {
        const Point r = hex_reference_node(i);
        t[q][i] = 0.125 * (1 + r[0] * xi[q][0]) * (1 + r[1] * xi[q][1]) * (1 + r[2] * xi[q][2]);
      }
    return t;
  }();
  return table;
}

const ElementValues::GradTable &ElementValues::reference_grad()
{
  static const GradTable table = []
  {
    GradTable t{};
    const auto &xi = hex_gauss_points();
    for (int q = 0; q < n_points; ++q)
      for (int i = 0; i < n_hex_nodes; ++i)
      {
        const Point r = hex_reference_node(i);
        const double f[3] = {1 + r[0] * xi[q][0], 1 + r[1] * xi[q][1], 1 + r[2] * xi[q][2]};
        t[q][i] = {0.125 * r[0] * f[1] * f[2], 0.125 * r[1] * f[0] * f[2],
                   0.125 * r[2] * f[0] * f[1]};
      }
    return t;
  }();
  return table;
}

void ElementValues::reinit(const HexNodes &x)
{
  const ShapeTable &N = reference_shape();
  const GradTable &dN = reference_grad();
  for (int q = 0; q < n_points; ++q)
  {
    double J[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}; // J[d][r] = dx_d/dxi_r
    Point xq{0, 0, 0};
    for (int i = 0; i < n_hex_nodes; ++i)
      for (int d = 0; d < 3; ++d)
      {
        xq[d] += N[q][i] * x[i][d];
        for (int r = 0; r < 3; ++r)
          J[d][r] += x[i][d] * dN[q][i][r];
      }
    // Cofactors: inv(J)[r][d] = C[d][r] / det, with C the cofactor matrix of J.
    const double C[3][3] = {
        {J[1][1] * J[2][2] - J[1][2] * J[2][1], J[1][2] * J[2][0] - J[1][0] * J[2][2],
         J[1][0] * J[2][1] - J[1][1] * J[2][0]},
        {J[0][2] * J[2][1] - J[0][1] * J[2][2], J[0][0] * J[2][2] - J[0][2] * J[2][0],
         J[0][1] * J[2][0] - J[0][0] * J[2][1]},
        {J[0][1] * J[1][2] - J[0][2] * J[1][1], J[0][2] * J[1][0] - J[0][0] * J[1][2],
         J[0][0] * J[1][1] - J[0][1] * J[1][0]}};
    const double det = J[0][0] * C[0][0] + J[0][1] * C[0][1] + J[0][2] * C[0][2];
    if (!(det > 0.0))
    {
      std::ostringstream msg;
      msg << "ElementValues::reinit: det(dx/dxi) = " << det << " <= 0 at Gauss point " << q
          << " (an inverted or degenerate cell; node 0 at (" << x[0][0] << ", " << x[0][1] << ", "
          << x[0][2] << "))";
      throw InternalError(msg.str());
    }
    // grad N_i = J^{-T} grad_xi N_i, component d: sum_r inv(J)[r][d] dN_r = sum_r C[d][r] dN_r /
    // det
    const double inv_det = 1.0 / det;
    for (int i = 0; i < n_hex_nodes; ++i)
      for (int d = 0; d < 3; ++d)
        grad_[q][i][d] =
            (C[d][0] * dN[q][i][0] + C[d][1] * dN[q][i][1] + C[d][2] * dN[q][i][2]) * inv_det;
    JxW_[q] = det; // the 2x2x2 Gauss weights are 1
    quadrature_point_[q] = xq;
  }
}
} // namespace kiln
