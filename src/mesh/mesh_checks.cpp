#include "mesh/mesh_checks.hpp"

#include "base/errors.hpp"
#include "mesh/hex_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace kiln
{
void check_mesh(const Mesh &mesh, const std::string &where)
{
  KILN_CHECK_INPUT(mesh.n_cells() > 0, where, "the mesh has no cells");
  KILN_CHECK_INPUT(mesh.block_id.size() == mesh.connectivity.size(), where,
                   "the mesh has " << mesh.n_cells() << " cells but " << mesh.block_id.size()
                                   << " block ids");
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (const int n : mesh.connectivity[c])
      KILN_CHECK_INPUT(n >= 0 && n < mesh.n_nodes(), where,
                       "cell " << c + 1 << " (block " << mesh.block_id[c] << ") refers to node "
                               << n + 1 << " but the mesh has " << mesh.n_nodes() << " nodes");
  std::vector<char> used(mesh.n_nodes(), 0);
  for (const auto &cell : mesh.connectivity)
    for (const int n : cell)
      used[n] = 1;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    KILN_CHECK_INPUT(used[n], where,
                     "node " << n + 1 << " belongs to no cell; remove unused nodes from the mesh");
  for (const auto &s : mesh.side_sets)
    for (int k = 0; k < s.n_sides(); ++k)
      KILN_CHECK_INPUT(s.cells[k] >= 0 && s.cells[k] < mesh.n_cells() && s.faces[k] >= 0 &&
                           s.faces[k] < n_hex_faces,
                       where,
                       "side set " << s.id << " entry " << k + 1 << " (cell " << s.cells[k] + 1
                                   << ", side " << s.faces[k] + 1 << ") is not a face of the mesh");
  for (int c = 0; c < mesh.n_cells(); ++c)
  {
    const HexNodes x = cell_nodes(mesh, c);
    // A flat cell's determinant is round-off of either sign: count as non-positive anything
    // below 1e-12 (d/2)^3, d the largest distance from node 0 (det ~ (h/2)^3 for a cube of side h).
    double d2 = 0.0;
    for (int i = 1; i < n_hex_nodes; ++i)
      d2 = std::max(d2, (x[i][0] - x[0][0]) * (x[i][0] - x[0][0]) +
                            (x[i][1] - x[0][1]) * (x[i][1] - x[0][1]) +
                            (x[i][2] - x[0][2]) * (x[i][2] - x[0][2]));
    const double half = 0.5 * std::sqrt(d2), det_tolerance = 1e-12 * half * half * half;
    for (const Point &xi : hex_gauss_points())
    {
      const double det = hex_jacobian_determinant(x, xi);
      KILN_CHECK_INPUT(det > det_tolerance, where,
                       "cell " << c + 1 << " (block " << mesh.block_id[c]
                               << ") has a non-positive Jacobian determinant " << det
                               << " at a quadrature point: it is inverted or degenerate, or "
                                  "its nodes are not in Exodus HEX8 order; fix the mesh");
    }
  }
}
} // namespace kiln
