#include "mesh/mesh_checks.hpp"

#include "base/errors.hpp"
#include "elements/finite_element.hpp"
#include "mesh/mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace kiln
{
namespace
{
/// The largest distance from node 0 of a cell to its other nodes (std::hypot: the squares
/// of a cell 1e-170 m across underflow to 0, which made a tiny Coordinate Scale look like a
/// mesh of collapsed cells).
double cell_extent(const Mesh &mesh, const int c)
{
  const Span<const int> nodes = mesh.cell_nodes(c);
  const Point &x0 = mesh.coordinates[nodes[0]];
  double d = 0.0;
  for (const int n : nodes)
  {
    const Point &x = mesh.coordinates[n];
    d = std::max(d, std::hypot(x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]));
  }
  return d;
}

/// Cells outside [smallest_cell, largest_cell] metres come from a wrong scale, not from a
/// continuum problem; below it volumes and areas underflow, and every later step fails
/// with a message about something else (an inverted cell, a zero-area face).
constexpr double smallest_cell = 1e-9, largest_cell = 1e6; // [m]

void check_scale(const Mesh &mesh, const std::string &where, const std::string &scale_parameter)
{
  for (int n = 0; n < mesh.n_nodes(); ++n)
  {
    const Point &p = mesh.coordinates[n];
    KILN_CHECK_INPUT(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]), where,
                     "node " << n + 1 << " is at (" << p[0] << ", " << p[1] << ", " << p[2]
                             << "), not a finite point; "
                             << (scale_parameter.empty()
                                     ? std::string("the mesh is damaged: fix it")
                                     : "check " + scale_parameter));
  }
  int smallest = 0, largest = 0;
  double smallest_extent = std::numeric_limits<double>::max(), largest_extent = 0.0;
  for (int c = 0; c < mesh.n_cells(); ++c)
  {
    const double extent = cell_extent(mesh, c);
    if (extent < smallest_extent)
      smallest_extent = extent, smallest = c;
    if (extent > largest_extent)
      largest_extent = extent, largest = c;
  }
  const std::string hint =
      scale_parameter.empty() ? std::string("fix the mesh") : "check " + scale_parameter;
  // A scale that shrinks every cell below what Kiln resolves, some to zero where the
  // coordinates underflow, collapses the mesh: name the scale, not the cells' Jacobians.
  KILN_CHECK_INPUT(smallest_extent > 0.0 || largest_extent >= smallest_cell, where,
                   "every cell is below "
                       << smallest_cell << " m across (the largest, cell " << largest + 1 << ", is "
                       << largest_extent
                       << " m): the mesh has collapsed, to a point where "
                          "coordinates underflow to 0; "
                       << (scale_parameter.empty() ? std::string("fix the mesh")
                                                   : "the cause is " + scale_parameter));
  // An extent of exactly 0 is a collapsed cell, which the Jacobian check below reports.
  KILN_CHECK_INPUT(smallest_extent == 0.0 || smallest_extent >= smallest_cell, where,
                   "cell " << smallest + 1 << " (block " << mesh.block_id[smallest] << ") is only "
                           << smallest_extent << " m across, below " << smallest_cell
                           << " m: Kiln takes coordinates in metres and cannot resolve cells "
                              "this small; "
                           << hint);
  KILN_CHECK_INPUT(largest_extent <= largest_cell, where,
                   "cell " << largest + 1 << " (block " << mesh.block_id[largest] << ") is "
                           << largest_extent << " m across, above " << largest_cell
                           << " m: Kiln takes coordinates in metres; " << hint);
}

/// A cell face for the conformity check: its key (sorted corners) and where it is.
struct KeyedFace
{
  FaceKey key;
  int cell;
  int face;
};

/// How many corner nodes two face keys share (-1 entries do not count).
int shared_corners(const FaceKey &a, const FaceKey &b)
{
  int n = 0;
  for (const int x : a)
    n += x >= 0 && std::find(b.begin(), b.end(), x) != b.end() ? 1 : 0;
  return n;
}

