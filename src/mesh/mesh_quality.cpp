#include "mesh/mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <ostream>
#include <set>

namespace kiln
{
double jacobian_determinant(const Mesh &mesh, const int c, const ReferenceValues &ref, const int q)
{
  const Span<const int> nodes = mesh.cell_nodes(c);
  double J[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}; // J[d][r] = dx_d/dxi_r
  for (int i = 0; i < nodes.size(); ++i)
  {
    const Point &x = mesh.coordinates[nodes[i]];
    const Point &dN = ref.grad[q * ref.n_shape + i];
    for (int d = 0; d < 3; ++d)
      for (int r = 0; r < 3; ++r)
        J[d][r] += x[d] * dN[r];
  }
  return J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
         J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
}

std::vector<std::pair<int, int>> corner_edges(const ReferenceCell &cell)
{
  std::set<std::pair<int, int>> edges;
  for (int f = 0; f < cell.n_faces(); ++f)
  {
    const std::vector<int> &face = cell.face_nodes(f);
    const int corners = ReferenceCell::of(cell.face_type(f)).n_vertices();
    for (int i = 0; i < corners; ++i)
    {
      const int a = face[i], b = face[(i + 1) % corners];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  }
  return {edges.begin(), edges.end()};
}

CellQuality cell_quality(const Mesh &mesh, const int c)
{
  const ReferenceValues &ref = ReferenceValues::of(mesh.cell_type(c));
  double min_det = std::numeric_limits<double>::max(), max_det = -min_det;
  for (int q = 0; q < ref.n_qpoints; ++q)
  {
    const double det = jacobian_determinant(mesh, c, ref, q);
    min_det = std::min(min_det, det);
    max_det = std::max(max_det, det);
  }
  // Edge tables per type, built once.
  static std::map<CellType, std::vector<std::pair<int, int>>> edge_tables;
  static const bool built = []
  {
    for (const CellType type : ReferenceCell::volume_types())
      edge_tables[type] = corner_edges(ReferenceCell::of(type));
    return true;
  }();
  (void)built;
  const Span<const int> nodes = mesh.cell_nodes(c);
  double shortest = std::numeric_limits<double>::max(), longest = 0.0;
  for (const auto &[a, b] : edge_tables.at(mesh.cell_type(c)))
  {
    const Point &x = mesh.coordinates[nodes[a]], &y = mesh.coordinates[nodes[b]];
    const double length = std::hypot(x[0] - y[0], x[1] - y[1], x[2] - y[2]);
    shortest = std::min(shortest, length);
    longest = std::max(longest, length);
  }
  CellQuality quality;
  quality.jacobian_ratio = max_det > 0.0 ? min_det / max_det : min_det;
  quality.aspect_ratio =
      shortest > 0.0 ? longest / shortest : std::numeric_limits<double>::infinity();
  return quality;
}

std::vector<BlockQuality> mesh_quality(const Mesh &mesh)
{
  std::map<std::pair<int, CellType>, BlockQuality> entries;
  for (int c = 0; c < mesh.n_cells(); ++c)
  {
    const CellQuality q = cell_quality(mesh, c);
    auto [it, inserted] = entries.try_emplace({mesh.block_id[c], mesh.cell_type(c)});
    BlockQuality &e = it->second;
    if (inserted)
    {
      e.block = mesh.block_id[c];
      e.type = mesh.cell_type(c);
      e.min_jacobian_ratio = e.max_jacobian_ratio = q.jacobian_ratio;
      e.min_aspect_ratio = e.max_aspect_ratio = q.aspect_ratio;
    }
    ++e.n_cells;
    e.min_jacobian_ratio = std::min(e.min_jacobian_ratio, q.jacobian_ratio);
    e.max_jacobian_ratio = std::max(e.max_jacobian_ratio, q.jacobian_ratio);
    e.min_aspect_ratio = std::min(e.min_aspect_ratio, q.aspect_ratio);
    e.max_aspect_ratio = std::max(e.max_aspect_ratio, q.aspect_ratio);
  }
  std::vector<BlockQuality> result;
  for (const auto &entry : entries)
    result.push_back(entry.second);
  return result;
}

void print_mesh_quality(const std::vector<BlockQuality> &quality, std::ostream &out)
{
  const auto flags = out.flags();
  const auto precision = out.precision();
  out << std::setprecision(3);
  out << "mesh quality (Jacobian ratio: min / max det J over a cell's quadrature points; aspect "
         "ratio: longest / shortest corner edge):\n";
  for (const BlockQuality &q : quality)
    out << "  block " << q.block << ": " << ReferenceCell::of(q.type).name() << ", " << q.n_cells
        << (q.n_cells == 1 ? " cell" : " cells") << ", Jacobian ratio " << q.min_jacobian_ratio
        << " to " << q.max_jacobian_ratio << ", aspect ratio " << q.min_aspect_ratio << " to "
        << q.max_aspect_ratio << "\n";
  out.flags(flags);
  out.precision(precision);
}
} // namespace kiln
