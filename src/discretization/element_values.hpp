#pragma once
/// Values of the trilinear (Q1) shape functions of a hexahedron at the 2x2x2 Gauss points.
#include "mesh/hex_geometry.hpp"

#include <array>

namespace kiln
{
/// The eight trilinear shape functions of a HEX8 cell (Exodus node order) at the 2x2x2 Gauss
/// points of hex_gauss_points(), in the deal.II FEValues style: reinit() on a cell, then read
/// N_i(x_q) = shape(i, q), grad N_i(x_q) = grad(i, q) [1/m], JxW(q) = det(dx/dxi) w_q [m^3]
/// and x_q = quadrature_point(q) [m].
/// The reference values are computed once for all objects; reinit() maps the gradients with
/// the inverse Jacobian: grad N_i = J^{-T} grad_xi N_i, J = dx/dxi.
/// The quadrature is exact for the volume of any trilinear cell and for the stiffness
/// integrals of affine (parallelepiped) cells.
class ElementValues
{
public:
  static constexpr int n_points = 8;

  /// Maps the cell with these nodes. Throws InternalError if det(dx/dxi) <= 0 at a Gauss
  /// point (an inverted or degenerate cell: the mesh checks should have caught it).
  void reinit(const HexNodes &x);

  int n_qpoints() const { return n_points; }
  int n_shape() const { return n_hex_nodes; }
  /// N_i at Gauss point q [-].
  double shape(const int i, const int q) const { return (*shape_)[q][i]; }
  /// The physical gradient of N_i at Gauss point q [1/m].
  const Point &grad(const int i, const int q) const { return grad_[q][i]; }
  /// det(dx/dxi) times the Gauss weight (1) at point q [m^3].
  double JxW(const int q) const { return JxW_[q]; }
  /// The physical position of Gauss point q [m].
  const Point &quadrature_point(const int q) const { return quadrature_point_[q]; }

private:
  using ShapeTable = std::array<std::array<double, n_hex_nodes>, n_points>;
  using GradTable = std::array<std::array<Point, n_hex_nodes>, n_points>;
  /// N_i(xi_q), indexed [q][i].
  static const ShapeTable &reference_shape();
  /// grad_xi N_i(xi_q), indexed [q][i].
  static const GradTable &reference_grad();

  /// reference_shape(), looked up once: shape() is inlined in the kernels' loops.
  const ShapeTable *shape_ = &reference_shape();
  GradTable grad_{};
  std::array<double, n_points> JxW_{};
  std::array<Point, n_points> quadrature_point_{};
};
} // namespace kiln
