#include "io/gap_surface.hpp"

#include "mesh/hex_geometry.hpp"

#include <cmath>
#include <map>

namespace kiln
{
namespace internal
{
GapSurface::GapSurface(const Mesh &mesh, const int gap)
{
  // A node is in one pair of each gap it lies on: a point per pair of this gap.
  std::map<std::pair<int, int>, std::int64_t> point_of_pair;
  Point normal{0.0, 0.0, 0.0}, centroid{0.0, 0.0, 0.0};
  double total_area = 0.0;
  for (std::size_t k = 0; k < mesh.gap_pairs.size(); ++k)
  {
    const GapPair &gap_pair = mesh.gap_pairs[k];
    if (gap_pair.gap != gap)
      continue;
    point_of_pair[{gap_pair.node_a, gap_pair.node_b}] = static_cast<std::int64_t>(points.size());
    pair.push_back(static_cast<int>(k));
    points.push_back(mesh.coordinates[gap_pair.node_a]);
    node_a.push_back(gap_pair.node_a);
    node_b.push_back(gap_pair.node_b);
    area.push_back(gap_pair.area);
    total_area += gap_pair.area;
    for (int d = 0; d < 3; ++d)
    {
      normal[d] += gap_pair.area * gap_pair.normal[d];
      centroid[d] += gap_pair.area * mesh.coordinates[gap_pair.node_a][d];
    }
  }
  for (const GapFace &face : mesh.gap_faces)
  {
    if (face.gap != gap)
      continue;
    const ReferenceCell &cell = mesh.reference_cell(face.cell_a);
    const int n_corners = ReferenceCell::of(cell.face_type(face.face_a)).n_vertices();
    std::vector<std::int64_t> corners(static_cast<std::size_t>(n_corners));
    for (int i = 0; i < n_corners; ++i)
      corners[i] = point_of_pair.at({mesh.face_node(face.cell_a, face.face_a, i), face.node_b[i]});
    faces.push_back(std::move(corners));
  }
  if (points.empty())
    return;
  const double length = std::sqrt(dot(normal, normal));
  for (int d = 0; d < 3; ++d)
  {
    normal[d] = length > 0.0 ? normal[d] / length : (d == 0 ? 1.0 : 0.0);
    centroid[d] = total_area > 0.0 ? centroid[d] / total_area : points[0][d];
  }
  // Along the first edge of the first face (a mesh edge: for a structured mesh the
  // axes follow its rows of faces), else the coordinate axis most nearly in the plane.
  Point e_s{0.0, 0.0, 0.0};
  if (!faces.empty())
    for (int d = 0; d < 3; ++d)
      e_s[d] = points[faces[0][1]][d] - points[faces[0][0]][d];
  else
  {
    int axis = 0;
    for (int d = 1; d < 3; ++d)
      if (std::abs(normal[d]) < std::abs(normal[axis]))
        axis = d;
    e_s[axis] = 1.0;
  }
  const double along = dot(e_s, normal);
  for (int d = 0; d < 3; ++d)
    e_s[d] -= along * normal[d];
  const double s_length = std::sqrt(dot(e_s, e_s));
  for (double &c : e_s)
    c /= s_length;
  const Point e_t{normal[1] * e_s[2] - normal[2] * e_s[1], normal[2] * e_s[0] - normal[0] * e_s[2],
                  normal[0] * e_s[1] - normal[1] * e_s[0]};
  for (const Point &x : points)
  {
    const Point r{x[0] - centroid[0], x[1] - centroid[1], x[2] - centroid[2]};
    s.push_back(dot(r, e_s));
    t.push_back(dot(r, e_t));
  }
}
int GapSurface::corners_per_face() const
{
  if (faces.empty())
    return 0;
  for (const auto &face : faces)
    if (face.size() != faces.front().size())
      return 0;
  return static_cast<int>(faces.front().size());
}

std::vector<std::int64_t> mixed_gap_connectivity(const GapSurface &gap)
{
  std::vector<std::int64_t> list;
  for (const auto &face : gap.faces)
  {
    list.push_back(
        ReferenceCell::of(face.size() == 3 ? CellType::tri3 : CellType::quad4).xdmf_code());
    list.insert(list.end(), face.begin(), face.end());
  }
  return list;
}
} // namespace internal
} // namespace kiln
