#include "physics/materials/mts_viscoplastic_model.hpp"

#include "base/parameters.hpp"

#include <cmath>
#include <sstream>

namespace kiln
{
std::string MtsViscoplasticModel::description()
{
  return "Truchas' MTS (mechanical threshold stress) viscoplasticity in von Mises form, "
         "integrated by backward Euler (doc/materials.md)";
}

/// The defaults are the aluminium of Truchas' viscoplastic-ring test (SI units).
Teuchos::ParameterList MtsViscoplasticModel::valid_parameters()
{
  Teuchos::ParameterList p = common_parameters("MTS");
  p.set("MTS b", 2.86e-10, "b, the Burgers vector length (Truchas' MTS_b), must be > 0 [m]",
        positive_double_validator());
  p.set("MTS D", 3.44e9,
        "D, in the shear modulus mu(T) = mu_0 - D/(exp(T_0/T) - 1) (Truchas' MTS_d) [Pa]");
  p.set("MTS edot_0i", 1.0e7,
        "the reference strain rate (Truchas' MTS_edot_0i), must be >= 0 [1/s]",
        nonnegative_double_validator());
  p.set("MTS g_0i", 3.6, "g_0i, a material constant (Truchas' MTS_g_0i), must be > 0 [-]",
        positive_double_validator());
  p.set("MTS k", 1.38e-23,
        "k, Boltzmann's constant in the units of mu b^3 / T (Truchas' MTS_k), must be > 0 [J/K]",
        positive_double_validator());
  p.set("MTS mu_0", 28.815e9,
        "mu_0, the reference shear modulus of mu(T) (Truchas' MTS_mu_0), must be > 0 [Pa]",
        positive_double_validator());
  p.set("MTS p_i", 0.5, "p_i, an exponent (Truchas' MTS_p_i), must be > 0 [-]",
        positive_double_validator());
  p.set("MTS q_i", 1.5, "q_i, an exponent (Truchas' MTS_q_i), must be > 0 [-]",
        positive_double_validator());
  p.set("MTS sig_a", 10.0e6, "sigma_a, the athermal stress (Truchas' MTS_sig_a), must be >= 0 [Pa]",
        nonnegative_double_validator());
  p.set("MTS sig_i", 107.2e6,
        "sigma_i, the stress of the obstacles to dislocation motion (Truchas' MTS_sig_i), must "
        "be > 0 [Pa]",
        positive_double_validator());
  p.set("MTS temp_0", 215.0, "T_0, in mu(T) (Truchas' MTS_temp_0), must be > 0 [K]",
        positive_double_validator());
  return p;
}

MtsViscoplasticModel::MtsViscoplasticModel(const Teuchos::ParameterList &params,
                                           const std::string &where)
    : VonMisesViscoplasticModel(params, where, "MTS"), b_(params.get<double>("MTS b")),
      D_(params.get<double>("MTS D")), edot_0i_(params.get<double>("MTS edot_0i")),
      g_0i_(params.get<double>("MTS g_0i")), k_(params.get<double>("MTS k")),
      mu_0_(params.get<double>("MTS mu_0")), p_i_(params.get<double>("MTS p_i")),
      q_i_(params.get<double>("MTS q_i")), sig_a_(params.get<double>("MTS sig_a")),
      sig_i_(params.get<double>("MTS sig_i")), temp_0_(params.get<double>("MTS temp_0"))
{
}

VonMisesViscoplasticModel::TemperatureFactors
MtsViscoplasticModel::temperature_factors(const double T) const
{
  // mu(T) = mu_0 - D/(E - 1), E = exp(T_0/T); dE/dT = -E T_0/T^2.
  const double E = std::exp(temp_0_ / T);
  const double mu = mu_0_ - D_ / (E - 1.0);
  const double dmu_dT = -D_ * E * temp_0_ / (T * T * (E - 1.0) * (E - 1.0));
  const double b3_g_k = b_ * b_ * b_ * g_0i_ / k_;
  const double G0 = mu * b3_g_k / T;
  return {G0, b3_g_k * (dmu_dT / T - mu / (T * T)), mu * sig_i_ / mu_0_, dmu_dT * sig_i_ / mu_0_,
          edot_0i_ * std::exp(-G0)};
}

VonMisesViscoplasticModel::FlowRate
MtsViscoplasticModel::flow_rate_at(const double q, const TemperatureFactors &factors) const
{
  const double G0 = factors[0], dG0_dT = factors[1];
  const double sigma_hat = factors[2], dsigma_hat_dT = factors[3];
  FlowRate g;
  if (q < sig_a_)
  {
    // edot_0i exp(-G0) (q/sigma_a)^5, continuous with the middle range at sigma_a.
    const double ratio = q / sig_a_;
    const double ratio4 = (ratio * ratio) * (ratio * ratio);
    g.value = factors[4] * ratio4 * ratio;
    g.d_stress = 5.0 * factors[4] * ratio4 / sig_a_;
    g.d_temperature = -g.value * dG0_dT;
  }
  else if (q > sigma_hat + sig_a_)
    g.value = edot_0i_;
  else
  {
    // g = edot_0i exp(-G0 h), h = y^q_i, y = 1 - x^p_i, x = (q - sigma_a)/sigma_hat.
    const double x = (q - sig_a_) / sigma_hat;
    const double x_p = std::pow(x, p_i_);
    const double y = 1.0 - x_p;
    const double h = std::pow(y, q_i_);
    g.value = edot_0i_ * std::exp(-G0 * h);
    // dy/dx = -p_i x^(p_i - 1) and dh/dy = q_i y^(q_i - 1), by their limits where x or y is 0.
    const double dy_dx =
        x == 0.0 ? (p_i_ == 1.0 ? -1.0 : (p_i_ > 1.0 ? 0.0 : -INFINITY)) : -p_i_ * x_p / x;
    const double dh_dy =
        y == 0.0 ? (q_i_ == 1.0 ? 1.0 : (q_i_ > 1.0 ? 0.0 : INFINITY)) : q_i_ * h / y;
    g.d_stress = -g.value * G0 * dh_dy * dy_dx / sigma_hat;
    // dx/dT = -x dsigma_hat_dT / sigma_hat, and x dy/dx = -p_i x^p_i stays finite.
    const double dh_dT = dh_dy * p_i_ * x_p * dsigma_hat_dT / sigma_hat;
    g.d_temperature = -g.value * (dG0_dT * h + G0 * dh_dT);
  }
  return g;
}

std::string MtsViscoplasticModel::temperature_problem(const double T) const
{
  std::ostringstream s;
  if (!(T > 0.0))
    s << "the MTS shear modulus mu(T) = mu_0 - D/(exp(T_0/T) - 1) needs T > 0 K";
  else if (const double mu = mu_0_ - D_ / (std::exp(temp_0_ / T) - 1.0); !(mu > 0.0))
    s << "the MTS shear modulus mu(T) = mu_0 - D/(exp(T_0/T) - 1) = " << mu
      << " Pa must be > 0 (\"MTS D\" too large for this temperature)";
  return s.str();
}
} // namespace kiln
