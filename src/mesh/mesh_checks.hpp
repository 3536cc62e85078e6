#pragma once
#include "mesh/mesh.hpp"

#include <string>

namespace kiln
{
/// Checks a mesh before use; throws InputError naming `where` and the entity:
/// node ids out of range, side-set faces out of range, a node that is not a
/// finite point, a cell smaller than 1e-9 m or larger than 1e6 m across (a wrong
/// unit: the message names `scale_parameter`, the input parameter that sets the
/// size, if given), and a cell whose Jacobian determinant is not positive at a
/// 2x2x2 Gauss point (inverted or degenerate cell, or a node order other than
/// Exodus HEX8), and a non-conforming mesh: faces of two cells that share three or more
/// corner nodes but are not the same face (a hex face against two tet faces), naming both
/// cells, their blocks and sides.
void check_mesh(const Mesh &mesh, const std::string &where,
                const std::string &scale_parameter = "");
} // namespace kiln
