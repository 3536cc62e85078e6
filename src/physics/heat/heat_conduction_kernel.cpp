#include "physics/heat/heat_conduction_kernel.hpp"

#include "base/errors.hpp"
#include "discretization/dof_manager.hpp"

#include <utility>

namespace kiln
{
HeatConductionKernel::HeatConductionKernel(Enthalpy enthalpy, ConductivityModel conductivity,
                                           const Capacity capacity)
    : enthalpy_(std::move(enthalpy)), rho_c_(enthalpy_.heat_capacity(0.0)), capacity_(capacity),
      conductivity_(std::move(conductivity))
{
}

HeatConductionKernel::HeatConductionKernel(const double rho_c, ConductivityModel conductivity,
                                           const Capacity capacity)
    : HeatConductionKernel(Enthalpy::constant(rho_c), std::move(conductivity), capacity)
{
}

double HeatConductionKernel::enthalpy_rate(const double T, const std::array<double, 2> &T_past,
                                           const double dTdot_dT,
                                           const TemperatureHistory &history) const
{
  double rate = dTdot_dT * enthalpy_.value(T);
  for (int k = 0; k < history.n; ++k)
    rate += history.weights[k] * enthalpy_.value(T_past[k]);
  return rate;
}

/// With `fixed` > 0 the cell is a HEX8 of `fixed` shape functions and as many points
/// (compile-time loop bounds).
template <int fixed, bool linear>
void HeatConductionKernel::assemble(const ElementValues &fe, const NodalValues &T_nodes,
                                    const NodalValues &T_dot_nodes, const double dTdot_dT,
                                    const TemperatureHistory &history, LocalSystem &local) const
{
  const int n = fixed > 0 ? fixed : fe.n_shape();
  const int n_q = fixed > 0 ? fixed : fe.n_qpoints();
  constexpr int T_field = static_cast<int>(Field::T);
  const bool lumped = capacity_ == Capacity::lumped;
  // rho c of T, lumped: Hdot and a rho c at each node.
  [[maybe_unused]] std::array<double, linear ? 1 : max_cell_nodes> H_dot_node{}, a_rho_c_node{};
  if constexpr (!linear)
    if (lumped)
      for (int i = 0; i < n; ++i)
      {
        const std::array<double, 2> T_past{history.n > 0 ? history.T_past[0][i] : 0.0,
                                           history.n > 1 ? history.T_past[1][i] : 0.0};
        H_dot_node[i] = enthalpy_rate(T_nodes[i], T_past, dTdot_dT, history);
        a_rho_c_node[i] = dTdot_dT * enthalpy_.heat_capacity(T_nodes[i]);
      }
  for (int q = 0; q < n_q; ++q)
  {
    const double *phi = fe.shapes(q);
    const Point *grad_phi = fe.grads(q);
    double T = 0.0;
    double T_dot = 0.0;
    std::array<double, 2> T_past{0.0, 0.0};
    Point grad_T{0.0, 0.0, 0.0};
    for (int j = 0; j < n; ++j)
    {
      T += phi[j] * T_nodes[j];
      if constexpr (linear)
        T_dot += phi[j] * T_dot_nodes[j];
      else
        for (int k = 0; k < history.n; ++k)
          T_past[k] += phi[j] * history.T_past[k][j];
      for (int d = 0; d < 3; ++d)
        grad_T[d] += grad_phi[j][d] * T_nodes[j];
    }
    const double k = conductivity_.value(T);
    const double dk_dT = conductivity_.derivative(T);
    const double JxW = fe.JxW(q);
    // The consistent capacity at the point: Hdot (rho c Tdot) and a rho c.
    double H_dot = rho_c_ * T_dot;
    double a_rho_c = rho_c_ * dTdot_dT;
    if constexpr (!linear)
      if (!lumped)
      {
        H_dot = enthalpy_rate(T, T_past, dTdot_dT, history);
        a_rho_c = dTdot_dT * enthalpy_.heat_capacity(T);
      }
    for (int i = 0; i < n; ++i)
    {
      const double phi_i = phi[i];
      const double grad_T_dot_grad_phi_i = dot(grad_T, grad_phi[i]);
      // The capacity term: at the point (consistent) or at the node (lumped by rows' sums).
      double H_dot_i = H_dot;
      if (lumped)
      {
        if constexpr (linear)
          H_dot_i = rho_c_ * T_dot_nodes[i];
        else
          H_dot_i = H_dot_node[i];
      }
      local.residual(T_field, i) += (H_dot_i * phi_i + k * grad_T_dot_grad_phi_i) * JxW;
      if (!local.has_jacobian())
        continue;
      // Capacity: consistent a rho c φ_j φ_i, or lumped a rho c φ_i on the diagonal.
      const double capacity_i = lumped ? 0.0 : a_rho_c * phi_i;
      for (int j = 0; j < n; ++j)
        local.jacobian(T_field, i, T_field, j) +=
            (capacity_i * phi[j] + k * dot(grad_phi[j], grad_phi[i]) +
             dk_dT * phi[j] * grad_T_dot_grad_phi_i) *
            JxW;
      if (lumped)
      {
        if constexpr (linear)
          local.jacobian(T_field, i, T_field, i) += a_rho_c * phi_i * JxW;
        else
          local.jacobian(T_field, i, T_field, i) += a_rho_c_node[i] * phi_i * JxW;
      }
    }
  }
}

void HeatConductionKernel::evaluate(const ElementValues &fe, const NodalValues &T_nodes,
                                    const NodalValues &T_dot_nodes, const double dTdot_dT,
                                    const TemperatureHistory &history, LocalSystem &local) const
{
  if (enthalpy_.is_linear())
  {
    if (fe.type() == CellType::hex8)
      assemble<hex8_n_nodes, true>(fe, T_nodes, T_dot_nodes, dTdot_dT, history, local);
    else
      assemble<0, true>(fe, T_nodes, T_dot_nodes, dTdot_dT, history, local);
    return;
  }
  KILN_ASSERT(dTdot_dT == 0.0 || history.n > 0,
              "a transient heat capacity of T without the past temperatures");
  if (fe.type() == CellType::hex8)
    assemble<hex8_n_nodes, false>(fe, T_nodes, T_dot_nodes, dTdot_dT, history, local);
  else
    assemble<0, false>(fe, T_nodes, T_dot_nodes, dTdot_dT, history, local);
}

void HeatConductionKernel::evaluate(const CellState &state, LocalSystem &local) const
{
  evaluate(state.fe, state.T, state.T_dot, state.dTdot_dT, state.history, local);
}
} // namespace kiln
