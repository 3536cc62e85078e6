#include "mesh/contact_surface.hpp"

#include "base/errors.hpp"
#include "mesh/hex_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace kiln
{
namespace internal
{
/// The ids of the mesh's side sets, "1, 2, 10" (or "none"), for messages.
std::string side_set_list(const Mesh &mesh)
{
  std::string list;
  for (const auto &s : mesh.side_sets)
    list += (list.empty() ? "" : ", ") + std::to_string(s.id);
  return list.empty() ? "none" : list;
}

/// Throws unless every face of `set` is a linear face on the mesh's boundary, listed once.
void check_boundary_faces(const Mesh &mesh, const SideSet &set, const std::string &where)
{
  std::vector<std::pair<FaceKey, int>> keys; // (face, its side in the set)
  for (int s = 0; s < set.n_sides(); ++s)
  {
    const int c = set.cells[s], f = set.faces[s];
    const ReferenceCell &face = ReferenceCell::of(mesh.reference_cell(c).face_type(f));
    KILN_CHECK_INPUT(face.degree() == 1, where,
                     "side set " << set.id << " has a " << face.name() << " face (cell " << c + 1
                                 << ", side " << f + 1
                                 << "); contact pairs take linear faces only (QUAD4, TRI3): mesh "
                                    "the bodies with HEX8, TETRA4, WEDGE6 or PYRAMID5 cells");
    keys.emplace_back(mesh.face_key(c, f), s);
  }
  std::sort(keys.begin(), keys.end());
  // Every cell face that is one of the set's, by another cell: the face is inside the mesh.
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int f = 0; f < mesh.reference_cell(c).n_faces(); ++f)
    {
      const FaceKey key = mesh.face_key(c, f);
      const auto it = std::lower_bound(keys.begin(), keys.end(), std::make_pair(key, -1));
      if (it == keys.end() || it->first != key || set.cells[it->second] == c)
        continue;
      KILN_CHECK_INPUT(false, where,
                       "side set " << set.id << " is not on the boundary: its face (cell "
                                   << set.cells[it->second] + 1 << ", side "
                                   << set.faces[it->second] + 1 << ") is shared with cell " << c + 1
                                   << "; a contact pair names boundary side sets of two "
                                      "bodies meshed apart (to cut one mesh, use Kiln/Mesh/\"Gap "
                                      "Side Set\")");
    }
  // Listed twice by the same cell (by two cells it is inside the mesh, found above).
  for (std::size_t i = 1; i < keys.size(); ++i)
  {
    const int s = keys[i].second;
    KILN_CHECK_INPUT(keys[i].first != keys[i - 1].first, where,
                     "side set " << set.id << " lists cell " << set.cells[s] + 1 << ", side "
                                 << set.faces[s] + 1
                                 << " twice; a contact surface is a boundary side set, each face "
                                    "listed once");
  }
}

/// Side set `side_set_id` of the mesh after the checks a contact surface needs.
const SideSet &contact_side_set(const Mesh &mesh, const int side_set_id, const std::string &where)
{
  const SideSet *set = mesh.find_side_set(side_set_id);
  KILN_CHECK_INPUT(set != nullptr, where,
                   "side set " << side_set_id
                               << " is not in the mesh (side sets present: " << side_set_list(mesh)
                               << "); use the id of a boundary side set of one of the bodies");
  KILN_CHECK_INPUT(!mesh.is_gap_side_set(side_set_id), where,
                   "side set " << side_set_id
                               << " is a gap the mesh was split at (Kiln/Mesh/\"Gap Side Set\"); "
                                  "a contact pair names boundary side sets of bodies meshed "
                                  "apart: remove it from the pair or from the gaps");
  KILN_CHECK_INPUT(set->n_sides() > 0, where,
                   "side set " << side_set_id
                               << " has no faces; a contact surface needs the faces of a body's "
                                  "boundary: check the side set in the mesh");
  check_boundary_faces(mesh, *set, where);
  return *set;
}
} // namespace internal

ContactSurface::ContactSurface(const Mesh &mesh, const int side_set_id, const std::string &where)
    : side_set_id_(side_set_id)
{
  take_faces(mesh, internal::contact_side_set(mesh, side_set_id, where), [](int) { return true; });
}

