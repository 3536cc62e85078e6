#include "mesh/box_mesh_generator.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "mesh/hex_geometry.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <tuple>
#include <unordered_map>

namespace kiln
{
namespace
{
using Lattice = std::array<int, 3>;

/// A cell of the grid before its nodes are numbered: its type, element block and corners on
/// the grid at half the spacing (a corner (i, j, k) is (2i, 2j, 2k)).
struct GridCell
{
  CellType type;
  int block;
  std::vector<Lattice> corners;
};

/// det(b - a, c - a, d - a): six times the signed volume of the tetrahedron a, b, c, d.
int lattice_det(const Lattice &a, const Lattice &b, const Lattice &c, const Lattice &d)
{
  const auto e = [&](const Lattice &p, const int k) { return p[k] - a[k]; };
  return e(b, 0) * (e(c, 1) * e(d, 2) - e(c, 2) * e(d, 1)) -
         e(b, 1) * (e(c, 0) * e(d, 2) - e(c, 2) * e(d, 0)) +
         e(b, 2) * (e(c, 0) * e(d, 1) - e(c, 1) * e(d, 0));
}

/// The tetrahedron a, b, c, d positively oriented (b and c swapped if it is not).
std::vector<Lattice> oriented_tet(const Lattice &a, const Lattice &b, const Lattice &c,
                                  const Lattice &d)
{
  if (lattice_det(a, b, c, d) < 0)
    return {a, c, b, d};
  return {a, b, c, d};
}

/// The 6 tetrahedra of Kuhn's split of the hexahedron with lowest corner `o`: a path from
/// corner 000 to 111 along the axes in each of the 6 orders.
std::vector<std::vector<Lattice>> kuhn_tets(const Lattice &o)
{
  const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  std::vector<std::vector<Lattice>> tets;
  for (const auto &order : orders)
  {
    std::vector<Lattice> path{o};
    Lattice at = o;
    for (const int axis : order)
    {
      at[axis] += 2;
      path.push_back(at);
    }
    tets.push_back(oriented_tet(path[0], path[1], path[2], path[3]));
  }
  return tets;
}

/// The hexahedron with lowest corner `o` split on its centre node into one cell per face:
/// a PYRAMID5 on the face (block `pyramid_block`), or, where `tets_on(face)`, two TETRA4 on the
/// face's halves cut by its diagonal from its lowest corner (as Kuhn's split cuts it, so that
/// the face matches a Kuhn neighbour; block `tet_block`). Faces: x-, x+, y-, y+, z-, z+.
std::vector<GridCell> pyramids_on_centre(const Lattice &o, const std::function<bool(int)> &tets_on,
                                         const int pyramid_block, const int tet_block)
{
  // Each face's corners in cyclic order from its lowest corner (offsets in cells).
  static const int faces[6][4][3] = {
      {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}}, {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}},
      {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}, {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}},
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
  const Lattice centre{o[0] + 1, o[1] + 1, o[2] + 1};
  std::vector<GridCell> cells;
  for (int f = 0; f < 6; ++f)
  {
    std::array<Lattice, 4> c;
    for (int v = 0; v < 4; ++v)
      for (int d = 0; d < 3; ++d)
        c[v][d] = o[d] + 2 * faces[f][v][d];
    if (tets_on(f))
    {
      cells.push_back({CellType::tet4, tet_block, oriented_tet(c[0], c[1], c[2], centre)});
      cells.push_back({CellType::tet4, tet_block, oriented_tet(c[0], c[2], c[3], centre)});
    }
    else if (lattice_det(c[0], c[1], c[3], centre) > 0) // the base counterclockwise from the apex
      cells.push_back({CellType::pyramid5, pyramid_block, {c[0], c[1], c[2], c[3], centre}});
    else
      cells.push_back({CellType::pyramid5, pyramid_block, {c[0], c[3], c[2], c[1], centre}});
  }
  return cells;
}