/// Cells meet at whole faces: two faces of different cells that share three or more corner
/// nodes are the same face (the same corners). A hex face against two tet faces (the tets
/// split it along a diagonal) is not: each looks like a boundary face, and the fields are
/// not continuous across them. Only faces that no other cell shares can be such a pair.
void check_conforming(const Mesh &mesh, const std::string &where)
{
  std::vector<KeyedFace> faces;
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int f = 0; f < mesh.reference_cell(c).n_faces(); ++f)
      faces.push_back({mesh.face_key(c, f), c, f});
  std::sort(faces.begin(), faces.end(),
            [](const KeyedFace &a, const KeyedFace &b) { return a.key < b.key; });
  std::vector<KeyedFace> alone; // the faces of one cell only
  for (std::size_t i = 0; i < faces.size();)
  {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key)
      ++j;
    if (j == i + 1)
      alone.push_back(faces[i]);
    i = j;
  }
  std::vector<std::pair<int, int>> at_node; // (corner node, index into alone), sorted
  for (std::size_t k = 0; k < alone.size(); ++k)
    for (const int n : alone[k].key)
      if (n >= 0)
        at_node.emplace_back(n, static_cast<int>(k));
  std::sort(at_node.begin(), at_node.end());
  for (std::size_t k = 0; k < alone.size(); ++k)
  {
    const KeyedFace &a = alone[k];
    for (const int n : a.key)
    {
      if (n < 0)
        continue;
      auto it = std::lower_bound(at_node.begin(), at_node.end(), std::make_pair(n, 0));
      for (; it != at_node.end() && it->first == n; ++it)
      {
        const KeyedFace &b = alone[static_cast<std::size_t>(it->second)];
        KILN_CHECK_INPUT(b.cell == a.cell || shared_corners(a.key, b.key) < 3, where,
                         "the mesh is not conforming: cell "
                             << a.cell + 1 << " (block " << mesh.block_id[a.cell] << ", "
                             << mesh.reference_cell(a.cell).name() << ") side " << a.face + 1
                             << " and cell " << b.cell + 1 << " (block " << mesh.block_id[b.cell]
                             << ", " << mesh.reference_cell(b.cell).name() << ") side "
                             << b.face + 1
                             << " share corner nodes but are not the same face (e.g. a hex "
                                "face against two tet faces). Cells must meet at whole faces: "
                                "put pyramids between hexahedra and tetrahedra (Cubit does "
                                "when the tets are meshed against the hexes' faces)");
      }
    }
  }
}
} // namespace

void check_mesh(const Mesh &mesh, const std::string &where, const std::string &scale_parameter)
{
  KILN_CHECK_INPUT(mesh.n_cells() > 0, where, "the mesh has no cells");
  KILN_CHECK_INPUT(mesh.block_id.size() == mesh.cell_types.size(), where,
                   "the mesh has " << mesh.n_cells() << " cells but " << mesh.block_id.size()
                                   << " block ids");
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (const int n : mesh.cell_nodes(c))
      KILN_CHECK_INPUT(n >= 0 && n < mesh.n_nodes(), where,
                       "cell " << c + 1 << " (block " << mesh.block_id[c] << ") refers to node "
                               << n + 1 << " but the mesh has " << mesh.n_nodes() << " nodes");
  // Exodus keeps one element type per block: a block of two types cannot be written.
  std::map<int, int> first_cell_of_block;
  for (int c = 0; c < mesh.n_cells(); ++c)
  {
    const int first = first_cell_of_block.emplace(mesh.block_id[c], c).first->second;
    KILN_CHECK_INPUT(mesh.cell_type(c) == mesh.cell_type(first), where,
                     "element block " << mesh.block_id[c] << " holds cell " << first + 1 << " ("
                                      << mesh.reference_cell(first).name() << ") and cell " << c + 1
                                      << " (" << mesh.reference_cell(c).name()
                                      << "): a block has one element type; put the cells of "
                                         "each type in a block of their own");
  }
  std::vector<char> used(mesh.n_nodes(), 0);
  for (const int n : mesh.cell_node_ids)
    used[n] = 1;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    KILN_CHECK_INPUT(used[n], where,
                     "node " << n + 1 << " belongs to no cell; remove unused nodes from the mesh");
  for (const auto &s : mesh.side_sets)
    for (int k = 0; k < s.n_sides(); ++k)
      KILN_CHECK_INPUT(s.cells[k] >= 0 && s.cells[k] < mesh.n_cells() && s.faces[k] >= 0 &&
                           s.faces[k] < mesh.reference_cell(s.cells[k]).n_faces(),
                       where,
                       "side set " << s.id << " entry " << k + 1 << " (cell " << s.cells[k] + 1
                                   << ", side " << s.faces[k] + 1 << ") is not a face of the mesh");
  check_scale(mesh, where, scale_parameter);
  for (int c = 0; c < mesh.n_cells(); ++c)
  {
    // A flat cell's determinant is round-off of either sign: count as non-positive anything
    // below 1e-12 (d/2)^3, d the largest distance from node 0 (det ~ (h/2)^3 for a cube of side h).
    const double half = 0.5 * cell_extent(mesh, c), det_tolerance = 1e-12 * half * half * half;
    const ReferenceValues &ref = ReferenceValues::of(mesh.cell_type(c));
    for (int q = 0; q < ref.n_qpoints; ++q)
    {
      const double det = jacobian_determinant(mesh, c, ref, q);
      KILN_CHECK_INPUT(det > det_tolerance, where,
                       "cell " << c + 1 << " (block " << mesh.block_id[c]
                               << ") has a non-positive Jacobian determinant " << det
                               << " at a quadrature point: it is inverted or degenerate, or "
                                  "its nodes are not in Exodus "
                               << mesh.reference_cell(c).name() << " order; fix the mesh");
    }
  }
  check_conforming(mesh, where);
}
} // namespace kiln