ContactSurface::ContactSurface(const Mesh &mesh, const int side_set_id, const std::string &where,
                               const std::vector<int> &cells)
    : side_set_id_(side_set_id)
{
  const SideSet &set = internal::contact_side_set(mesh, side_set_id, where);
  take_faces(mesh, set,
             [&](const int s)
             { return std::binary_search(cells.begin(), cells.end(), set.cells[s]); });
}

template <typename Keep>
void ContactSurface::take_faces(const Mesh &mesh, const SideSet &set, const Keep keep)
{
  for (int s = 0; s < set.n_sides(); ++s)
    if (keep(s))
      for (const int n : mesh.face_nodes(set.cells[s], set.faces[s]))
        nodes_.push_back(n);
  std::sort(nodes_.begin(), nodes_.end());
  nodes_.erase(std::unique(nodes_.begin(), nodes_.end()), nodes_.end());
  for (int s = 0; s < set.n_sides(); ++s)
  {
    if (!keep(s))
      continue;
    const int c = set.cells[s], f = set.faces[s];
    face_types_.push_back(mesh.reference_cell(c).face_type(f));
    face_cells_.push_back(c);
    face_sides_.push_back(f);
    for (const int n : mesh.face_nodes(c, f))
      face_node_ids_.push_back(surface_node(n));
    face_offsets_.push_back(static_cast<int>(face_node_ids_.size()));
  }
  for (const int n : nodes_)
    reference_positions_.push_back(mesh.coordinates[n]);
  set_displacement(std::vector<Point>(nodes_.size(), Point{0.0, 0.0, 0.0}));
}

int ContactSurface::surface_node(const int mesh_node) const
{
  const auto it = std::lower_bound(nodes_.begin(), nodes_.end(), mesh_node);
  return it != nodes_.end() && *it == mesh_node ? static_cast<int>(it - nodes_.begin()) : -1;
}

void ContactSurface::set_displacement(const std::vector<Point> &displacement)
{
  KILN_ASSERT(displacement.size() == nodes_.size(),
              "a displacement per surface node: " << displacement.size() << " for "
                                                  << nodes_.size());
  positions_.resize(nodes_.size());
  for (std::size_t j = 0; j < nodes_.size(); ++j)
    for (int d = 0; d < 3; ++d)
      positions_[j][d] = reference_positions_[j][d] + displacement[j][d];
  update_geometry();
}

void ContactSurface::update_geometry()
{
  normals_.assign(nodes_.size(), Point{0.0, 0.0, 0.0});
  nodal_areas_.assign(nodes_.size(), 0.0);
  face_area_vectors_.assign(face_types_.size(), Point{0.0, 0.0, 0.0});
  face_diameters_.assign(face_types_.size(), 0.0);
  face_boxes_.resize(face_types_.size());
  max_face_diameter_ = 0.0;
  std::vector<Point> x;
  for (int f = 0; f < n_faces(); ++f)
  {
    const Span<const int> face = face_nodes(f);
    x.clear();
    for (const int j : face)
      x.push_back(positions_[j]);
    const FaceNodalAreas areas = face_nodal_areas(face_types_[f], x.data());
    for (int i = 0; i < face.size(); ++i)
    {
      nodal_areas_[face[i]] += areas.area[i];
      for (int d = 0; d < 3; ++d)
      {
        normals_[face[i]][d] += areas.area_vector[i][d];
        face_area_vectors_[f][d] += areas.area_vector[i][d];
      }
    }
    const int n_corners = ReferenceCell::of(face_types_[f]).n_vertices();
    face_boxes_[f] = BoundingBox::of(x.data(), n_corners);
    for (int a = 0; a < n_corners; ++a)
      for (int b = a + 1; b < n_corners; ++b)
      {
        const Point e{x[b][0] - x[a][0], x[b][1] - x[a][1], x[b][2] - x[a][2]};
        face_diameters_[f] = std::max(face_diameters_[f], std::sqrt(dot(e, e)));
      }
    max_face_diameter_ = std::max(max_face_diameter_, face_diameters_[f]);
  }
  for (Point &n : normals_)
  {
    const double length = std::sqrt(dot(n, n));
    if (length > 0.0)
      for (double &v : n)
        v /= length;
  }
}
} // namespace kiln
