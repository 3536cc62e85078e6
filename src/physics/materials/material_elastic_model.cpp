#include "physics/materials/material_elastic_model.hpp"

namespace kiln
{
void MaterialElasticModel::evaluate(const PointInput &in, const double * /*old_state*/,
                                    double * /*new_state*/, PointResponse &out) const
{
  const double T = in.temperature;
  const double lambda = material_.lame_lambda(T), G = material_.shear_modulus(T);
  const double dlambda = material_.d_lame_lambda_d_T(T), dG = material_.d_shear_modulus_d_T(T);
  const double thermal = material_.thermal_strain(T);
  const double dthermal = material_.d_thermal_strain_d_T(T);
  Voigt e = in.strain;
  for (int I = 0; I < 3; ++I)
    e[I] -= thermal;
  const double trace = e[0] + e[1] + e[2];
  for (int I = 0; I < 6; ++I)
  {
    const bool normal = I < 3;
    out.stress[I] = (normal ? lambda * trace : 0.0) + 2.0 * G * e[I];
    out.stress_temperature_derivative[I] =
        (normal ? dlambda * trace - (3.0 * lambda + 2.0 * G) * dthermal : 0.0) + 2.0 * dG * e[I];
    if (in.derivatives && in.full_tangent)
      for (int J = 0; J < 6; ++J)
        out.tangent[I][J] = (normal && J < 3 ? lambda : 0.0) + (I == J ? 2.0 * G : 0.0);
  }
  out.isotropic.valid = true;
  out.isotropic.lambda = lambda;
  out.isotropic.shear = G;
}

double MaterialElasticModel::thermal_strain(const double temperature) const
{
  return material_.thermal_strain(temperature);
}
} // namespace kiln
