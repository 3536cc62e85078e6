#pragma once
/// What lives on a reference cell (deal.II's FiniteElement, Intrepid2's bases): the Lagrange
/// shape functions of an element type and their reference gradients, and the quadrature rule
/// Kiln integrates it with (deal.II's Quadrature). Tabulated once per type by ElementValues
/// and FaceValues; kernels never see these, only the per-cell values.
#include "elements/reference_cell.hpp"

#include <vector>

namespace kiln
{
/// A quadrature rule on a reference cell: points (faces: third coordinate 0) and weights
/// (summing to the reference cell's measure).
struct Quadrature
{
  std::vector<Point> points;
  std::vector<double> weights;
  int size() const { return static_cast<int>(points.size()); }
};

/// The nodal (Lagrange) basis of one element type: N_i(node_j) = δ_ij, Σ N_i = 1.
class FiniteElement
{
public:
  virtual ~FiniteElement() = default;
  /// The basis of `type`; InternalError if none is registered.
  static const FiniteElement &of(CellType type);
  /// The basis of `type`, or nullptr if none is registered.
  static const FiniteElement *find(CellType type);

  virtual CellType type() const = 0;
  const ReferenceCell &cell() const { return ReferenceCell::of(type()); }
  int n_shape() const { return cell().n_nodes(); }
  /// N_i(xi), i < n_shape(), into `values`.
  virtual void values(const Point &xi, double *values) const = 0;
  /// ∂N_i/∂xi_k (faces: k < 2, the third component 0), into `gradients`.
  virtual void gradients(const Point &xi, Point *gradients) const = 0;
  /// The rule that integrates this element's mass and stiffness integrands on affine cells
  /// exactly (hex8: 2x2x2 Gauss, as Kiln has always used; quad4: 2x2).
  virtual const Quadrature &quadrature() const = 0;
};
/// A basis tabulated at its quadrature points, once per element type: N_i(xi_q) =
/// shape[q * n_shape + i], grad_xi N_i(xi_q) = grad[q * n_shape + i], weights w_q.
struct ReferenceValues
{
  int n_shape = 0;
  int n_qpoints = 0;
  std::vector<double> shape;
  std::vector<Point> grad;
  std::vector<double> weights;
  /// The table of `type` (computed on first use, then shared).
  static const ReferenceValues &of(CellType type);
};
} // namespace kiln
