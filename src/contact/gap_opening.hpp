#pragma once
/// The one definition of the gap opening, used by contact, the gap conductance and output.
#include "mesh/mesh.hpp"

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
} // namespace kiln
