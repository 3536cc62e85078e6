#pragma once
/// The contact search (issue 30, doc/contact.md "Search"): the primary faces' bounding boxes in
/// a grid of buckets whose cell is the largest primary face's diameter, so that a box spans at
/// most two cells per axis; each face is kept once, in its box's lower corner's bucket, and
/// the buckets are a sorted list (memory follows the faces, not the grid). A query with a secondary
/// face's box grown by a reach returns every primary face whose box meets it: the candidates the
/// mortar segments are integrated over.
#include "mesh/bounding_box.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace kiln
{
class ContactSurface;

class FaceSearch
{
public:
  /// Over these primary face boxes (face f: boxes[f]) with buckets of edge `cell_size` [m]
  /// (> 0 unless there are no boxes).
  FaceSearch(std::vector<BoundingBox> boxes, double cell_size);
  /// Over the faces of `primary` in its current configuration, cell = its largest face.
  explicit FaceSearch(const ContactSurface &primary);

  int n_faces() const { return static_cast<int>(boxes_.size()); }
  /// The primary faces whose boxes meet `box` grown by `reach` [m] (BoundingBox::overlaps),
  /// in increasing order.
  std::vector<int> candidates(const BoundingBox &box, double reach) const;

private:
  /// The bucket of coordinate `x` along axis d, clamped to the grid.
  int bucket(int d, double x) const;
  std::int64_t key(int i, int j, int k) const;

  std::vector<BoundingBox> boxes_;
  double cell_size_ = 1.0;
  Point origin_{0.0, 0.0, 0.0};
  std::array<int, 3> n_buckets_{0, 0, 0};
  /// The most buckets a face's box reaches beyond its lower corner's, per axis.
  std::array<int, 3> span_{0, 0, 0};
  /// (bucket key of the box's lower corner, face), sorted.
  std::vector<std::pair<std::int64_t, int>> entries_;
};
} // namespace kiln