/// The linear cells the hexahedron with lowest corner `o` becomes in a box of one `type` (block
/// `block`), each in its linear type's Exodus order and positively oriented.
std::vector<GridCell> split_hexahedron(const CellType type, const Lattice &o, const int block)
{
  const auto corner = [&](const int a, const int b, const int c) {
    return Lattice{o[0] + 2 * a, o[1] + 2 * b, o[2] + 2 * c};
  };
  std::vector<GridCell> cells;
  if (type == CellType::tet4 || type == CellType::tet10)
    for (const auto &tet : kuhn_tets(o))
      cells.push_back({type, block, tet});
  else if (type == CellType::pyramid5)
    return pyramids_on_centre(
        o, [](int) { return false; }, block, block);
  else if (type == CellType::wedge6)
  {
    // The triangles 00-10-11 and 00-11-01, counterclockwise seen from +z, swept along z.
    for (const auto &tri : {std::array<std::array<int, 2>, 3>{{{0, 0}, {1, 0}, {1, 1}}},
                            std::array<std::array<int, 2>, 3>{{{0, 0}, {1, 1}, {0, 1}}}})
    {
      std::vector<Lattice> wedge;
      for (int c = 0; c < 2; ++c)
        for (const auto &v : tri)
          wedge.push_back(corner(v[0], v[1], c));
      cells.push_back({type, block, wedge});
    }
  }
  else
    cells.push_back({type,
                     block,
                     {corner(0, 0, 0), corner(1, 0, 0), corner(1, 1, 0), corner(0, 1, 0),
                      corner(0, 0, 1), corner(1, 0, 1), corner(1, 1, 1), corner(0, 1, 1)}});
  return cells;
}

/// The cells of the hexahedron (i, j, k) of the MIXED box of nx cells along x: HEX8 (block 1)
/// for x < 0; the first layer beyond, split on its centre into a PYRAMID5 on its face x = 0
/// (block 2) and two TETRA4 on each other face (block 3); Kuhn's TETRA4 beyond (block 3).
std::vector<GridCell> mixed_hexahedron(const int nx, const Lattice &o)
{
  const int i = o[0] / 2;
  if (i < nx / 2)
    return split_hexahedron(CellType::hex8, o, 1);
  if (i > nx / 2)
    return split_hexahedron(CellType::tet4, o, 3);
  return pyramids_on_centre(
      o, [](const int face) { return face != 0; }, 2, 3);
}

/// The grid points of all nodes of a cell of `type` whose corners are `corners`: the corners,
/// then the higher-order nodes mapped from their reference coordinates (the cells are
/// affine images of their reference cells on the grid).
std::vector<Lattice> cell_lattice_nodes(const CellType type, const std::vector<Lattice> &corners)
{
  const ReferenceCell &ref = ReferenceCell::of(type);
  std::vector<Lattice> nodes(corners);
  const bool hex = ref.n_vertices() == 8;
  // The origin and the three edge vectors of the affine map, with the reference coordinate
  // each multiplies (hex: (x + 1) / 2; tet: x).
  const Lattice &o = corners[0];
  const Lattice *ends[3] = {&corners[1], hex ? &corners[3] : &corners[2],
                            hex ? &corners[4] : &corners[3]};
  for (int n = ref.n_vertices(); n < ref.n_nodes(); ++n)
  {
    Lattice p = o;
    for (int e = 0; e < 3; ++e)
    {
      const double t = hex ? (ref.node(n)[e] + 1) / 2 : ref.node(n)[e];
      for (int d = 0; d < 3; ++d)
        p[d] += static_cast<int>(std::lround(t * ((*ends[e])[d] - o[d])));
    }
    nodes.push_back(p);
  }
  return nodes;
}

