#pragma once
/// Values of a cell's shape functions at its quadrature points (deal.II's FEValues).
#include "elements/finite_element.hpp"
#include "mesh/mesh.hpp"

#include <array>
#include <vector>

namespace kiln
{
/// The shape functions of one cell of any volume type at its quadrature points, in the
/// deal.II FEValues style: reinit() on a cell, then read N_i(x_q) = shape(i, q),
/// grad N_i(x_q) = grad(i, q) [1/m], JxW(q) = det(dx/dxi) w_q [m^3] and x_q =
/// quadrature_point(q) [m]; i < n_shape(), q < n_qpoints(). The reference values come from
/// FiniteElement::of(type), tabulated once per type (ReferenceValues); reinit() maps the
/// gradients with the inverse Jacobian: grad N_i = J^{-T} grad_xi N_i, J = dx/dxi (an
/// isoparametric map). Kernels loop over n_qpoints() and n_shape() and never name a count.
class ElementValues
{
public:
  /// Maps cell c of `mesh`.
  void reinit(const Mesh &mesh, int c);
  /// Maps a cell of `type` with these node coordinates (as many as the type has nodes).
  /// Throws InternalError if det(dx/dxi) <= 0 at a quadrature point (an inverted or
  /// degenerate cell: the mesh checks should have caught it).
  void reinit(CellType type, const Point *x);

  CellType type() const { return type_; }
  int n_qpoints() const { return n_qpoints_; }
  int n_shape() const { return n_shape_; }
  /// N_i at quadrature point q [-].
  double shape(const int i, const int q) const { return shape_[q * n_shape_ + i]; }
  /// The physical gradient of N_i at quadrature point q [1/m].
  const Point &grad(const int i, const int q) const { return grad_[q * n_shape_ + i]; }
  /// N_0..N_{n_shape()-1} at point q: shapes(q)[i] == shape(i, q). The kernels' inner loops
  /// read a point's row through this (no stride to reload per shape function).
  const double *shapes(const int q) const { return shape_ + q * n_shape_; }
  /// The gradients at point q: grads(q)[i] == grad(i, q) [1/m].
  const Point *grads(const int q) const { return grad_.data() + q * n_shape_; }
  /// det(dx/dxi) times the quadrature weight at point q [m^3].
  double JxW(const int q) const { return JxW_[q]; }
  /// The physical position of quadrature point q [m].
  const Point &quadrature_point(const int q) const { return quadrature_point_[q]; }

private:
  /// Maps the cell (any type).
  void map(const Point *x);
  /// map() of a HEX8 (the common case), the same results from a table laid out for the vector
  /// units.
  void map_hex8(const Point *x);

  CellType type_ = CellType::hex8;
  int n_shape_ = 0;
  int n_qpoints_ = 0;
  /// ReferenceValues::of(type_).shape, looked up once per type: shape() is inlined in the
  /// kernels' loops.
  const double *shape_ = nullptr;
  const Point *ref_grad_ = nullptr; ///< ReferenceValues::of(type_).grad
  const double *weights_ = nullptr; ///< ReferenceValues::of(type_).weights
  std::vector<Point> grad_;
  std::vector<double> JxW_;
  std::vector<Point> quadrature_point_;
  std::array<Point, max_cell_nodes> x_; ///< the node coordinates of reinit(mesh, c)
};
} // namespace kiln
