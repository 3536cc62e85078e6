#pragma once
/// Private to src/io: a gap (one of the mesh's gap side sets) as a surface of its own, seen
/// from side a: one point per gap pair, one face (all its nodes) per cut face, and coordinates
/// in the gap's plane; or the faces of a side set (a contact pair's secondary surface), one
/// point per node.
#include "mesh/mesh.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace kiln
{
namespace internal
{
/// Point p is the p-th pair of gap `gap` in Mesh::gap_pairs (mesh pair pair[p]): at node_a's
/// coordinates. Face q is the q-th cut face of the gap in Mesh::gap_faces, of type
/// face_types[q] (TRI3, QUAD4, or a quadratic TRI6, QUAD8, QUAD9), its nodes as point numbers
/// in ReferenceCell::face_nodes order (the Exodus order, which is XDMF's and VTK's for faces). The
/// in-plane coordinates (s, t) of a point are measured from the area-weighted centroid of the gap
/// along e_s and e_t: with n the area-weighted mean normal, e_s is the first edge of the first face
/// projected onto the plane normal to n (for a structured mesh, s and t then follow its rows of
/// faces), and e_t = n x e_s. For a plane gap they are lengths along the gap [m]; for a curved one,
/// along its projection.
struct GapSurface
{
  /// Gap `gap`: an index into Mesh::gap_side_sets.
  GapSurface(const Mesh &mesh, int gap);
  /// The faces of `side_set` (e.g. a contact pair's secondary side set): a point per node of
  /// its faces (increasing node id), `pair` -1, node_a the node, node_b -1, `area` each
  /// face's area shared equally among its nodes, and n the area-weighted mean of the faces'
  /// outward normals.
  GapSurface(const Mesh &mesh, const SideSet &side_set);
  int n_points() const { return static_cast<int>(points.size()); }
  int n_faces() const { return static_cast<int>(faces.size()); }
  /// The type every face has, or none when the faces differ (or there are none).
  std::optional<CellType> face_type() const;

  std::vector<Point> points;                    ///< [m]
  std::vector<std::vector<std::int64_t>> faces; ///< point numbers of each face's nodes
  std::vector<CellType> face_types;             ///< each face's type
  std::vector<int> pair;                        ///< its index in Mesh::gap_pairs
  std::vector<std::int64_t> node_a;             ///< mesh node of each point (side a)
  std::vector<std::int64_t> node_b;             ///< its twin on side b
  std::vector<double> area;                     ///< the pair's share of the gap area [m^2]
  std::vector<double> s, t;                     ///< in-plane coordinates [m]

private:
  /// s and t of every point, from the area-weighted sums of the normal and of the position.
  void set_plane_coordinates(Point normal, Point centroid, double total_area);
};
/// The faces of `gap` as XDMF's Mixed topology lists them: per face its XDMF type code
/// (ReferenceCell::xdmf_code) and its nodes.
std::vector<std::int64_t> mixed_gap_connectivity(const GapSurface &gap);
} // namespace internal
} // namespace kiln
