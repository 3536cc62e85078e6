#pragma once
/// An axis-aligned box: the bounding box of a face, grown by a reach for a search.
#include "elements/reference_cell.hpp"

#include <algorithm>
#include <cmath>

namespace kiln
{
struct BoundingBox
{
  Point lo{0.0, 0.0, 0.0};
  Point hi{0.0, 0.0, 0.0};

  /// The smallest box holding points x[0], ..., x[n-1] (n > 0).
  static BoundingBox of(const Point *x, const int n)
  {
    BoundingBox box{x[0], x[0]};
    for (int i = 1; i < n; ++i)
      for (int d = 0; d < 3; ++d)
      {
        box.lo[d] = std::min(box.lo[d], x[i][d]);
        box.hi[d] = std::max(box.hi[d], x[i][d]);
      }
    return box;
  }
  /// This box grown by `reach` [m] on every side.
  BoundingBox grown(const double reach) const
  {
    BoundingBox box = *this;
    for (int d = 0; d < 3; ++d)
    {
      box.lo[d] -= reach;
      box.hi[d] += reach;
    }
    return box;
  }
  /// Whether the two boxes share a point (touching counts).
  bool overlaps(const BoundingBox &other) const
  {
    for (int d = 0; d < 3; ++d)
      if (lo[d] > other.hi[d] || hi[d] < other.lo[d])
        return false;
    return true;
  }
  /// The distance between the nearest points of the two boxes (0 if they overlap) [m].
  double distance(const BoundingBox &other) const
  {
    double sum = 0.0;
    for (int d = 0; d < 3; ++d)
    {
      const double apart = std::max({0.0, other.lo[d] - hi[d], lo[d] - other.hi[d]});
      sum += apart * apart;
    }
    return std::sqrt(sum);
  }
};
} // namespace kiln
