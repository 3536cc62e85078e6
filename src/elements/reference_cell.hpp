#pragma once
/// What a cell is (style.md §9, deal.II's ReferenceCell, Shards' CellTopology): its nodes in
/// the reference domain and its faces, for every element type Kiln knows. Node numbering and
/// face (side) numbering follow Exodus II. One immutable object per type, looked up by type.
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace kiln
{
using Point = std::array<double, 3>;

/// The element types. Volume cells first, then the face types their faces have.
enum class CellType : unsigned char
{
  hex8,
  tet4,
  wedge6,
  pyramid5,
  tet10,
  hex20,
  hex27,
  quad4, ///< faces of hex8, wedge6, pyramid5
  tri3,  ///< faces of tet4, wedge6, pyramid5
  quad8, ///< faces of hex20
  quad9, ///< faces of hex27
  tri6,  ///< faces of tet10
};
/// How many CellTypes there are (for tables indexed by type).
inline constexpr int n_cell_types = static_cast<int>(CellType::tri6) + 1;
/// The most nodes a cell of any type has (a capacity for per-cell buffers).
inline constexpr int max_cell_nodes = 27;
/// The HEX8 reference cell's nodes, [-1,1]^3 in Exodus order: the bottom face (z = -1)
/// counterclockwise seen from +z, then the top face. ReferenceCell::of(CellType::hex8) is
/// made from them.
inline constexpr std::array<Point, 8> hex8_corners = {{{-1, -1, -1},
                                                       {1, -1, -1},
                                                       {1, 1, -1},
                                                       {-1, 1, -1},
                                                       {-1, -1, 1},
                                                       {1, -1, 1},
                                                       {1, 1, 1},
                                                       {-1, 1, 1}}};
/// HEX8's node count, the one home of the HEX8 fast path's size: ElementValues and the
/// kernels map and assemble a HEX8 cell with this compile-time bound for its shape functions
/// and its quadrature points (its 2x2x2 Gauss rule has a point per corner;
/// unit_finite_element checks both counts against FiniteElement::of(CellType::hex8)).
inline constexpr int hex8_n_nodes = static_cast<int>(hex8_corners.size());

class ReferenceCell
{
public:
  /// The reference cell of `type`.
  static const ReferenceCell &of(CellType type);
  /// The volume types, in CellType order (for messages listing what is supported).
  static const std::vector<CellType> &volume_types();

  CellType type() const { return type_; }
  /// Exodus' element type name, upper case ("HEX8", "TETRA4", "WEDGE6", "PYRAMID5",
  /// "TETRA10", "HEX20", "HEX27", "QUAD4", "TRI3", ...).
  const std::string &name() const { return name_; }
  /// 3 for a volume cell, 2 for a face.
  int dim() const { return dim_; }
  int n_nodes() const { return static_cast<int>(nodes_.size()); }
  /// The corner nodes (the first n_vertices() nodes).
  int n_vertices() const { return n_vertices_; }
  /// Reference coordinates of node i (faces: the third coordinate is 0). Hex: [-1,1]^3;
  /// tet: the unit simplex; wedge: triangle (unit simplex in x,y) times [-1,1] in z;
  /// pyramid: base [-1,1]^2 at z = 0, apex (0,0,1) (Exodus / Intrepid2 conventions).
  const Point &node(int i) const { return nodes_[i]; }
  /// Polynomial degree of its Lagrange basis (1 or 2).
  int degree() const { return degree_; }

  int n_faces() const { return static_cast<int>(faces_.size()); }
  /// Nodes of face f (Exodus side f + 1): corners first, ordered so that the right-hand rule
  /// gives the outward normal, then mid-side (and centre) nodes in the face type's order.
  const std::vector<int> &face_nodes(int f) const { return faces_[f]; }
  /// The type of face f.
  CellType face_type(int f) const { return face_types_[f]; }

  /// The XDMF topology type code of this type (Mixed topologies write it per cell).
  int xdmf_code() const { return xdmf_code_; }
  /// XDMF's (VTK's) node order where it differs from Exodus': XDMF node i is node
  /// xdmf_order()[i]; empty when the orders agree.
  const std::vector<int> &xdmf_order() const { return xdmf_order_; }

  ReferenceCell(CellType type, std::string name, int dim, int degree, int n_vertices,
                std::vector<Point> nodes, std::vector<std::vector<int>> faces,
                std::vector<CellType> face_types, int xdmf_code, std::vector<int> xdmf_order = {});

private:
  CellType type_;
  std::string name_;
  int dim_;
  int degree_;
  int n_vertices_;
  std::vector<Point> nodes_;
  std::vector<std::vector<int>> faces_;
  std::vector<CellType> face_types_;
  int xdmf_code_;
  std::vector<int> xdmf_order_;
};

/// The volume type of an Exodus element block: its type name in any case and with or without
/// the node count ("HEX8", "HEX", "HEXAHEDRON", "TETRA4", "TET", "TETRA", "WEDGE6", "WEDGE",
/// "PYRAMID5", "PYRAMID", "TETRA10", "HEX20", ...) and its nodes per element; none if Kiln has
/// no such volume type.
std::optional<CellType> exodus_cell_type(const std::string &name, int n_nodes_per_element);
/// "HEX8, TETRA4, ..." (the volume types Kiln supports), for messages.
std::string supported_volume_types();
} // namespace kiln
