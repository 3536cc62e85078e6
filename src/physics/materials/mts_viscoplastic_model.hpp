#pragma once
#include "physics/materials/von_mises_viscoplastic_model.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>

namespace kiln
{
/// Truchas' MTS (mechanical threshold stress) viscoplastic model
/// (viscoplastic_material_model_types.F90), with μ(T) = μ0 − D / (exp(T0/T) − 1),
/// σ̂ = μ σ_i / μ0 and G0 = μ b³ g0i / (k T):
///   ε̇_eq = ε̇0i exp(−G0 (1 − ((σ_vM − σ_a)/σ̂)^p_i)^q_i)   for σ_a <= σ_vM <= σ_a + σ̂,
///   ε̇_eq = ε̇0i exp(−G0) (σ_vM/σ_a)^5                      for σ_vM < σ_a (continuous),
///   ε̇_eq = ε̇0i                                             for σ_vM > σ_a + σ̂.
/// Truchas' checks: b, g0i, k, μ0, p_i, q_i, σ_i, T0 > 0; ε̇0i, σ_a >= 0. Flow and its
/// integration: VonMisesViscoplasticModel.
class MtsViscoplasticModel final : public VonMisesViscoplasticModel
{
public:
  static std::string description();
  static Teuchos::ParameterList valid_parameters();
  /// From a validated list; `where` names it in messages.
  MtsViscoplasticModel(const Teuchos::ParameterList &params, const std::string &where);

  /// [G0, ∂G0/∂T, σ̂, ∂σ̂/∂T, ε̇0i exp(−G0)]
  TemperatureFactors temperature_factors(double T) const override;
  FlowRate flow_rate_at(double q, const TemperatureFactors &factors) const override;
  std::string temperature_problem(double T) const override;

private:
  double b_;
  double D_;
  double edot_0i_;
  double g_0i_;
  double k_;
  double mu_0_;
  double p_i_;
  double q_i_;
  double sig_a_;
  double sig_i_;
  double temp_0_;
};
} // namespace kiln
