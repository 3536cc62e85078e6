#pragma once
/// Two bodies meshed apart, for contact surfaces and their search (issue 30): each a block of
/// HEX8 cells mapped from the unit cube, with a side set on its bottom (zeta = 0) and its top
/// (zeta = 1) face. Body 1 is block 1 with side sets 3 (bottom) and 1 (top); body 2 is block
/// 2 with side sets 2 (bottom) and 4 (top): side sets 1 and 2 face each other across the gap.
/// Cells are numbered body 1 first, each x-fastest; side-set faces in cell order.
#include "mesh/mesh.hpp"

#include <Teuchos_ParameterList.hpp>

#include <array>
#include <functional>
#include <string>

namespace kiln_test
{
/// (xi, eta, zeta) in [0, 1]^3 to a point; right-handed, so that the cells are not inverted.
using BodyMap = std::function<kiln::Point(double xi, double eta, double zeta)>;

/// Appends a body of cells[0] x cells[1] x cells[2] cells mapped by `map` as block `block`,
/// its bottom faces as side set `bottom` and its top faces as side set `top`.
void add_body(kiln::Mesh &mesh, const std::array<int, 3> &cells, const BodyMap &map, int block,
              int bottom, int top);

/// Body 1 on [0, 1]^2 x [-0.2, 0] with n1[0] x n1[1] x 1 cells, body 2 on [0, 1]^2 x [gap, gap
/// + 0.2] with n2[0] x n2[1] x 1 cells [m].
kiln::Mesh two_flat_bodies(const std::array<int, 2> &n1, const std::array<int, 2> &n2, double gap);

/// Two arcs of cylindrical shells about the z axis over the angle [0, 1] rad and z in [0, 1]:
/// body 1 for radii [1.5, 2], body 2 for [2 + gap, 2.5] [m], with n1 and n2 (angle, z) cells
/// and one through the thickness. Side set 1: body 1's outer face; 2: body 2's inner one.
kiln::Mesh two_cylinder_shells(const std::array<int, 2> &n1, const std::array<int, 2> &n2,
                               double gap);

/// Two concentric cylindrical shell arcs about the z axis over the angle [0, 1] rad and z in
/// [0, 1] m, for a whole run: body 1 (block 1) on the radii [radii[0], radii[1]], body 2 (block
/// 2) on [radii[2], radii[3]] [m], with n1 and n2 (angle, radius) cells and one along z. Side
/// sets 1: body 1's outer face, 2: body 2's inner one (they face each other across the gap), 3:
/// body 1's inner face, 4: body 2's outer one; and, of both bodies, 5: the faces on the plane
/// angle 0, 6: on the plane angle 1 rad, 7: on z = 0 and z = 1 (for symmetry conditions).
kiln::Mesh concentric_shells(const std::array<double, 4> &radii, const std::array<int, 2> &n1,
                             const std::array<int, 2> &n2);

/// Moves every node by a deterministic pseudo-random vector of components in
/// [-amplitude, amplitude] [m].
void perturb(kiln::Mesh &mesh, double amplitude);
/// Rotates every node about the origin by phi about y, then theta about x [degrees].
void rotate(kiln::Mesh &mesh, double phi_degrees, double theta_degrees);
/// The point x rotated as rotate() rotates (`inverse`: the rotation undone).
kiln::Point rotated(const kiln::Point &x, double phi_degrees, double theta_degrees,
                    bool inverse = false);

/// The contact box's generator parameters (0.04 m, rotated by phi = 45, theta = -30) with its
/// halves meshed apart, 4x4x4 (block 1, x < 0) and 5x3x6 (block 2) cells of `cell_type`, the
/// second moved by `gap` along x (Mesh/Box "Second Half Cells", "Gap Width").
Teuchos::ParameterList box_halves_parameters(double gap, const std::string &cell_type = "HEX8");
} // namespace kiln_test
