#pragma once
/// The quadrature rules of Kiln's element types (doc/elements.md lists each rule, its points
/// and the degree it integrates exactly). Built once per element type by its FiniteElement.
#include "elements/finite_element.hpp"

namespace kiln::quadrature
{
/// n-point Gauss-Legendre on [-1, 1], n = 1, 2 or 3: exact to degree 2n - 1.
Quadrature gauss_line(int n);
/// The 2^dim-point Gauss rule of [-1,1]^dim with the points in the order of the cell's
/// corners (point i at the corner i scaled by 1/sqrt(3)): hex8's and quad4's rule as Kiln
/// has always ordered it (hex_gauss_points()). Degree 3 in each coordinate.
Quadrature gauss_at_corners(const ReferenceCell &cell);
/// The n^dim-point tensor Gauss rule of [-1,1]^dim (dim = 2 or 3), x fastest.
Quadrature gauss_tensor(int dim, int n);
/// Triangle (unit simplex) rules: 3 points, degree 2 (Strang-Fix); 7 points, degree 5 (Radon).
Quadrature triangle_degree2();
Quadrature triangle_degree5();
/// Tetrahedron (unit simplex) rules: 4 points, degree 2; 14 points, degree 5 (Walkington),
/// all weights positive.
Quadrature tetrahedron_degree2();
Quadrature tetrahedron_degree5();
/// The wedge (triangle x [-1,1]): `triangle` times n-point Gauss in z, triangle points fastest.
Quadrature wedge(const Quadrature &triangle, int n);
/// The pyramid (base [-1,1]^2 at z = 0, apex (0,0,1)) as the collapsed cube
/// x = a (1 - z), y = b (1 - z): 2x2 Gauss in a, b times the 2-point Gauss-Jacobi rule of
/// weight (1 - z)^2 on [0, 1]. 8 points, exact for polynomials of degree 3 and for the mass
/// and stiffness integrands of the rational PYRAMID5 basis on affine pyramids.
Quadrature pyramid_collapsed();
} // namespace kiln::quadrature
