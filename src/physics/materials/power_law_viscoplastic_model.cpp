#include "physics/materials/power_law_viscoplastic_model.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"

#include <cmath>
#include <sstream>

namespace kiln
{
std::string PowerLawViscoplasticModel::description()
{
  return "Truchas' power-law viscoplasticity in von Mises form, eps_dot_eq = A sigma_vM^n "
         "exp(-Q/(R (T - Tref))), integrated by backward Euler (doc/materials.md)";
}

Teuchos::ParameterList PowerLawViscoplasticModel::valid_parameters()
{
  Teuchos::ParameterList p = common_parameters("Power Law");
  p.set("Power Law A", 0.0,
        "A, the coefficient of the rate (Truchas' Pwr_Law_A), required; must be >= 0 "
        "[1/(s Pa^n)]",
        nonnegative_double_validator());
  p.set("Power Law n", 1.0,
        "n, the stress exponent (Truchas' Pwr_Law_N), required; must be >= 0 [-]",
        nonnegative_double_validator());
  p.set("Power Law Q", 0.0,
        "Q, the activation energy (Truchas' Pwr_Law_Q); 0: no temperature dependence [J/mol]");
  p.set("Power Law R", 8.314462618,
        "R, the gas constant in the units of Q (Truchas' Pwr_Law_R); must be nonzero "
        "[J/(mol K)]");
  p.set("Power Law Tref", 0.0,
        "T_ref, the temperature offset in exp(-Q/(R (T - Tref))) (Truchas' Pwr_Law_Tref); where "
        "Q is nonzero, T must stay above it [K]");
  return p;
}

PowerLawViscoplasticModel::PowerLawViscoplasticModel(const Teuchos::ParameterList &params,
                                                     const std::string &where)
    : VonMisesViscoplasticModel(params, where, "Power Law"), A_(params.get<double>("Power Law A")),
      n_(params.get<double>("Power Law n")), Q_(params.get<double>("Power Law Q")),
      R_(params.get<double>("Power Law R")), T_ref_(params.get<double>("Power Law Tref")),
      log_A_(A_ > 0.0 ? std::log(A_) : 0.0)
{
  for (const char *name : {"Power Law A", "Power Law n"})
    KILN_CHECK_INPUT(given_in_input(params, name), where + "/\"" + name + "\"",
                     "is required by the \"Power Law\" viscoplastic model (eps_dot_eq = A "
                     "sigma_vM^n exp(-Q/(R (T - Tref)))); give it, e.g. <Parameter name=\""
                         << name << "\" type=\"double\" value=\"1\"/>");
  KILN_CHECK_INPUT(R_ != 0.0, where + "/\"Power Law R\"",
                   "= 0, but the \"Power Law\" viscoplastic model divides by it (exp(-Q/(R (T - "
                   "Tref)))): give the gas constant in the units of \"Power Law Q\", e.g. "
                   "8.314462618 J/(mol K)");
}

VonMisesViscoplasticModel::TemperatureFactors
PowerLawViscoplasticModel::temperature_factors(const double T) const
{
  // ln A' without a log per point (ln A once); -inf for A = 0 (no flow).
  const double log_A = A_ > 0.0 ? log_A_ : -INFINITY;
  if (Q_ == 0.0)
    return {A_, 0.0, log_A};
  const double dT = T - T_ref_;
  return {A_ * std::exp(-Q_ / (R_ * dT)), Q_ / (R_ * dT * dT), log_A - Q_ / (R_ * dT)};
}

VonMisesViscoplasticModel::FlowRate
PowerLawViscoplasticModel::flow_rate_at(const double q, const TemperatureFactors &factors) const
{
  const double coefficient = factors[0];
  FlowRate g;
  g.value = coefficient * std::pow(q, n_);
  if (n_ == 0.0)
    g.d_stress = 0.0;
  else if (q > 0.0)
    g.d_stress = n_ * g.value / q;
  else // the limit q -> 0, without pow(0, negative) (FE_DIVBYZERO)
    g.d_stress = n_ < 1.0 ? INFINITY : (n_ == 1.0 ? coefficient : 0.0);
  g.d_temperature = g.value * factors[1];
  return g;
}

VonMisesViscoplasticModel::FlowRate
PowerLawViscoplasticModel::log_flow_rate_at(const double q, const TemperatureFactors &factors) const
{
  if (!(factors[0] > 0.0) || (n_ > 0.0 && !(q > 0.0))) // g = 0
    return {-INFINITY, 0.0, 0.0};
  if (n_ == 0.0)
    return {factors[2], 0.0, factors[1]};
  return {factors[2] + n_ * std::log(q), n_ / q, factors[1]};
}

std::string PowerLawViscoplasticModel::temperature_problem(const double T) const
{
  if (Q_ == 0.0 || T > T_ref_)
    return "";
  std::ostringstream s;
  s << "the rate exp(-Q/(R (T - Tref))) needs T > \"Power Law Tref\" = " << T_ref_ << " K";
  return s.str();
}
} // namespace kiln
