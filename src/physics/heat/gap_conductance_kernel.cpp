#include "physics/heat/gap_conductance_kernel.hpp"

#include "discretization/dof_manager.hpp"

namespace kiln
{
void GapConductanceKernel::evaluate(const FaceValues &fv, const Span<const double> T_a,
                                    const Span<const double> T_b, LocalSystem &local) const
{
  constexpr int T_field = static_cast<int>(Field::T);
  const int n = fv.n_shape(); // local nodes 0..n-1 on side a, n..2n-1 their twins
  for (int q = 0; q < fv.n_qpoints(); ++q)
  {
    double jump = 0.0;
    for (int j = 0; j < n; ++j)
      jump += fv.shape(j, q) * (T_a[j] - T_b[j]);
    const double JxW = fv.JxW(q);
    for (int i = 0; i < n; ++i)
    {
      const double flux_i = h_ * jump * fv.shape(i, q) * JxW;
      local.residual(T_field, i) += flux_i;
      local.residual(T_field, n + i) -= flux_i;
      if (!local.has_jacobian())
        continue;
      for (int j = 0; j < n; ++j)
      {
        const double m_ij = h_ * fv.shape(j, q) * fv.shape(i, q) * JxW;
        local.jacobian(T_field, i, T_field, j) += m_ij;
        local.jacobian(T_field, i, T_field, n + j) -= m_ij;
        local.jacobian(T_field, n + i, T_field, j) -= m_ij;
        local.jacobian(T_field, n + i, T_field, n + j) += m_ij;
      }
    }
  }
}

void GapConductanceKernel::evaluate(const InterfaceState &state, LocalSystem &local) const
{
  const int n = state.fv.n_shape();
  evaluate(state.fv, {state.T.data(), n}, {state.T.data() + n, n}, local);
}
} // namespace kiln