/// The number of cells of the box (in long double: exact below 2^64, no overflow above).
long double count_cells(const CellType type, const bool mixed, const std::array<int, 3> &cells)
{
  const long double nx = cells[0], column = static_cast<long double>(cells[1]) * cells[2];
  if (mixed) // hexahedra, the layer of 1 pyramid and 10 tets each, Kuhn's tets
    return column * (nx / 2 + 11 + 6 * (nx / 2 - 1));
  switch (type)
  {
  case CellType::tet4:
  case CellType::tet10:
  case CellType::pyramid5:
    return nx * column * 6;
  case CellType::wedge6:
    return nx * column * 2;
  default:
    return nx * column;
  }
}

/// The number of cells of one half (`half` 1: x < 0, 2: x > 0) of `cells` cells (its own
/// counts).
long double count_half_cells(const CellType type, const bool mixed, const int half,
                             const std::array<int, 3> &cells)
{
  const long double column = static_cast<long double>(cells[1]) * cells[2];
  if (mixed) // hexahedra; the layer of 1 pyramid and 10 tets each, Kuhn's tets
    return half == 1 ? column * cells[0] : column * (11 + 6 * (cells[0] - 1.0L));
  return count_cells(type, false, cells);
}

/// The number of nodes of a box of `cells` cells of `type` (MIXED: `mixed`).
long long count_nodes(const CellType type, const bool mixed, const std::array<int, 3> &cells)
{
  const long long nx = cells[0], ny = cells[1], nz = cells[2];
  const long long corners = (nx + 1) * (ny + 1) * (nz + 1);
  const long long edges =
      nx * (ny + 1) * (nz + 1) + (nx + 1) * ny * (nz + 1) + (nx + 1) * (ny + 1) * nz;
  const long long faces = nx * ny * (nz + 1) + nx * (ny + 1) * nz + (nx + 1) * ny * nz;
  if (mixed) // the centres of the pyramid layer
    return corners + ny * nz;
  switch (type)
  {
  case CellType::pyramid5: // and the centres
    return corners + nx * ny * nz;
  case CellType::hex20:
    return corners + edges;
  case CellType::hex27:
    return (2 * nx + 1) * (2 * ny + 1) * (2 * nz + 1);
  case CellType::tet10: // the grid's edges, one diagonal per square face and per hexahedron
    return corners + edges + faces + nx * ny * nz;
  default:
    return corners;
  }
}

/// Keeps the nodes that cells use, renumbered in their order.
void drop_unused_nodes(Mesh &mesh)
{
  std::vector<int> number(mesh.coordinates.size(), -1);
  for (const int n : mesh.cell_node_ids)
    number[n] = 0;
  std::vector<Point> kept;
  for (std::size_t n = 0; n < number.size(); ++n)
    if (number[n] == 0)
    {
      number[n] = static_cast<int>(kept.size());
      kept.push_back(mesh.coordinates[n]);
    }
  for (int &n : mesh.cell_node_ids)
    n = number[n];
  mesh.coordinates = std::move(kept);
}

/// Appends `second`'s cells, nodes and side sets to `mesh` (its side sets of the same ids
/// joined, block 1's faces first; its side set `cut` (10) as `cut_id`).
void append_half(Mesh &mesh, const Mesh &second, const int cut_id)
{
  const int node_offset = mesh.n_nodes(), cell_offset = mesh.n_cells();
  std::vector<int> nodes;
  for (int c = 0; c < second.n_cells(); ++c)
  {
    nodes.clear();
    for (const int n : second.cell_nodes(c))
      nodes.push_back(n + node_offset);
    mesh.add_cell(second.cell_type(c), nodes.data(), second.block_id[c]);
  }
  mesh.coordinates.insert(mesh.coordinates.end(), second.coordinates.begin(),
                          second.coordinates.end());
  for (const SideSet &set : second.side_sets)
  {
    SideSet *into = nullptr;
    if (set.id == 10)
    {
      mesh.side_sets.push_back({cut_id, "cut_2", {}, {}});
      into = &mesh.side_sets.back();
    }
    else
      for (SideSet &s : mesh.side_sets)
        if (s.id == set.id)
          into = &s;
    for (int s = 0; s < set.n_sides(); ++s)
    {
      into->cells.push_back(set.cells[s] + cell_offset);
      into->faces.push_back(set.faces[s]);
    }
  }
}
} // namespace

