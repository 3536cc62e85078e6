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
    const CellType type = mesh.reference_cell(face.cell_a).face_type(face.face_a);
    std::vector<std::int64_t> nodes(face.node_b.size());
    for (std::size_t i = 0; i < nodes.size(); ++i)
      nodes[i] = point_of_pair.at(
          {mesh.face_node(face.cell_a, face.face_a, static_cast<int>(i)), face.node_b[i]});
    faces.push_back(std::move(nodes));
    face_types.push_back(type);
  }
  set_plane_coordinates(normal, centroid, total_area);
}

GapSurface::GapSurface(const Mesh &mesh, const SideSet &side_set)
{
  std::map<int, std::int64_t> point_of_node;
  for (int k = 0; k < side_set.n_sides(); ++k)
  {
    const int n =
        ReferenceCell::of(mesh.reference_cell(side_set.cells[k]).face_type(side_set.faces[k]))
            .n_nodes();
    for (int i = 0; i < n; ++i)
      point_of_node[mesh.face_node(side_set.cells[k], side_set.faces[k], i)] = 0;
  }
  for (auto &[node, point] : point_of_node)
  {
    point = static_cast<std::int64_t>(points.size());
    points.push_back(mesh.coordinates[node]);
    pair.push_back(-1);
    node_a.push_back(node);
    node_b.push_back(-1);
  }
  area.assign(points.size(), 0.0);
  Point normal{0.0, 0.0, 0.0}, centroid{0.0, 0.0, 0.0};
  double total_area = 0.0;
  for (int k = 0; k < side_set.n_sides(); ++k)
  {
    const CellType type = mesh.reference_cell(side_set.cells[k]).face_type(side_set.faces[k]);
    const ReferenceCell &face = ReferenceCell::of(type);
    const int n = face.n_nodes();
    std::vector<std::int64_t> nodes(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
      nodes[i] = point_of_node.at(mesh.face_node(side_set.cells[k], side_set.faces[k], i));
    // Newell's vector of the corners (listed first, in order round the face): 2 A n.
    const int corners = face.n_vertices();
    Point twice{0.0, 0.0, 0.0};
    for (int i = 0; i < corners; ++i)
    {
      const Point &x = points[nodes[i]], &y = points[nodes[(i + 1) % corners]];
      twice[0] += (x[1] - y[1]) * (x[2] + y[2]);
      twice[1] += (x[2] - y[2]) * (x[0] + y[0]);
      twice[2] += (x[0] - y[0]) * (x[1] + y[1]);
    }
    const double face_area = 0.5 * std::sqrt(dot(twice, twice));
    for (const std::int64_t p : nodes)
      area[p] += face_area / n;
    for (int d = 0; d < 3; ++d)
    {
      normal[d] += 0.5 * twice[d];
      for (const std::int64_t p : nodes)
        centroid[d] += face_area / n * points[p][d];
    }
    total_area += face_area;
    faces.push_back(std::move(nodes));
    face_types.push_back(type);
  }
  set_plane_coordinates(normal, centroid, total_area);
}

void GapSurface::set_plane_coordinates(Point normal, Point centroid, const double total_area)
{
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
std::optional<CellType> GapSurface::face_type() const
{
  if (face_types.empty())
    return std::nullopt;
  for (const CellType type : face_types)
    if (type != face_types.front())
      return std::nullopt;
  return face_types.front();
}

std::vector<std::int64_t> mixed_gap_connectivity(const GapSurface &gap)
{
  std::vector<std::int64_t> list;
  for (std::size_t q = 0; q < gap.faces.size(); ++q)
  {
    list.push_back(ReferenceCell::of(gap.face_types[q]).xdmf_code());
    list.insert(list.end(), gap.faces[q].begin(), gap.faces[q].end());
  }
  return list;
}
} // namespace internal
} // namespace kiln
