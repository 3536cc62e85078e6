#include "physics/heat/heat_conduction_kernel.hpp"

#include "discretization/dof_manager.hpp"

#include <utility>

namespace kiln
{
HeatConductionKernel::HeatConductionKernel(const double rho_c, ConductivityModel conductivity,
                                           const Capacity capacity)
    : rho_c_(rho_c), capacity_(capacity), conductivity_(std::move(conductivity))
{
}

/// With `fixed` > 0 the cell is a HEX8 of `fixed` shape functions and as many points
/// (compile-time loop bounds).
template <int fixed>
void HeatConductionKernel::assemble(const ElementValues &fe, const NodalValues &T_nodes,
                                    const NodalValues &T_dot_nodes, const double dTdot_dT,
                                    LocalSystem &local) const
{
  const int n = fixed > 0 ? fixed : fe.n_shape();
  const int n_q = fixed > 0 ? fixed : fe.n_qpoints();
  constexpr int T_field = static_cast<int>(Field::T);
  const bool lumped = capacity_ == Capacity::lumped;
  for (int q = 0; q < n_q; ++q)
  {
    const double *phi = fe.shapes(q);
    const Point *grad_phi = fe.grads(q);
    double T = 0.0;
    double T_dot = 0.0;
    Point grad_T{0.0, 0.0, 0.0};
    for (int j = 0; j < n; ++j)
    {
      T += phi[j] * T_nodes[j];
      T_dot += phi[j] * T_dot_nodes[j];
      for (int d = 0; d < 3; ++d)
        grad_T[d] += grad_phi[j][d] * T_nodes[j];
    }
    const double k = conductivity_.value(T);
    const double dk_dT = conductivity_.derivative(T);
    const double JxW = fe.JxW(q);
    for (int i = 0; i < n; ++i)
    {
      const double phi_i = phi[i];
      const double grad_T_dot_grad_phi_i = dot(grad_T, grad_phi[i]);
      // The capacity term: at the point (consistent) or at the node (lumped by rows' sums).
      const double T_dot_capacity = lumped ? T_dot_nodes[i] : T_dot;
      local.residual(T_field, i) +=
          (rho_c_ * T_dot_capacity * phi_i + k * grad_T_dot_grad_phi_i) * JxW;
      if (!local.has_jacobian())
        continue;
      // Capacity: consistent rho c a φ_j φ_i, or lumped rho c a φ_i on the diagonal.
      const double capacity_i = rho_c_ * dTdot_dT * (lumped ? 0.0 : phi_i);
      for (int j = 0; j < n; ++j)
        local.jacobian(T_field, i, T_field, j) +=
            (capacity_i * phi[j] + k * dot(grad_phi[j], grad_phi[i]) +
             dk_dT * phi[j] * grad_T_dot_grad_phi_i) *
            JxW;
      if (lumped)
        local.jacobian(T_field, i, T_field, i) += rho_c_ * dTdot_dT * phi_i * JxW;
    }
  }
}

void HeatConductionKernel::evaluate(const ElementValues &fe, const NodalValues &T_nodes,
                                    const NodalValues &T_dot_nodes, const double dTdot_dT,
                                    LocalSystem &local) const
{
  if (fe.type() == CellType::hex8)
    assemble<hex8_n_nodes>(fe, T_nodes, T_dot_nodes, dTdot_dT, local);
  else
    assemble<0>(fe, T_nodes, T_dot_nodes, dTdot_dT, local);
}

void HeatConductionKernel::evaluate(const CellState &state, LocalSystem &local) const
{
  evaluate(state.fe, state.T, state.T_dot, state.dTdot_dT, local);
}
} // namespace kiln