Teuchos::ParameterList BoxMeshGenerator::valid_parameters()
{
  Teuchos::ParameterList p("Box");
  p.set("Size", Teuchos::Array<double>(Teuchos::tuple(0.04, 0.04, 0.04)),
        "edge lengths Lx, Ly, Lz of the block in its own frame [m]",
        positive_double_array_validator(3));
  p.set("Cells", Teuchos::Array<int>(Teuchos::tuple(4, 4, 4)),
        "cells along x, y, z; the x count must be even so that x = 0 is a cell face [-]",
        positive_int_array_validator(3));
  p.set("Phi", 0.0, "rotation about the y axis, applied first [degrees]",
        double_range_validator(-360.0, 360.0));
  p.set("Theta", 0.0, "rotation about the x axis, applied second [degrees]",
        double_range_validator(-360.0, 360.0));
  p.set("Translation", Teuchos::Array<double>(Teuchos::tuple(0.0, 0.0, 0.0)),
        "translation applied after the rotation [m]", double_array_validator(3));
  p.set("Cell Type", "HEX8",
        "the cells: HEX8 the grid's hexahedra; TETRA4 each split in 6 tetrahedra (Kuhn); "
        "WEDGE6 in 2 wedges (prisms along z); HEX20, HEX27 quadratic hexahedra; TETRA10 the "
        "tetrahedra made quadratic; PYRAMID5 each split in 6 pyramids on its centre (one per "
        "face); MIXED: HEX8 for x < 0 (block 1), TETRA4 (Kuhn) for x > 0 (block 3) but the "
        "first layer of hexahedra there, each split on its centre into a PYRAMID5 on its face "
        "x = 0 (block 2) and 2 TETRA4 on each other face (block 3) (see doc/mesh.md) [-]",
        choice_validator(
            {"HEX8", "TETRA4", "WEDGE6", "PYRAMID5", "HEX20", "HEX27", "TETRA10", "MIXED"}));
  p.set("Second Half Cells", Teuchos::Array<int>(),
        "empty: one mesh, the halves sharing the nodes of x = 0 (as the gap split needs); "
        "three counts: the halves meshed apart (contact pairs between separately meshed "
        "bodies, Mechanics/Contact/Pairs), the half x < 0 with Cells[0] / 2 x Cells[1] x "
        "Cells[2] cells and the half x > 0 (edge Lx / 2 along x) with these cells along x, y, "
        "z; side sets 1..6 on both halves, 10 the cut face x = 0 of block 1 (named cut_1) and "
        "20 that of block 2 (cut_2); Mesh/\"Gap Side Set\" is then 0 (given nonzero: an error; see "
        "doc/mesh.md) "
        "[-]");
  p.set("Gap Width", 0.0,
        "with \"Second Half Cells\": the half x > 0 moved by this along x, before the "
        "rotation, so that the cut faces start this far apart (0: they touch at x = 0) [m]",
        nonnegative_double_validator());
  return p;
}

