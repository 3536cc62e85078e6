#pragma once
/// Cells and faces with known geometry for the element, face and kernel tests: the unit cube,
/// affine images of cells and faces, parallelepipeds and parallelograms spanned by edge
/// vectors, and what makes their integrals closed forms. On a parallelepiped x = origin +
/// Σ_d ξ_d a_d, ξ in [0, 1]^3, the shape functions are products of the 1D linear functions
/// ℓ(ξ) = ξ or 1 - ξ, so every integral is a product of 1D integrals (mass_1d, sign) and the
/// cofactors of A = [a1 a2 a3] (∇φ = A^{-T} ∇_ξ φ̂, A^{-T} = cof(A) / det A).
#include "discretization/face_values.hpp"
#include "mesh/hex_geometry.hpp"
#include "support/tensors.hpp"

#include <array>

namespace kiln_test
{
/// The three edge vectors a_1, a_2, a_3 of a parallelepiped.
using Edges = std::array<Point, 3>;

/// HEX8 (Exodus) corner i at (ξ, η, ζ) in {0, 1}^3; face (quad) corner i counterclockwise.
inline constexpr int hex_corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
inline constexpr int quad_corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

/// fe.reinit on a HEX8 with these corners.
inline void reinit(kiln::ElementValues &fe, const kiln::HexNodes &x)
{
  fe.reinit(kiln::CellType::hex8, x.data());
}
/// fv.reinit on a QUAD4 face with these corners.
inline void reinit(kiln::FaceValues &fv, const kiln::QuadNodes &x)
{
  fv.reinit(kiln::CellType::quad4, x.data());
}

/// The unit cube [0,1]^3 in Exodus HEX8 order.
inline kiln::HexNodes unit_cube()
{
  return {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
}

/// The cell with its top and bottom faces exchanged: a reflection, an inverted cell (negative
/// Jacobian determinant).
inline kiln::HexNodes mirrored_cell(const kiln::HexNodes &x)
{
  kiln::HexNodes mirrored;
  for (int i = 0; i < 4; ++i)
  {
    mirrored[i] = x[i + 4];
    mirrored[i + 4] = x[i];
  }
  return mirrored;
}

/// The cell after x -> M x + b.
inline kiln::HexNodes mapped(const kiln::HexNodes &x, const Matrix3 &M, const Point &b)
{
  kiln::HexNodes y;
  for (int i = 0; i < 8; ++i)
  {
    y[i] = times(M, x[i]);
    for (int d = 0; d < 3; ++d)
      y[i][d] += b[d];
  }
  return y;
}

/// The face after x -> M x + b.
inline kiln::QuadNodes mapped_face(const kiln::QuadNodes &x, const Matrix3 &M, const Point &b)
{
  kiln::QuadNodes y;
  for (int i = 0; i < 4; ++i)
  {
    y[i] = times(M, x[i]);
    for (int d = 0; d < 3; ++d)
      y[i][d] += b[d];
  }
  return y;
}

/// The cell x = origin + Σ_d ξ_d edges[d], ξ in [0, 1]^3, in HEX8 order.
inline kiln::HexNodes parallelepiped(const Edges &edges, const Point &origin)
{
  kiln::HexNodes x;
  for (int i = 0; i < 8; ++i)
    for (int d = 0; d < 3; ++d)
    {
      x[i][d] = origin[d];
      for (int e = 0; e < 3; ++e)
        x[i][d] += hex_corner[i][e] * edges[e][d];
    }
  return x;
}

/// The face x = origin + s e1 + t e2, (s, t) in [0, 1]^2, counterclockwise about e1 x e2.
inline kiln::QuadNodes parallelogram(const Point &e1, const Point &e2, const Point &origin)
{
  kiln::QuadNodes x;
  for (int i = 0; i < 4; ++i)
    for (int d = 0; d < 3; ++d)
      x[i][d] = origin[d] + quad_corner[i][0] * e1[d] + quad_corner[i][1] * e2[d];
  return x;
}

/// A sheared, stretched and rotated parallelepiped (volume about 0.78) and its origin.
inline const Edges skew_edges = {{{1.2, 0.3, -0.2}, {-0.4, 0.9, 0.25}, {0.3, -0.1, 0.7}}};
inline const Point skew_origin{0.5, -1.0, 2.0};

/// The columns of cof(A) = det(A) A^{-T} for A = [a1 a2 a3]: a2 x a3, a3 x a1, a1 x a2
/// (the area vectors of the cell's faces).
inline Edges cofactor_columns(const Edges &a)
{
  return {cross(a[1], a[2]), cross(a[2], a[0]), cross(a[0], a[1])};
}

/// det A = a1 · (a2 x a3), the volume of the parallelepiped.
inline double volume(const Edges &a)
{
  return dot(a[0], cross(a[1], a[2]));
}

/// ±1: the sign of ∂ℓ/∂ξ of the 1D linear function of corner coordinate c (ξ or 1 - ξ).
inline double sign(const int c)
{
  return c == 1 ? 1.0 : -1.0;
}

/// ∫_0^1 ℓ_a ℓ_b dξ for the corner coordinates a, b: 1/3 if equal, 1/6 if not.
inline double mass_1d(const int a, const int b)
{
  return a == b ? 1.0 / 3.0 : 1.0 / 6.0;
}

/// ∫_[0,1]^3 ∂_d φ̂_i ∂_e φ̂_j dξ of the reference shape functions of corners i and j: a
/// product over the axes f of ∫ℓ'ℓ' = sign sign (f = d = e), ∫ℓ'ℓ = sign/2 (f = d or f = e)
/// and mass_1d (neither).
inline double reference_grad_grad(const int i, const int d, const int j, const int e)
{
  double reference = 1.0;
  for (int f = 0; f < 3; ++f)
  {
    const int ci = hex_corner[i][f], cj = hex_corner[j][f];
    if (f == d && f == e)
      reference *= sign(ci) * sign(cj);
    else if (f == d)
      reference *= 0.5 * sign(ci);
    else if (f == e)
      reference *= 0.5 * sign(cj);
    else
      reference *= mass_1d(ci, cj);
  }
  return reference;
}
} // namespace kiln_test
