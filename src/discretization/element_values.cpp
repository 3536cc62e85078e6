#include "discretization/element_values.hpp"

#include "base/errors.hpp"

#include <sstream>

namespace kiln
{
void ElementValues::reinit(const Mesh &mesh, const int c)
{
  const Span<const int> nodes = mesh.cell_nodes(c);
  for (int i = 0; i < nodes.size(); ++i)
    x_[i] = mesh.coordinates[nodes[i]];
  reinit(mesh.cell_type(c), x_.data());
}

void ElementValues::reinit(const CellType type, const Point *x)
{
  if (shape_ == nullptr || type != type_)
  {
    const ReferenceValues &ref = ReferenceValues::of(type);
    KILN_ASSERT(ref.n_shape > 0 && ReferenceCell::of(type).dim() == 3,
                "no volume basis for " << ReferenceCell::of(type).name());
    ref_grad_ = ref.grad.data();
    weights_ = ref.weights.data();
    type_ = type;
    n_shape_ = ref.n_shape;
    n_qpoints_ = ref.n_qpoints;
    shape_ = ref.shape.data();
    grad_.resize(ref.grad.size());
    JxW_.resize(n_qpoints_);
    quadrature_point_.resize(n_qpoints_);
  }
  // The common HEX8 (as many points as shape functions) with compile-time loop bounds.
  if (type_ == CellType::hex8)
    map<hex8_n_nodes>(x);
  else
    map<0>(x);
}

template <int fixed> void ElementValues::map(const Point *x)
{
  const int n = fixed > 0 ? fixed : n_shape_;
  const int n_q = fixed > 0 ? fixed : n_qpoints_;
  const CellType type = type_;
  for (int q = 0; q < n_q; ++q)
  {
    const double *N = shape_ + q * n;
    const Point *dN = ref_grad_ + q * n;
    double J[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}; // J[d][r] = dx_d/dxi_r
    Point xq{0, 0, 0};
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d)
      {
        xq[d] += N[i] * x[i][d];
        for (int r = 0; r < 3; ++r)
          J[d][r] += x[i][d] * dN[i][r];
      }
    // Cofactors: inv(J)[r][d] = C[d][r] / det, with C the cofactor matrix of J.
    const double C[3][3] = {
        {J[1][1] * J[2][2] - J[1][2] * J[2][1], J[1][2] * J[2][0] - J[1][0] * J[2][2],
         J[1][0] * J[2][1] - J[1][1] * J[2][0]},
        {J[0][2] * J[2][1] - J[0][1] * J[2][2], J[0][0] * J[2][2] - J[0][2] * J[2][0],
         J[0][1] * J[2][0] - J[0][0] * J[2][1]},
        {J[0][1] * J[1][2] - J[0][2] * J[1][1], J[0][2] * J[1][0] - J[0][0] * J[1][2],
         J[0][0] * J[1][1] - J[0][1] * J[1][0]}};
    const double det = J[0][0] * C[0][0] + J[0][1] * C[0][1] + J[0][2] * C[0][2];
    if (!(det > 0.0))
    {
      std::ostringstream msg;
      msg << "ElementValues::reinit: det(dx/dxi) = " << det << " <= 0 at quadrature point " << q
          << " of a " << ReferenceCell::of(type).name()
          << " (an inverted or degenerate cell; node 0 at (" << x[0][0] << ", " << x[0][1] << ", "
          << x[0][2] << "))";
      throw InternalError(msg.str());
    }
    // grad N_i = J^{-T} grad_xi N_i, component d: sum_r inv(J)[r][d] dN_r = sum_r C[d][r] dN_r /
    // det
    const double inv_det = 1.0 / det;
    Point *grad = grad_.data() + q * n;
    for (int i = 0; i < n; ++i)
    {
      // A copy: the stores to grad (Points too) would otherwise make the compiler reload
      // dN[i] for every component.
      const Point dN_i = dN[i];
      for (int d = 0; d < 3; ++d)
        grad[i][d] = (C[d][0] * dN_i[0] + C[d][1] * dN_i[1] + C[d][2] * dN_i[2]) * inv_det;
    }
    JxW_[q] = det * weights_[q];
    quadrature_point_[q] = xq;
  }
}
} // namespace kiln
