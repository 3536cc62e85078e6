#pragma once
#include "physics/materials/constitutive_model.hpp"
#include "physics/materials/linear_elastic_model.hpp"

#include <Teuchos_ParameterList.hpp>

#include <array>
#include <string>
#include <vector>

namespace kiln
{
/// Isotropic viscoplasticity in von Mises form (Truchas' solid mechanics, doc/materials.md):
///   σ = C : (ε − ε_th − ε_p),   ε̇_p = (3/2) ε̇_eq s / σ_vM,   ε̇_eq = g(σ_vM, T),
/// s the deviator of σ and σ_vM = sqrt(3/2 s:s); a subclass gives the flow law g.
/// Integrated by backward Euler on the flow at T_{n+1}, as a radial return: with the trial
/// stress σ_tr = C : (ε − ε_th − ε_p,n) (deviator s_tr, von Mises q_tr), the increment
/// Δε_eq = x solves the scalar equation
///   r(x) = x − Δt g(q_tr − 3G x, T) = 0,   0 <= x <= q_tr / (3G)
/// by Newton's method on the equivalent ln x = ln(Δt g) (the log tames exponential laws),
/// safeguarded by a bracket (bisection when a step leaves it); then
///   s = (1 − 3G x / q_tr) s_tr,   Δε_p = (3/2) x s_tr / q_tr.
/// If even x = q_tr/(3G) (zero deviator) leaves r <= 0 (a law with g(0, T) > 0), the deviator
/// relaxes to zero. The tangent is the consistent (algorithmic) one of this update, ∂σ/∂T
/// includes the thermal strain and ∂g/∂T. No flow when Δt = 0 or s_tr = 0.
/// State (8 doubles): ε_p (6, Voigt, tensor shears), ε_eq (accumulated Σ x), and the rate
/// x / Δt of the last evaluation.
class VonMisesViscoplasticModel : public ConstitutiveModel
{
public:
  /// g and its partial derivatives at (σ_vM, T); d_stress may be +inf (q^(n−1) at q = 0).
  struct FlowRate
  {
    double value = 0.0;         ///< ε̇_eq [1/s]
    double d_stress = 0.0;      ///< ∂g/∂σ_vM [1/(Pa s)]
    double d_temperature = 0.0; ///< ∂g/∂T [1/(K s)]
  };

  int n_state() const final { return 8; }
  std::vector<std::string> state_names() const final;
  void evaluate(const PointInput &in, const double *old_state, double *new_state,
                PointResponse &out) const final;
  double equivalent_plastic_strain(const double *state) const final { return state[6]; }
  double plastic_strain_rate(const double *state) const final { return state[7]; }

  /// What a flow law computes once per point from T (Truchas' set_temperature): the local
  /// solve then evaluates the law at many stresses for the price of the stress terms alone.
  using TemperatureFactors = std::array<double, 6>;

  const LinearElasticModel &elasticity() const { return elasticity_; }
  double thermal_strain(const double temperature) const override
  {
    return elasticity_.thermal_strain(temperature);
  }
  /// The flow law: the equivalent plastic strain rate at von Mises stress q >= 0 and T.
  FlowRate flow_rate(const double q, const double T) const
  {
    return flow_rate_at(q, temperature_factors(T));
  }
  /// The law's factors at T (which temperature_problem() accepts).
  virtual TemperatureFactors temperature_factors(double T) const = 0;
  /// The law at q >= 0 with the factors of T; d_temperature is ∂g/∂T.
  virtual FlowRate flow_rate_at(double q, const TemperatureFactors &factors) const = 0;
  /// ln g and its partial derivatives ∂ ln g/∂σ_vM = g'/g, ∂ ln g/∂T, what the local solve and
  /// the tangent read: value −inf where g = 0 (then the derivatives are 0). Default: from
  /// flow_rate_at(); a law whose logarithm is cheaper than itself (a power of q) overrides it.
  virtual FlowRate log_flow_rate_at(double q, const TemperatureFactors &factors) const;
  /// Why the flow law cannot be evaluated at T ("" when it can), e.g. T <= 0 K.
  virtual std::string temperature_problem(double T) const = 0;

protected:
  /// The elastic parameters (LinearElasticModel's) and those of the local solve, for a
  /// subclass's valid_parameters().
  static Teuchos::ParameterList common_parameters(const std::string &name);
  /// `name` names the model in messages ("Power Law").
  VonMisesViscoplasticModel(const Teuchos::ParameterList &params, const std::string &where,
                            const std::string &name);

private:
  /// Δε_eq = x by the safeguarded Newton iteration, from `start` if it lies in (0, x_max) (the
  /// point's last evaluation), else from the explicit estimate; throws StepFailure when it does
  /// not converge.
  double solve_increment(const PointInput &in, const TemperatureFactors &factors, double q_trial,
                         double x_max, double start) const;
  [[noreturn]] void fail(const PointInput &in, double q_trial, const std::string &why) const;

  LinearElasticModel elasticity_;
  std::string name_;
  double tolerance_;
  int max_iterations_;
};
} // namespace kiln