BoxMeshGenerator::BoxMeshGenerator(const Teuchos::ParameterList &p, const std::string &where)
    : where_(where)
{
  const auto &size = p.get<Teuchos::Array<double>>("Size");
  const auto &cells = p.get<Teuchos::Array<int>>("Cells");
  const auto &shift = p.get<Teuchos::Array<double>>("Translation");
  for (int d = 0; d < 3; ++d)
  {
    size_[d] = size[d];
    cells_[d] = cells[d];
    translation_[d] = shift[d];
  }
  phi_ = p.get<double>("Phi");
  theta_ = p.get<double>("Theta");
  mixed_ = p.get<std::string>("Cell Type") == "MIXED";      // linear cells: type_ stays HEX8
  for (const CellType type : ReferenceCell::volume_types()) // the validator allows only these
    if (ReferenceCell::of(type).name() == p.get<std::string>("Cell Type"))
      type_ = type;
  // Odd: suggest the even counts next to it that are valid (1 has only 2).
  const std::string even_choices =
      cells_[0] > 1 ? std::to_string(cells_[0] - 1) + " or " + std::to_string(cells_[0] + 1)
                    : std::string("2 (one cell on each side)");
  KILN_CHECK_INPUT(cells_[0] % 2 == 0, where + "/\"Cells\"",
                   "the x count is " << cells_[0]
                                     << " but must be even, so that the plane x = 0 between "
                                        "the two blocks is a cell face; use "
                                     << even_choices);
  const auto &second = p.get<Teuchos::Array<int>>("Second Half Cells");
  KILN_CHECK_INPUT(second.empty() ||
                       (second.size() == 3 &&
                        std::all_of(second.begin(), second.end(), [](int n) { return n > 0; })),
                   where + "/\"Second Half Cells\"",
                   "must be empty (one mesh) or three counts > 0 (the cells of the half x > 0 "
                   "along x, y, z), not "
                       << second);
  separate_ = !second.empty();
  for (int d = 0; d < 3 && separate_; ++d)
    second_cells_[d] = second[d];
  gap_width_ = p.get<double>("Gap Width");
  KILN_CHECK_INPUT(gap_width_ == 0.0 || separate_, where + "/\"Gap Width\"",
                   "is " << gap_width_
                         << " m, but the halves are one mesh: give \"Second Half Cells\" to "
                            "mesh them apart, or remove \"Gap Width\"");
  // Nodes and cells are numbered with int: refuse counts that overflow it before the
  // generator computes them.
  // Quadratic cells: up to the nodes of the grid at half the spacing.
  const long double m = ReferenceCell::of(type_).degree();
  const long double n_nodes =
      (m * cells_[0] + 1.0L) * (m * cells_[1] + 1.0L) * (m * cells_[2] + 1.0L);
  const long double n_cells = count_cells(type_, mixed_, cells_);
  if (separate_)
  {
    const long double n_second = (m * second_cells_[0] + 1.0L) * (m * second_cells_[1] + 1.0L) *
                                 (m * second_cells_[2] + 1.0L);
    KILN_CHECK_INPUT(
        n_nodes + n_second <= std::numeric_limits<int>::max(), where + "/\"Second Half Cells\"",
        "with the half x < 0, gives about "
            << static_cast<double>(n_nodes + n_second) << " nodes, more than the "
            << std::numeric_limits<int>::max() << " a Kiln mesh can number: use fewer cells");
  }
  KILN_CHECK_INPUT(n_nodes <= std::numeric_limits<int>::max(), where + "/\"Cells\"",
                   "{" << cells_[0] << ", " << cells_[1] << ", " << cells_[2] << "} gives "
                       << static_cast<double>(n_cells) << " cells and "
                       << static_cast<double>(n_nodes) << " nodes, more than the "
                       << std::numeric_limits<int>::max()
                       << " a Kiln mesh can number (and far more than fits in memory): use "
                          "fewer cells");
}

long long BoxMeshGenerator::n_cells() const
{
  if (!separate_)
    return static_cast<long long>(count_cells(type_, mixed_, cells_));
  return static_cast<long long>(
      count_half_cells(type_, mixed_, 1, {cells_[0] / 2, cells_[1], cells_[2]}) +
      count_half_cells(type_, mixed_, 2, second_cells_));
}

long long BoxMeshGenerator::n_nodes() const
{
  if (!separate_)
    return count_nodes(type_, mixed_, cells_);
  // MIXED: hexahedra for x < 0, the pyramids' centres and the corners for x > 0.
  return count_nodes(mixed_ ? CellType::hex8 : type_, false,
                     {cells_[0] / 2, cells_[1], cells_[2]}) +
         count_nodes(type_, mixed_, second_cells_);
}

