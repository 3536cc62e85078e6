#pragma once
/// A block of hexahedra, cut in two element blocks by the plane x = 0 of its
/// own frame, then rotated (phi about y, then theta about x) and translated.
/// Side sets as in the contact-box spec: 1 x = -Lx/2, 2 x = +Lx/2, 3 y = -Ly/2,
/// 4 y = +Ly/2, 5 z = -Lz/2, 6 z = +Lz/2, 10 the plane x = 0 listed from both
/// sides (block 1 first); named x_min, x_max, y_min, y_max, z_min, z_max (in the box's own
/// frame) and gap. Cells are numbered block 1 first, each block in
/// x-fastest order; nodes in x-fastest order.
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
  Mesh generate() const;
  /// The counts generate() makes, without making them (the gap split adds the nodes of the
  /// plane x = 0 once more).
  long long n_cells() const;
  long long n_nodes() const;

private:
  std::array<double, 3> size_;
  std::array<int, 3> cells_;
  double phi_;
  double theta_;
  std::array<double, 3> translation_;
};
} // namespace kiln
