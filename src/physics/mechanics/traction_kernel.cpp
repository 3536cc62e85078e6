#include "physics/mechanics/traction_kernel.hpp"

namespace kiln
{
void TractionKernel::evaluate(const FaceValues &fv, const Point &traction, const int u_slot,
                              LocalSystem &local)
{
  for (int q = 0; q < fv.n_qpoints(); ++q)
    for (int i = 0; i < fv.n_shape(); ++i)
    {
      const double phi_i_JxW = fv.shape(i, q) * fv.JxW(q);
      for (int d = 0; d < 3; ++d)
        local.residual(u_slot + d, i) -= traction[d] * phi_i_JxW;
    }
}

void TractionKernel::evaluate_pressure(const FaceValues &fv, const ValueAt &pressure_at,
                                       const int u_slot, LocalSystem &local)
{
  for (int q = 0; q < fv.n_qpoints(); ++q)
  {
    const Point &normal = fv.normal(q);
    const double pressure = pressure_at(fv.quadrature_point(q));
    for (int i = 0; i < fv.n_shape(); ++i)
    {
      const double phi_i_JxW = fv.shape(i, q) * fv.JxW(q);
      for (int d = 0; d < 3; ++d)
        local.residual(u_slot + d, i) += pressure * normal[d] * phi_i_JxW;
    }
  }
}
} // namespace kiln
