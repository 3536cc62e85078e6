#pragma once
/// The mesh as Kiln holds it: replicated on every rank (small and mid-size
/// meshes; a distributed mesh is future work). Cells of any ReferenceCell type, stored flat.
/// Node and cell numbers are global ids; they do not depend on the number of
/// ranks. Twin nodes made by the gap split are appended after the original
/// nodes, so an input mesh keeps its numbering.

#include "base/span.hpp"
#include "elements/reference_cell.hpp"

#include <algorithm>
#include <array>
#include <initializer_list>
#include <string>
#include <vector>

namespace kiln
{
inline double dot(const Point &a, const Point &b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// Exodus II HEX8 numbering. Nodes 0-3 are the bottom face counterclockwise
/// (seen from above), 4-7 the top face. Local faces in Exodus side order
/// (side k+1 is face k), nodes ordered so that the right-hand rule gives the
/// outward normal.
inline constexpr int n_hex_nodes = 8;
inline constexpr int n_hex_faces = 6;
inline constexpr int hex_face_nodes[n_hex_faces][4] = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                                       {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};

/// A side set: cell faces, as Exodus stores it (face = local face, Exodus side - 1).
/// A contact pair between separately meshed bodies (Mechanics/Contact/Pairs) as the results
/// show it: its name and the side set of its secondary surface (the nodes of its rows).
struct ContactPairSurface
{
  std::string name;
  int secondary_side_set = 0;
  /// Its surface's name in the results (an HDF5 group and XDMF grid, a CSV file's suffix):
  /// "pair_NAME".
  std::string surface_name() const { return "pair_" + name; }
};

struct SideSet
{
  int id = 0;
  std::string name;
  std::vector<int> cells;
  std::vector<int> faces;
  int n_sides() const { return static_cast<int>(cells.size()); }
};

/// A node pair across a split gap: node_a on side a, its twin node_b on side b (the copies
/// of one original node in the two parts of the mesh that the pair's faces separate; side a
/// is the part ranked first). `normal` is the area-weighted unit normal of the side-a faces
/// between the two parts at node_a (pointing from a to b); `area` is the node's share of
/// their area, the integral of its shape function over them. `gap`: the index of the gap
/// side set in Mesh::gap_side_sets. A node where gaps cross has a copy per part and is in a
/// pair with each copy it faces.
struct GapPair
{
  int node_a = -1;
  int node_b = -1;
  double area = 0.0;
  Point normal{0.0, 0.0, 0.0};
  int gap = 0;
};

/// A cut face of the gap seen from side a, with the twins of its nodes:
/// node_b[i] is the twin of the face's i-th node (ReferenceCell::face_nodes order).
struct GapFace
{
  int cell_a = -1;
  int face_a = -1;
  int cell_b = -1;
  int face_b = -1;
  std::vector<int> node_b;
  int gap = 0; ///< the index of its side set in Mesh::gap_side_sets
};

/// A cell face by its corner node ids in increasing order (a triangle's first entry is -1):
/// two cells share a face exactly when their faces have the same key.
using FaceKey = std::array<int, 4>;

struct Mesh
{
  std::vector<Point> coordinates; ///< per node [m]
  std::vector<int> block_id;      ///< per cell, the element block id
  std::vector<SideSet> side_sets; ///< in increasing id order

  // Filled by split_gaps():
  std::vector<int> gap_side_sets; ///< ids of the side sets the mesh was split at (none: empty)
  std::vector<GapPair> gap_pairs; ///< in increasing (node_a, node_b) order
  std::vector<GapFace> gap_faces; ///< the cut faces, seen from side a
  std::vector<int> parent_node;   ///< per node: the original node it copies (itself if not a twin)
  /// The contact pairs of Mechanics/Contact/Pairs (the input's order) as the results show
  /// them (their secondary surfaces and history columns); set with their rows.
  std::vector<ContactPairSurface> contact_pairs;
  /// Their names, in order.
  std::vector<std::string> contact_pair_names() const
  {
    std::vector<std::string> names;
    for (const ContactPairSurface &pair : contact_pairs)
      names.push_back(pair.name);
    return names;
  }

  int n_nodes() const { return static_cast<int>(coordinates.size()); }
  /// Whether side set `id` is one the mesh was split at.
  bool is_gap_side_set(const int id) const
  {
    return std::find(gap_side_sets.begin(), gap_side_sets.end(), id) != gap_side_sets.end();
  }
  /// The name of gap `gap` (an index into gap_side_sets) in the results: "gap" for the first,
  /// "gap_ID" for the others (ID: the side set's id), as the Exodus side sets are named.
  std::string gap_name(const int gap) const
  {
    return gap == 0 ? std::string("gap") : "gap_" + std::to_string(gap_side_sets[gap]);
  }
  int n_cells() const { return static_cast<int>(cell_types.size()); }
  /// The nodes of cell c (0-based ids, in its type's Exodus order).
  Span<const int> cell_nodes(const int c) const
  {
    return {cell_node_ids.data() + cell_offsets[c], cell_offsets[c + 1] - cell_offsets[c]};
  }
  Span<int> cell_nodes(const int c)
  {
    return {cell_node_ids.data() + cell_offsets[c], cell_offsets[c + 1] - cell_offsets[c]};
  }
  CellType cell_type(const int c) const { return cell_types[c]; }
  const ReferenceCell &reference_cell(const int c) const
  {
    return ReferenceCell::of(cell_types[c]);
  }
  /// The mesh node of the i-th node of local face `face` of cell c.
  int face_node(const int c, const int face, const int i) const
  {
    return cell_node_ids[cell_offsets[c] + reference_cell(c).face_nodes(face)[i]];
  }
  /// The mesh nodes of local face `face` of cell c, in the face's order.
  std::vector<int> face_nodes(int c, int face) const;
  /// Appends a cell of `type` in block `block` with these nodes (as many as the type has).
  void add_cell(CellType type, const int *nodes, int block);
  void add_cell(CellType type, std::initializer_list<int> nodes, int block)
  {
    add_cell(type, nodes.begin(), block);
  }
  /// The distinct cell types, in CellType order.
  std::vector<CellType> types() const;

  // The cells, flat (read them through cell_nodes() and cell_type()):
  std::vector<CellType> cell_types; ///< per cell
  std::vector<int> cell_offsets{0}; ///< cell c's nodes are cell_node_ids[offsets[c], offsets[c+1])
  std::vector<int> cell_node_ids;   ///< every cell's nodes, one cell after another
  /// The side set with this id, or nullptr.
  const SideSet *find_side_set(int id) const;
  /// The distinct block ids, sorted.
  std::vector<int> block_ids() const;
  /// The key of local face `face` of `cell`.
  FaceKey face_key(int cell, int face) const;
};
} // namespace kiln