Mesh BoxMeshGenerator::generate(const bool mid_y, const bool mid_z) const
{
  KILN_CHECK_INPUT(!separate_ || (!mid_y && !mid_z), where_ + "/\"Second Half Cells\"",
                   "meshes the halves apart, so the box has no mid-planes y = 0 and z = 0 "
                   "(side sets 11 and 12) to split at; remove them from Mesh/\"Gap Side "
                   "Sets\"");
  KILN_CHECK_INPUT(!mid_y || cells_[1] % 2 == 0, where_ + "/\"Cells\"",
                   "has " << cells_[1]
                          << " cells along y: side set 11 (the plane y = 0) needs an even "
                          << "number; use " << cells_[1] + 1);
  KILN_CHECK_INPUT(!mid_z || cells_[2] % 2 == 0, where_ + "/\"Cells\"",
                   "has " << cells_[2]
                          << " cells along z: side set 12 (the plane z = 0) needs an even "
                          << "number; use " << cells_[2] + 1);
  Mesh mesh;
  if (!separate_)
    mesh = grid(cells_, 0, mid_y, mid_z);
  else
  {
    mesh = grid(cells_, 1, false, false);
    for (SideSet &set : mesh.side_sets)
      if (set.id == 10)
        set.name = "cut_1";
    Mesh second = grid({2 * second_cells_[0], second_cells_[1], second_cells_[2]}, 2, false, false);
    for (Point &x : second.coordinates)
      x[0] += gap_width_;
    append_half(mesh, second, 20);
  }
  const auto A = rotation_matrix(phi_, theta_);
  for (Point &y : mesh.coordinates)
  {
    const Point x = y;
    for (int d = 0; d < 3; ++d)
      y[d] = A[d][0] * x[0] + A[d][1] * x[1] + A[d][2] * x[2] + translation_[d];
  }
  return mesh;
}

