#pragma once
/// Geometry of trilinear hexahedra (Exodus HEX8 order) and bilinear quad faces.
#include "mesh/mesh.hpp"

#include <array>

namespace kiln
{
using HexNodes = std::array<Point, 8>;
using QuadNodes = std::array<Point, 4>;

/// The nodes of a cell.
HexNodes cell_nodes(const Mesh &mesh, int cell);
/// Appends `v` to the orthonormal `basis` (Gram-Schmidt, twice for accuracy) unless it is
/// within 1e-6 of their span; returns whether it was appended.
bool append_orthonormal(std::vector<Point> &basis, Point v);

/// The nodes of local face `face` of a cell, ordered for an outward normal.
QuadNodes face_nodes(const Mesh &mesh, int cell, int face);

/// Reference coordinates of HEX8 node i, each -1 or +1.
Point hex_reference_node(int i);
/// det(dx/dxi) at reference point `xi`.
double hex_jacobian_determinant(const HexNodes &x, const Point &xi);
/// The 2x2x2 Gauss points in the reference cube [-1,1]^3 (weights are 1).
const std::array<Point, 8> &hex_gauss_points();
/// Volume by 2x2x2 Gauss quadrature (exact for trilinear maps).
double hex_volume(const HexNodes &x);

/// For each face node i: the integral over the face of N_i n dA (the node's share of the area
/// vector) and of N_i dA (its share of the area), by the face type's quadrature. n follows
/// the right-hand rule of the node order.
struct FaceNodalAreas
{
  std::vector<Point> area_vector;
  std::vector<double> area;
};
/// Of a face of `face_type` with these node coordinates.
FaceNodalAreas face_nodal_areas(CellType face_type, const Point *x);
/// Of local face `face` of cell c.
FaceNodalAreas face_nodal_areas(const Mesh &mesh, int c, int face);

/// Rotation matrix A = Rx(theta) Ry(phi), angles in degrees, right-handed
/// (see doc/mesh.md and the contact-box spec).
std::array<std::array<double, 3>, 3> rotation_matrix(double phi_degrees, double theta_degrees);
} // namespace kiln
