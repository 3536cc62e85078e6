#include "physics/heat/heat_flux_kernel.hpp"

#include "discretization/dof_manager.hpp"

namespace kiln
{
void HeatFluxKernel::evaluate(const FaceValues &fv, const ValueAt &q, LocalSystem &local)
{
  constexpr int T_field = static_cast<int>(Field::T);
  for (int qp = 0; qp < fv.n_qpoints(); ++qp)
  {
    const double q_qp = q(fv.quadrature_point(qp));
    for (int i = 0; i < fv.n_shape(); ++i)
      local.residual(T_field, i) -= q_qp * fv.shape(i, qp) * fv.JxW(qp);
  }
}
} // namespace kiln
