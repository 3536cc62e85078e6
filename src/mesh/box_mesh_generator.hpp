#pragma once
/// A block of hexahedra, cut in two element blocks by the plane x = 0 of its
/// own frame, then rotated (phi about y, then theta about x) and translated.
/// Side sets as in the contact-box spec: 1 x = -Lx/2, 2 x = +Lx/2, 3 y = -Ly/2,
/// 4 y = +Ly/2, 5 z = -Lz/2, 6 z = +Lz/2, 10 the plane x = 0 listed from both
/// sides (block 1 first); named x_min, x_max, y_min, y_max, z_min, z_max (in the box's own
/// frame) and gap. On request the mid-planes y = 0 (side set 11, mid_y) and z = 0 (12,
/// mid_z), each listed from its lower side first, for gaps that cross. Cells are numbered
/// block 1 first, each block in x-fastest order; nodes in x-fastest order.
/// "Cell Type" other than HEX8: each hexahedron of the grid becomes 6 tetrahedra (Kuhn's split,
/// every tet holding the diagonal from the cell's lowest to its highest corner, so that shared
/// faces are split alike), 2 wedges (the square in x, y cut by its diagonal from the lowest
/// corner, prisms along z) or a quadratic cell (HEX20, HEX27; TETRA10 on the Kuhn tets); the
/// cells of one hexahedron are numbered consecutively. The grid's corner nodes keep their
/// x-fastest numbers; mid-edge, face and centre nodes follow, numbered as first met, each
/// shared by the cells around it. Side sets list every face on their planes.
/// PYRAMID5: each hexahedron split on a centre node into 6 pyramids, one on each face.
/// MIXED: HEX8 for x < 0 (block 1); for x > 0, the first layer of hexahedra split on their
/// centres into a PYRAMID5 on the face x = 0 (block 2) and two TETRA4 on each other face, cut
/// as Kuhn's split cuts it (block 3), and Kuhn's TETRA4 beyond (block 3): a conforming mesh of
/// three types (doc/mesh.md).
/// "Second Half Cells" (issue 30): the halves meshed apart, with no node in common: x < 0 with
/// Cells[0] / 2 x Cells[1] x Cells[2] cells, x > 0 with its own counts, moved along x by "Gap
/// Width" before the rotation; side sets 1..6 on both, 10 the cut face x = 0 of block 1 and 20
/// that of block 2 (the pair's two surfaces); nodes and cells of block 1 first.
#include "mesh/mesh.hpp"

#include <Teuchos_ParameterList.hpp>

namespace kiln
{
class BoxMeshGenerator
{
public:
  static Teuchos::ParameterList valid_parameters();
  /// `params` must be validated; `where` names it in messages.
  BoxMeshGenerator(const Teuchos::ParameterList &params, const std::string &where);
  /// With `mid_y`, `mid_z`: side sets 11 and 12 as well (InputError naming `where` if the
  /// count of cells along that axis is odd, or if the halves are meshed apart).
  Mesh generate(bool mid_y = false, bool mid_z = false) const;
  /// Whether the halves are meshed apart ("Second Half Cells" given).
  bool separate_halves() const { return separate_; }
  /// The counts generate() makes, without making them (the gap split adds the nodes of the
  /// plane x = 0 once more).
  long long n_cells() const;
  long long n_nodes() const;

private:
  /// The box of `cells` in its own frame (not rotated): the whole box (`half` 0) or only the
  /// cells of one half (1: x < 0, 2: x > 0; its nodes alone, in the whole grid's order).
  Mesh grid(const std::array<int, 3> &cells, int half, bool mid_y, bool mid_z) const;

  std::array<double, 3> size_;
  std::array<int, 3> cells_;
  double phi_;
  double theta_;
  std::array<double, 3> translation_;
  CellType type_ = CellType::hex8;
  bool mixed_ = false; ///< "Cell Type" MIXED (type_ is then HEX8)
  bool separate_ = false;
  std::array<int, 3> second_cells_{0, 0, 0}; ///< the half x > 0's cells when separate_
  double gap_width_ = 0.0;
  std::string where_;
};
} // namespace kiln
