/// The table of reference cells: one entry per CellType (style.md §9: a new type is a new
/// entry here and a FiniteElement in src/discretization/elements/). Node and side numbering
/// are Exodus II's (the Exodus II manual, SAND92-2137, and SEACAS' Ioss element topologies);
/// faces list their corners so that the right-hand rule gives the outward normal (Exodus'
/// side order), then their mid-edge nodes and centre in the face type's own order. Checked
/// by tests/unit/discretization/reference_element_test.cpp. doc/elements.md has the pictures.
#include "elements/reference_cell.hpp"

#include "base/errors.hpp"

#include <array>
#include <string>

namespace kiln
{
namespace
{
constexpr CellType Q4 = CellType::quad4, T3 = CellType::tri3, Q8 = CellType::quad8,
                   Q9 = CellType::quad9, T6 = CellType::tri6;

// Functions, not namespace-scope objects: ReferenceCell::of() may run during another file's
// static initialisation.

/// Hexahedron corners: [-1,1]^3, bottom (z = -1) counterclockwise seen from +z, then top.
std::vector<Point> hex_corners()
{
  return {hex8_corners.begin(), hex8_corners.end()};
}
/// Exodus' hexahedron edges in mid-edge node order (nodes 8..19): bottom, verticals, top.
constexpr int hex_edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
                                  {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
/// Exodus' tetrahedron edges in mid-edge node order (nodes 4..9).
constexpr int tet_edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
/// Exodus' quadrilateral/triangle edges in mid-edge node order.
constexpr int quad_edges[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
constexpr int tri_edges[3][2] = {{0, 1}, {1, 2}, {2, 0}};

Point midpoint(const Point &a, const Point &b)
{
  return {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])};
}

/// `corners` followed by the midpoints of `edges`.
template <std::size_t n>
std::vector<Point> with_edge_midpoints(std::vector<Point> corners, const int (&edges)[n][2])
{
  const std::vector<Point> c = corners;
  for (const auto &e : edges)
    corners.push_back(midpoint(c[e[0]], c[e[1]]));
  return corners;
}

std::vector<Point> hex27_nodes()
{
  // Exodus HEX27: node 20 the centroid, then the face centres in the order -z, +z, -x, +x,
  // -y, +y (sides 5, 6, 4, 2, 1, 3): Ioss_Hex27's face_node_order and Shards' Hexahedron<27>.
  std::vector<Point> x = with_edge_midpoints(hex_corners(), hex_edges);
  const std::vector<Point> centres = {{0, 0, 0}, {0, 0, -1}, {0, 0, 1}, {-1, 0, 0},
                                      {1, 0, 0}, {0, -1, 0}, {0, 1, 0}};
  x.insert(x.end(), centres.begin(), centres.end());
  return x;
}

std::vector<Point> quad_corners()
{
  return {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
}
std::vector<Point> tri_corners()
{
  return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
}
std::vector<Point> tet_corners()
{
  return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
}

std::vector<Point> quad9_nodes()
{
  std::vector<Point> x = with_edge_midpoints(quad_corners(), quad_edges);
  x.push_back({0, 0, 0});
  return x;
}

// Faces, as Exodus numbers the sides (side s = face s - 1).
std::vector<std::vector<int>> hex8_faces()
{
  return {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};
}
std::vector<std::vector<int>> hex20_faces()
{
  return {{0, 1, 5, 4, 8, 13, 16, 12},  {1, 2, 6, 5, 9, 14, 17, 13}, {2, 3, 7, 6, 10, 15, 18, 14},
          {0, 4, 7, 3, 12, 19, 15, 11}, {0, 3, 2, 1, 11, 10, 9, 8},  {4, 5, 6, 7, 16, 17, 18, 19}};
}
std::vector<std::vector<int>> hex27_faces()
{
  return {{0, 1, 5, 4, 8, 13, 16, 12, 25},  {1, 2, 6, 5, 9, 14, 17, 13, 24},
          {2, 3, 7, 6, 10, 15, 18, 14, 26}, {0, 4, 7, 3, 12, 19, 15, 11, 23},
          {0, 3, 2, 1, 11, 10, 9, 8, 21},   {4, 5, 6, 7, 16, 17, 18, 19, 22}};
}
std::vector<std::vector<int>> tet4_faces()
{
  return {{0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 2, 1}};
}
std::vector<std::vector<int>> tet10_faces()
{
  return {{0, 1, 3, 4, 8, 7}, {1, 2, 3, 5, 9, 8}, {0, 3, 2, 7, 9, 6}, {0, 2, 1, 6, 5, 4}};
}
std::vector<std::vector<int>> wedge6_faces()
{
  return {{0, 1, 4, 3}, {1, 2, 5, 4}, {0, 3, 5, 2}, {0, 2, 1}, {3, 4, 5}};
}
/// Side 4 as the exodus library lists it ({0, 4, 3}: ex_get_side_set_node_list); Ioss writes
/// the same oriented triangle from another corner ({3, 0, 4}).
std::vector<std::vector<int>> pyramid5_faces()
{
  return {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {0, 4, 3}, {0, 3, 2, 1}};
}

/// XDMF's (VTK's) HEX20 order: the top edges (Exodus 16..19) before the vertical ones
/// (Exodus 12..15).
std::vector<int> hex20_xdmf_order()
{
  return {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 16, 17, 18, 19, 12, 13, 14, 15};
}
/// XDMF's (VTK's) HEX27 order: HEX20's, then the face centres -x, +x, -y, +y, -z, +z and the
/// centroid (Exodus 23, 24, 25, 26, 21, 22, 20).
std::vector<int> hex27_xdmf_order()
{
  std::vector<int> order = hex20_xdmf_order();
  order.insert(order.end(), {23, 24, 25, 26, 21, 22, 20});
  return order;
}

// XDMF topology codes (Xdmf2's XdmfTopology.h): Triangle 0x4, Quadrilateral 0x5, Tetrahedron
// 0x6, Pyramid 0x7, Wedge 0x8, Hexahedron 0x9, Quad_9 0x23, Tri_6 0x24, Quad_8 0x25, Tet_10
// 0x26, Hex_20 0x30, Hex_27 0x32. (XDMF orders the quadratic hexahedron's nodes as VTK does,
// not as Exodus: the writer permutes HEX20/HEX27, see doc/elements.md. So does the wedge: VTK's
// triangle (0, 1, 2) faces away from (3, 4, 5), Exodus' towards it; ParaView's XDMF reader
// gave every WEDGE6 a negative volume before the permutation, tests/tools/paraview_open_test.)
std::array<ReferenceCell, 12> make_table()
{
  return {{
      {CellType::hex8, "HEX8", 3, 1, 8, hex_corners(), hex8_faces(), {Q4, Q4, Q4, Q4, Q4, Q4}, 0x9},
      {CellType::tet4, "TETRA4", 3, 1, 4, tet_corners(), tet4_faces(), {T3, T3, T3, T3}, 0x6},
      {CellType::wedge6,
       "WEDGE6",
       3,
       1,
       6,
       {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}},
       wedge6_faces(),
       {Q4, Q4, Q4, T3, T3},
       0x8,
       {0, 2, 1, 3, 5, 4}},
      {CellType::pyramid5,
       "PYRAMID5",
       3,
       1,
       5,
       {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 1}},
       pyramid5_faces(),
       {T3, T3, T3, T3, Q4},
       0x7},
      {CellType::tet10,
       "TETRA10",
       3,
       2,
       4,
       with_edge_midpoints(tet_corners(), tet_edges),
       tet10_faces(),
       {T6, T6, T6, T6},
       0x26},
      {CellType::hex20,
       "HEX20",
       3,
       2,
       8,
       with_edge_midpoints(hex_corners(), hex_edges),
       hex20_faces(),
       {Q8, Q8, Q8, Q8, Q8, Q8},
       0x30,
       hex20_xdmf_order()},
      {CellType::hex27,
       "HEX27",
       3,
       2,
       8,
       hex27_nodes(),
       hex27_faces(),
       {Q9, Q9, Q9, Q9, Q9, Q9},
       0x32,
       hex27_xdmf_order()},
      {CellType::quad4, "QUAD4", 2, 1, 4, quad_corners(), {}, {}, 0x5},
      {CellType::tri3, "TRI3", 2, 1, 3, tri_corners(), {}, {}, 0x4},
      {CellType::quad8,
       "QUAD8",
       2,
       2,
       4,
       with_edge_midpoints(quad_corners(), quad_edges),
       {},
       {},
       0x25},
      {CellType::quad9, "QUAD9", 2, 2, 4, quad9_nodes(), {}, {}, 0x23},
      {CellType::tri6,
       "TRI6",
       2,
       2,
       3,
       with_edge_midpoints(tri_corners(), tri_edges),
       {},
       {},
       0x24},
  }};
}
} // namespace

const ReferenceCell &ReferenceCell::of(const CellType type)
{
  static const std::array<ReferenceCell, 12> table = make_table();
  const auto i = static_cast<std::size_t>(type);
  if (i >= table.size() || table[i].type() != type)
    throw InternalError("ReferenceCell::of: no reference cell for CellType " + std::to_string(i));
  return table[i];
}

const std::vector<CellType> &ReferenceCell::volume_types()
{
  static const std::vector<CellType> types = {CellType::hex8,     CellType::tet4,  CellType::wedge6,
                                              CellType::pyramid5, CellType::tet10, CellType::hex20,
                                              CellType::hex27};
  return types;
}
} // namespace kiln
