#pragma once
/// The shape quality of a mesh's cells, by block and element type (kiln --check): the
/// Jacobian ratio (min det J / max det J over a cell's quadrature points: 1 for an affine
/// cell, <= 0 for an inverted one) and the aspect ratio (longest / shortest edge between
/// corner nodes: 1 for a cube or a regular tetrahedron). Generic in the cell type: the
/// Jacobians come from ReferenceValues, the edges from the ReferenceCell's faces.
#include "elements/finite_element.hpp"
#include "mesh/mesh.hpp"

#include <iosfwd>
#include <utility>
#include <vector>

namespace kiln
{
/// det(dx/dxi) of cell c at quadrature point q of `ref` (the table of its type).
double jacobian_determinant(const Mesh &mesh, int c, const ReferenceValues &ref, int q);

/// The corner-node edges of a reference cell, as pairs of local node numbers (each once):
/// the sides of its faces' corner polygons.
std::vector<std::pair<int, int>> corner_edges(const ReferenceCell &cell);

struct CellQuality
{
  double jacobian_ratio = 1.0; ///< min det J / max det J over the quadrature points
  double aspect_ratio = 1.0;   ///< longest / shortest corner edge
};

/// The quality of cell c.
CellQuality cell_quality(const Mesh &mesh, int c);

/// The cells of one element type in one block, and their quality range.
struct BlockQuality
{
  int block = 0;
  CellType type = CellType::hex8;
  int n_cells = 0;
  double min_jacobian_ratio = 0.0, max_jacobian_ratio = 0.0;
  double min_aspect_ratio = 0.0, max_aspect_ratio = 0.0;
};

/// One entry per (block id, element type) present, in increasing block id, then CellType
/// order (a mixed block has one per type).
std::vector<BlockQuality> mesh_quality(const Mesh &mesh);

/// Writes the table kiln --check prints: a line per entry of `quality`.
void print_mesh_quality(const std::vector<BlockQuality> &quality, std::ostream &out);
} // namespace kiln
