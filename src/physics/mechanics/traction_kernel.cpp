#include "physics/mechanics/traction_kernel.hpp"

namespace kiln
{
void TractionKernel::evaluate(const FaceValues &fv, const Point &traction, const int u_slot,
                              LocalSystem &local)
{
  evaluate(fv, {ValueAt(traction[0]), ValueAt(traction[1]), ValueAt(traction[2])}, u_slot, local);
}

void TractionKernel::evaluate(const FaceValues &fv, const std::array<ValueAt, 3> &traction_at,
                              const int u_slot, LocalSystem &local)
{
  for (int q = 0; q < fv.n_qpoints(); ++q)
  {
    const Point &x = fv.quadrature_point(q);
    const Point traction{traction_at[0](x), traction_at[1](x), traction_at[2](x)};
    for (int i = 0; i < fv.n_shape(); ++i)
    {
      const double phi_i_JxW = fv.shape(i, q) * fv.JxW(q);
      for (int d = 0; d < 3; ++d)
        local.residual(u_slot + d, i) -= traction[d] * phi_i_JxW;
    }
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
