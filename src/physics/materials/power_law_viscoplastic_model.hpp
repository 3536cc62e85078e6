#pragma once
#include "physics/materials/von_mises_viscoplastic_model.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>

namespace kiln
{
/// Truchas' "power law" viscoplastic model (viscoplastic_material_model_types.F90):
///   ε̇_eq = A σ_vM^n exp(−Q / (R (T − T_ref))),
/// with exp(...) = 1 when Q = 0; Truchas' checks A >= 0, n >= 0, R ≠ 0. Flow and its
/// integration: VonMisesViscoplasticModel.
class PowerLawViscoplasticModel final : public VonMisesViscoplasticModel
{
public:
  static std::string description();
  static Teuchos::ParameterList valid_parameters();
  /// From a validated list; `where` names it in messages.
  PowerLawViscoplasticModel(const Teuchos::ParameterList &params, const std::string &where);

  /// [A' = A exp(−Q/(R (T − Tref))), Q/(R (T − Tref)²), ln A' (−inf for A = 0)]
  TemperatureFactors temperature_factors(double T) const override;
  FlowRate flow_rate_at(double q, const TemperatureFactors &factors) const override;
  /// ln A' + n ln q, n / q, Q/(R (T − Tref)²) (the factors above): one log, no power.
  FlowRate log_flow_rate_at(double q, const TemperatureFactors &factors) const override;
  std::string temperature_problem(double T) const override;

private:
  double A_;
  double n_;
  double Q_;
  double R_;
  double T_ref_;
  double log_A_; ///< ln A (0 for A = 0, not read then)
};
} // namespace kiln
