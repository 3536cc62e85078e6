#include "physics/materials/linear_elastic_model.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"

namespace kiln
{
std::string LinearElasticModel::description()
{
  return "isotropic linear thermo-elasticity, sigma = lambda tr(eps - eps_th) I + 2G (eps - "
         "eps_th), eps_th = alpha (T - T_ref) I (doc/materials.md)";
}

Teuchos::ParameterList LinearElasticModel::valid_parameters()
{
  Teuchos::ParameterList p("Linear Elastic");
  p.set("Lame Lambda", 5.2e10,
        "lambda, the first Lame constant; the bulk modulus lambda + 2G/3 must be > 0 [Pa]");
  p.set("Shear Modulus", 2.6e10, "G (the second Lame constant mu), must be > 0 [Pa]",
        positive_double_validator());
  p.set("Thermal Expansion", 2.2e-5,
        "alpha, the linear thermal expansion coefficient, must be >= 0 [1/K]",
        nonnegative_double_validator());
  p.set("Reference Temperature", 298.0,
        "T_ref, the stress-free temperature: the thermal strain is alpha (T - T_ref); must be > "
        "0 [K]",
        positive_double_validator());
  return p;
}

LinearElasticModel::LinearElasticModel(const Teuchos::ParameterList &params,
                                       const std::string &where)
    : LinearElasticModel(params.get<double>("Lame Lambda"), params.get<double>("Shear Modulus"),
                         params.get<double>("Thermal Expansion"),
                         params.get<double>("Reference Temperature"))
{
  KILN_CHECK_INPUT(bulk_modulus() > 0.0, where + "/\"Lame Lambda\"",
                   "= " << lambda_ << " Pa gives the bulk modulus lambda + 2G/3 = "
                        << bulk_modulus() << " Pa with \"Shear Modulus\" = " << G_
                        << " Pa, but it must be > 0: give \"Lame Lambda\" > " << -2.0 * G_ / 3.0
                        << " Pa");
}

LinearElasticModel::LinearElasticModel(const double lambda, const double G, const double alpha,
                                       const double T_ref)
    : lambda_(lambda), G_(G), alpha_(alpha), T_ref_(T_ref)
{
}

void LinearElasticModel::evaluate(const PointInput &in, const double * /*old_state*/,
                                  double * /*new_state*/, PointResponse &out) const
{
  out.stress = elastic_stress(mechanical_strain(in.strain, in.temperature));
  if (!in.derivatives)
    return;
  if (in.full_tangent)
    out.tangent = elastic_tangent();
  out.stress_temperature_derivative = thermal_stress_derivative();
  out.isotropic = isotropic_tangent();
}

IsotropicTangent LinearElasticModel::isotropic_tangent() const
{
  IsotropicTangent t;
  t.valid = true;
  t.lambda = lambda_;
  t.shear = G_;
  return t;
}

Voigt LinearElasticModel::mechanical_strain(const Voigt &strain, const double T) const
{
  Voigt e = strain;
  const double thermal = alpha_ * (T - T_ref_);
  for (int i = 0; i < 3; ++i)
    e[i] -= thermal;
  return e;
}

Voigt LinearElasticModel::elastic_stress(const Voigt &elastic_strain) const
{
  const double volumetric = lambda_ * (elastic_strain[0] + elastic_strain[1] + elastic_strain[2]);
  Voigt stress;
  for (int i = 0; i < 6; ++i)
    stress[i] = 2.0 * G_ * elastic_strain[i] + (i < 3 ? volumetric : 0.0);
  return stress;
}

VoigtMatrix LinearElasticModel::elastic_tangent() const
{
  VoigtMatrix C{};
  for (int i = 0; i < 6; ++i)
  {
    C[i][i] = 2.0 * G_;
    for (int j = 0; j < 3 && i < 3; ++j)
      C[i][j] += lambda_;
  }
  return C;
}

Voigt LinearElasticModel::thermal_stress_derivative() const
{
  const double d = -(3.0 * lambda_ + 2.0 * G_) * alpha_;
  return {d, d, d, 0.0, 0.0, 0.0};
}
} // namespace kiln
