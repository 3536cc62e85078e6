#include "physics/mechanics/gravity_kernel.hpp"

#include "base/errors.hpp"

namespace kiln
{
GravityKernel::GravityKernel(const Mesh &mesh, std::vector<TemperatureFunction> densities,
                             std::vector<char> weighed, std::map<int, int> kernel_of_block,
                             const Point &gravity)
    : densities_(std::move(densities)), weighed_(std::move(weighed)),
      material_of_cell_(mesh, std::move(kernel_of_block), static_cast<int>(densities_.size())),
      gravity_(gravity)
{
  KILN_ASSERT(weighed_.size() == densities_.size(), "a density without its flag");
}

void GravityKernel::evaluate(const CellState &state, LocalSystem &local) const
{
  const int material = material_of_cell_.of_cell(state.cell);
  if (!weighed_[material])
    return;
  const TemperatureFunction &density = densities_[material];
  const ElementValues &fe = state.fe;
  const int n = fe.n_shape();
  const int u_slot = state.slots.u;
  const int T_slot = state.slots.T;
  const bool coupled = T_slot >= 0 && local.has_jacobian();
  for (int q = 0; q < fe.n_qpoints(); ++q)
  {
    double T = 0.0;
    for (int j = 0; j < n; ++j)
      T += fe.shape(j, q) * state.T[j];
    const double JxW = fe.JxW(q);
    const double rho_JxW = density.value(T) * JxW;
    const double drho_JxW = coupled ? density.derivative(T) * JxW : 0.0;
    for (int i = 0; i < n; ++i)
    {
      const double phi_i = fe.shape(i, q);
      for (int d = 0; d < 3; ++d)
        local.residual(u_slot + d, i) -= rho_JxW * gravity_[d] * phi_i;
      if (!coupled)
        continue;
      for (int j = 0; j < n; ++j)
      {
        const double m = drho_JxW * fe.shape(j, q) * phi_i;
        for (int d = 0; d < 3; ++d)
          local.jacobian(u_slot + d, i, T_slot, j) -= m * gravity_[d];
      }
    }
  }
}
} // namespace kiln
