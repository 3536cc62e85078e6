#pragma once
/// The one definition of the gap opening, used by contact, the gap conductance and output.
#include "mesh/mesh.hpp"

#include <cstddef>
#include <vector>

namespace kiln
{
/// The opening of the gap between two facing points, g = n . (y_b - y_a) [m]: y_a on side a,
/// y_b on side b, n the unit normal from side a to side b. With the displaced positions
/// (x + u) it is the distance across the gap; on a gap of zero width (split at a side set)
/// the displacements alone give the same. g > 0: open; g < 0: the sides interpenetrate.
inline double gap_opening(const Point &n, const Point &y_a, const Point &y_b)
{
  return n[0] * (y_b[0] - y_a[0]) + n[1] * (y_b[1] - y_a[1]) + n[2] * (y_b[2] - y_a[2]);
}

/// The twin point of a row, sum_k w_k y_k (y_k: `y(partner k)`, a point or a displacement).
template <class PointOf>
Point twin_point(const std::vector<int> &partners, const std::vector<double> &weights,
                 const PointOf &y)
{
  Point twin{};
  for (std::size_t k = 0; k < partners.size(); ++k)
  {
    const Point y_k = y(partners[k]);
    for (int i = 0; i < 3; ++i)
      twin[i] += weights[k] * y_k[i];
  }
  return twin;
}

/// The opening of a row (ContactRow) along n: g = g0 + n . (u_j - sum_k w_k u_k) [m], with
/// g0 the opening in the reference configuration and u(node) the displacements.
template <class DisplacementOf>
double gap_opening(const Point &n, const double g0, const int node,
                   const std::vector<int> &partners, const std::vector<double> &weights,
                   const DisplacementOf &u)
{
  return g0 + gap_opening(n, twin_point(partners, weights, u), u(node));
}
} // namespace kiln
