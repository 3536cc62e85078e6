#pragma once
/// A contact surface (issue 30): the faces of a boundary side set, with its own numbering of
/// their nodes and their geometry in a configuration x = X + u. Per-node data is indexed by
/// the surface's nodes (0 .. n_nodes() - 1, in increasing mesh node id), never by the mesh's.
/// Linear faces only (QUAD4, TRI3: faces of HEX8, TETRA4, WEDGE6, PYRAMID5).
#include "base/span.hpp"
#include "mesh/bounding_box.hpp"
#include "mesh/mesh.hpp"

#include <string>
#include <vector>

namespace kiln
{
class ContactSurface
{
public:
  /// The faces of side set `side_set_id` in the reference configuration X. Throws InputError
  /// naming `where` (the pair and its parameter) if the side set is not in the mesh, is a
  /// gap the mesh was split at, is empty, lists a face twice, has a face inside the mesh
  /// (shared by two cells) or a face that is not linear (QUAD8, QUAD9, TRI6).
  ContactSurface(const Mesh &mesh, int side_set_id, const std::string &where);
  /// As above (the same checks, on the whole side set), but with only the side set's faces of
  /// `cells` (increasing cell ids: a rank's owned cells) and their nodes. A node that also has
  /// faces of other cells gets its normal and nodal area from this part's faces only: what the
  /// parts give are summed to the node's owner (doc/contact.md, "Search").
  ContactSurface(const Mesh &mesh, int side_set_id, const std::string &where,
                 const std::vector<int> &cells);

  int side_set_id() const { return side_set_id_; }
  int n_faces() const { return static_cast<int>(face_types_.size()); }
  int n_nodes() const { return static_cast<int>(nodes_.size()); }

  /// The mesh node id of each surface node, increasing.
  const std::vector<int> &nodes() const { return nodes_; }
  /// The surface node of mesh node `mesh_node`, or -1 if it is not on the surface.
  int surface_node(int mesh_node) const;

  /// Face f: its type, its cell and local face in the mesh, its nodes (surface node ids, in
  /// the face's order: the right-hand rule gives the normal out of the cell).
  CellType face_type(const int f) const { return face_types_[f]; }
  int face_cell(const int f) const { return face_cells_[f]; }
  int face_side(const int f) const { return face_sides_[f]; }
  Span<const int> face_nodes(const int f) const
  {
    return {face_node_ids_.data() + face_offsets_[f], face_offsets_[f + 1] - face_offsets_[f]};
  }

  /// Moves the surface to x = X + u; `displacement` has a u per surface node [m].
  void set_displacement(const std::vector<Point> &displacement);
  /// The current position of each surface node [m].
  const std::vector<Point> &positions() const { return positions_; }
  /// The unit normal of surface node j out of its body: the normalized sum of its faces'
  /// integrals of N_j n dA (area-weighted).
  const Point &normal(const int j) const { return normals_[j]; }
  /// The integral of N_j over the node's faces (its share of the area) [m^2].
  double nodal_area(const int j) const { return nodal_areas_[j]; }
  /// The integral of n dA over face f (the face's area times its mean unit normal) [m^2].
  const Point &face_area_vector(const int f) const { return face_area_vectors_[f]; }
  /// The largest distance between two corners of face f [m].
  double face_diameter(const int f) const { return face_diameters_[f]; }
  /// The largest face diameter of the surface [m].
  double max_face_diameter() const { return max_face_diameter_; }
  /// The bounding box of face f's corners [m].
  const BoundingBox &face_box(const int f) const { return face_boxes_[f]; }

private:
  /// Keeps the side set's faces for which `keep(s)` (s: the side in the set) is true.
  template <typename Keep> void take_faces(const Mesh &mesh, const SideSet &set, Keep keep);
  void update_geometry();

  int side_set_id_;
  std::vector<int> nodes_;
  std::vector<Point> reference_positions_;
  std::vector<CellType> face_types_;
  std::vector<int> face_cells_;
  std::vector<int> face_sides_;
  std::vector<int> face_offsets_{0};
  std::vector<int> face_node_ids_;

  std::vector<Point> positions_;
  std::vector<Point> normals_;
  std::vector<double> nodal_areas_;
  std::vector<Point> face_area_vectors_;
  std::vector<double> face_diameters_;
  std::vector<BoundingBox> face_boxes_;
  double max_face_diameter_ = 0.0;
};
} // namespace kiln
