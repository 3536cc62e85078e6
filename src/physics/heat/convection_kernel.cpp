#include "physics/heat/convection_kernel.hpp"

#include "discretization/dof_manager.hpp"

namespace kiln
{
void ConvectionKernel::evaluate(const FaceValues &fv, const Span<const double> T_nodes,
                                const ValueAt &T_ambient_at, LocalSystem &local) const
{
  constexpr int T_field = static_cast<int>(Field::T);
  for (int q = 0; q < fv.n_qpoints(); ++q)
  {
    double T = 0.0;
    for (int j = 0; j < fv.n_shape(); ++j)
      T += fv.shape(j, q) * T_nodes[j];
    const double JxW = fv.JxW(q);
    const double T_ambient = T_ambient_at(fv.quadrature_point(q));
    for (int i = 0; i < fv.n_shape(); ++i)
    {
      local.residual(T_field, i) += h_ * (T - T_ambient) * fv.shape(i, q) * JxW;
      if (!local.has_jacobian())
        continue;
      for (int j = 0; j < fv.n_shape(); ++j)
        local.jacobian(T_field, i, T_field, j) += h_ * fv.shape(j, q) * fv.shape(i, q) * JxW;
    }
  }
}
} // namespace kiln
