#include "physics/heat/gap_conductance_kernel.hpp"

#include "discretization/dof_manager.hpp"

namespace kiln
{
void GapConductanceKernel::evaluate(const FaceValues &fv, const std::array<double, 4> &T_a,
                                    const std::array<double, 4> &T_b, LocalSystem &local) const
{
  constexpr int T_field = static_cast<int>(Field::T);
  for (int q = 0; q < fv.n_qpoints(); ++q)
  {
    double jump = 0.0;
    for (int j = 0; j < 4; ++j)
      jump += fv.shape(j, q) * (T_a[j] - T_b[j]);
    const double JxW = fv.JxW(q);
    for (int i = 0; i < 4; ++i)
    {
      const double flux_i = h_ * jump * fv.shape(i, q) * JxW;
      local.residual(T_field, i) += flux_i;
      local.residual(T_field, 4 + i) -= flux_i;
      if (!local.has_jacobian())
        continue;
      for (int j = 0; j < 4; ++j)
      {
        const double m_ij = h_ * fv.shape(j, q) * fv.shape(i, q) * JxW;
        local.jacobian(T_field, i, T_field, j) += m_ij;
        local.jacobian(T_field, i, T_field, 4 + j) -= m_ij;
        local.jacobian(T_field, 4 + i, T_field, j) -= m_ij;
        local.jacobian(T_field, 4 + i, T_field, 4 + j) += m_ij;
      }
    }
  }
}

void GapConductanceKernel::evaluate(const InterfaceState &state, LocalSystem &local) const
{
  std::array<double, 4> T_a{}, T_b{};
  for (int i = 0; i < 4; ++i)
  {
    T_a[i] = state.T[i];
    T_b[i] = state.T[4 + i];
  }
  evaluate(state.fv, T_a, T_b, local);
}
} // namespace kiln
