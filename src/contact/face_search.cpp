#include "contact/face_search.hpp"

#include "base/errors.hpp"
#include "mesh/contact_surface.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace kiln
{
namespace internal
{
std::vector<BoundingBox> face_boxes(const ContactSurface &surface)
{
  std::vector<BoundingBox> boxes;
  for (int f = 0; f < surface.n_faces(); ++f)
    boxes.push_back(surface.face_box(f));
  return boxes;
}
} // namespace internal

FaceSearch::FaceSearch(const ContactSurface &primary)
    : FaceSearch(internal::face_boxes(primary), primary.max_face_diameter())
{
}

FaceSearch::FaceSearch(std::vector<BoundingBox> boxes, const double cell_size)
    : boxes_(std::move(boxes)), cell_size_(cell_size)
{
  if (boxes_.empty())
    return;
  KILN_ASSERT(cell_size_ > 0.0, "the bucket size must be positive: " << cell_size_);
  BoundingBox all = boxes_.front();
  for (const BoundingBox &box : boxes_)
    for (int d = 0; d < 3; ++d)
    {
      all.lo[d] = std::min(all.lo[d], box.lo[d]);
      all.hi[d] = std::max(all.hi[d], box.hi[d]);
    }
  origin_ = all.lo;
  for (int d = 0; d < 3; ++d)
    n_buckets_[d] = static_cast<int>(std::floor((all.hi[d] - all.lo[d]) / cell_size_)) + 1;
  // Each face in the bucket of its box's lower corner; span_ the most buckets a box reaches
  // beyond it (1 with the largest face as the cell: a box is no wider than its face).
  for (int f = 0; f < n_faces(); ++f)
  {
    const BoundingBox &box = boxes_[f];
    for (int d = 0; d < 3; ++d)
      span_[d] = std::max(span_[d], bucket(d, box.hi[d]) - bucket(d, box.lo[d]));
    entries_.emplace_back(key(bucket(0, box.lo[0]), bucket(1, box.lo[1]), bucket(2, box.lo[2])), f);
  }
  std::sort(entries_.begin(), entries_.end());
}

int FaceSearch::bucket(const int d, const double x) const
{
  const double i = std::floor((x - origin_[d]) / cell_size_);
  return static_cast<int>(std::clamp(i, 0.0, static_cast<double>(n_buckets_[d] - 1)));
}

std::int64_t FaceSearch::key(const int i, const int j, const int k) const
{
  return (static_cast<std::int64_t>(i) * n_buckets_[1] + j) * n_buckets_[2] + k;
}

std::vector<int> FaceSearch::candidates(const BoundingBox &box, const double reach) const
{
  std::vector<int> found;
  if (boxes_.empty())
    return found;
  const BoundingBox query = box.grown(reach);
  // A box that meets the query has its lower corner at most span_ buckets below the query's.
  const auto first = [&](const int d) { return std::max(0, bucket(d, query.lo[d]) - span_[d]); };
  const int k_lo = first(2), k_hi = bucket(2, query.hi[2]);
  for (int i = first(0); i <= bucket(0, query.hi[0]); ++i)
  {
    auto it = entries_.begin();
    for (int j = first(1); j <= bucket(1, query.hi[1]); ++j)
    {
      // The buckets (i, j, k_lo .. k_hi) are consecutive keys, after those of (i, j - 1): a
      // galloping search from there, then a scan.
      const auto start = std::make_pair(key(i, j, k_lo), -1);
      auto end = it;
      for (std::ptrdiff_t step = 1; end != entries_.end() && *end < start; step *= 2)
      {
        it = end;
        end = entries_.end() - it > step ? it + step : entries_.end();
      }
      it = std::lower_bound(it, end, start);
      const std::int64_t last = key(i, j, k_hi);
      for (; it != entries_.end() && it->first <= last; ++it)
        if (boxes_[it->second].overlaps(query))
          found.push_back(it->second);
    }
  }
  std::sort(found.begin(), found.end());
  return found;
}
} // namespace kiln