Mesh BoxMeshGenerator::grid(const std::array<int, 3> &cells_of_grid, const int only_half,
                            const bool mid_y, const bool mid_z) const
{
  const int nx = cells_of_grid[0], ny = cells_of_grid[1], nz = cells_of_grid[2];
  const int n_corners = (nx + 1) * (ny + 1) * (nz + 1);

  Mesh mesh;
  // A node at grid point p (on the grid at half the spacing): the grid's corners keep their
  // x-fastest numbers, the other points are numbered as first met.
  std::vector<Lattice> lattice(static_cast<std::size_t>(n_corners));
  std::unordered_map<long long, int> extra_nodes;
  const auto node_at = [&](const Lattice &p)
  {
    if (p[0] % 2 == 0 && p[1] % 2 == 0 && p[2] % 2 == 0)
      return p[0] / 2 + (nx + 1) * (p[1] / 2 + (ny + 1) * (p[2] / 2));
    const long long key = p[0] + (2LL * nx + 1) * (p[1] + (2LL * ny + 1) * p[2]);
    const auto [it, added] = extra_nodes.emplace(key, static_cast<int>(lattice.size()));
    if (added)
      lattice.push_back(p);
    return it->second;
  };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        lattice[i + (nx + 1) * (j + (ny + 1) * k)] = {2 * i, 2 * j, 2 * k};

  // The cells, block 1 (x < 0) first, each hexahedron of the grid in x-fastest order; MIXED's
  // blocks 2 and 3 (both x > 0) in block order, each in the order of the hexahedra.
  std::vector<GridCell> cells;
  for (int half = 1; half <= 2; ++half)
    for (int k = 0; k < nz && (only_half == 0 || only_half == half); ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = (half == 1 ? 0 : nx / 2); i < (half == 1 ? nx / 2 : nx); ++i)
        {
          const Lattice o{2 * i, 2 * j, 2 * k};
          const std::vector<GridCell> split =
              mixed_ ? mixed_hexahedron(nx, o) : split_hexahedron(type_, o, half);
          cells.insert(cells.end(), split.begin(), split.end());
        }
  std::stable_sort(cells.begin(), cells.end(),
                   [](const GridCell &a, const GridCell &b) { return a.block < b.block; });
  std::vector<int> nodes;
  for (const GridCell &cell : cells)
  {
    const std::vector<Lattice> points = cell_lattice_nodes(cell.type, cell.corners);
    nodes.resize(points.size());
    for (std::size_t n = 0; n < points.size(); ++n)
      nodes[n] = node_at(points[n]);
    mesh.add_cell(cell.type, nodes.data(), cell.block);
  }

  mesh.coordinates.resize(lattice.size());
  for (std::size_t n = 0; n < lattice.size(); ++n)
  {
    // A corner (2i, 2j, 2k) gives i / nx exactly as the grid of corners would.
    Point &x = mesh.coordinates[n];
    for (int d = 0; d < 3; ++d)
      x[d] = size_[d] * (lattice[n][d] % 2 == 0
                             ? double(lattice[n][d] / 2) / cells_of_grid[d] - 0.5
                             : double(lattice[n][d]) / (2 * cells_of_grid[d]) - 0.5);
  }

  // Side sets: 1..6 the outer planes, 10 the plane x = 0 (block 1's faces first: the cells are
  // in block order), 11 and 12 on request the planes y = 0 and z = 0 (the lower side's faces
  // first). A face is on a plane when all its corners are.
  const char *const face_names[6] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
  for (int s = 0; s < 6; ++s)
    mesh.side_sets.push_back({s + 1, face_names[s], {}, {}});
  mesh.side_sets.push_back({10, "gap", {}, {}});
  // For each set: its axis, its plane's grid coordinate, and (mid-planes) which side's faces.
  struct Plane
  {
    int set;
    int axis;
    int at;
    int side; // -1: any; 0: cells below the plane; 1: above
  };
  std::vector<Plane> planes;
  for (int d = 0; d < 3; ++d)
  {
    planes.push_back({2 * d, d, 0, -1});
    planes.push_back({2 * d + 1, d, 2 * cells_of_grid[d], -1});
  }
  planes.push_back({6, 0, nx, -1});
  for (const auto &[wanted, id, axis, name] :
       {std::tuple{mid_y, 11, 1, "mid_y"}, std::tuple{mid_z, 12, 2, "mid_z"}})
    if (wanted)
    {
      mesh.side_sets.push_back({id, name, {}, {}});
      const int set = static_cast<int>(mesh.side_sets.size()) - 1;
      planes.push_back({set, axis, cells_of_grid[axis], 0});
      planes.push_back({set, axis, cells_of_grid[axis], 1});
    }
  for (const Plane &plane : planes)
  {
    SideSet &set = mesh.side_sets[plane.set];
    for (int c = 0; c < mesh.n_cells(); ++c)
    {
      const Span<const int> cell = mesh.cell_nodes(c);
      const ReferenceCell &ref = mesh.reference_cell(c);
      int lowest = std::numeric_limits<int>::max();
      for (int n = 0; n < ref.n_vertices(); ++n)
        lowest = std::min(lowest, lattice[cell[n]][plane.axis]);
      if (plane.side >= 0 && (lowest < plane.at) != (plane.side == 0))
        continue;
      for (int f = 0; f < ref.n_faces(); ++f)
      {
        const std::vector<int> &face = ref.face_nodes(f);
        const int n_corners_f = ReferenceCell::of(ref.face_type(f)).n_vertices();
        bool on = true;
        for (int n = 0; n < n_corners_f && on; ++n)
          on = lattice[cell[face[n]]][plane.axis] == plane.at;
        if (on)
        {
          set.cells.push_back(c);
          set.faces.push_back(f);
        }
      }
    }
  }
  if (only_half != 0)
    drop_unused_nodes(mesh);
  return mesh;
}
} // namespace kiln
