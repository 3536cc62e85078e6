#include "physics/materials/von_mises_viscoplastic_model.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace kiln
{
namespace
{
/// The weight of a Voigt component in a tensor contraction a : b (shears count twice).
constexpr double contraction_weight(const int i)
{
  return i < 3 ? 1.0 : 2.0;
}
} // namespace

Teuchos::ParameterList VonMisesViscoplasticModel::common_parameters(const std::string &name)
{
  Teuchos::ParameterList p = LinearElasticModel::valid_parameters();
  p.setName(name);
  p.set("Local Tolerance", 1e-12,
        "the local Newton solve for the equivalent plastic strain increment x stops when its "
        "step is below this times x; must be > 0 and < 1e-3 [-]",
        double_range_validator(1e-16, 1e-3));
  p.set("Local Iterations", 50,
        "at most this many local Newton iterations per point; a point that does not converge "
        "fails the step, which is then cut; must be > 0 [-]",
        positive_int_validator());
  return p;
}

VonMisesViscoplasticModel::VonMisesViscoplasticModel(const Teuchos::ParameterList &params,
                                                     const std::string &where,
                                                     const std::string &name)
    : elasticity_(params, where), name_(name), tolerance_(params.get<double>("Local Tolerance")),
      max_iterations_(params.get<int>("Local Iterations"))
{
}

std::vector<std::string> VonMisesViscoplasticModel::state_names() const
{
  return {"plastic_strain_xx",         "plastic_strain_yy",  "plastic_strain_zz",
          "plastic_strain_xy",         "plastic_strain_xz",  "plastic_strain_yz",
          "equivalent_plastic_strain", "plastic_strain_rate"};
}

void VonMisesViscoplasticModel::evaluate(const PointInput &in, const double *old_state,
                                         double *new_state, PointResponse &out) const
{
  const double G = elasticity_.shear_modulus();
  const double K = elasticity_.bulk_modulus();
  // The trial state: the step is elastic.
  Voigt elastic_strain = elasticity_.mechanical_strain(in.strain, in.temperature);
  for (int i = 0; i < 6; ++i)
    elastic_strain[i] -= old_state[i];
  const Voigt trial = elasticity_.elastic_stress(elastic_strain);
  const double pressure = (trial[0] + trial[1] + trial[2]) / 3.0;
  Voigt s_trial = trial;
  for (int i = 0; i < 3; ++i)
    s_trial[i] -= pressure;
  double s_s = 0.0;
  for (int i = 0; i < 6; ++i)
    s_s += contraction_weight(i) * s_trial[i] * s_trial[i];
  const double q_trial = std::sqrt(1.5 * s_s);

  out.stress = trial;
  if (in.derivatives)
  {
    if (in.full_tangent)
      out.tangent = elasticity_.elastic_tangent();
    out.stress_temperature_derivative = elasticity_.thermal_stress_derivative();
    out.isotropic = elasticity_.isotropic_tangent();
  }
  // The rate this point's last evaluation in the step wrote (or the committed one): the local
  // solve's start.
  const double last_rate = new_state[7];
  for (int i = 0; i < 8; ++i)
    new_state[i] = old_state[i];
  new_state[7] = 0.0;
  // A strain or temperature that is not a number (a diverging Newton iterate) fails the step
  // here rather than passing NaN on.
  if (!std::isfinite(q_trial) || !std::isfinite(in.temperature))
    fail(in, q_trial, "the strain or the temperature is not a finite number");
  if (!(in.time_step > 0.0 && q_trial > 0.0))
    return;

  const std::string problem = temperature_problem(in.temperature);
  if (!problem.empty())
    fail(in, q_trial, problem);
  const TemperatureFactors factors = temperature_factors(in.temperature);
  const double x_max = q_trial / (3.0 * G);
  const double x = solve_increment(in, factors, q_trial, x_max, last_rate * in.time_step);
  const bool relaxed = x >= x_max;
  const double beta = relaxed ? 1.0 : 3.0 * G * x / q_trial;

  for (int i = 0; i < 6; ++i)
  {
    out.stress[i] = (1.0 - beta) * s_trial[i] + (i < 3 ? pressure : 0.0);
    new_state[i] = old_state[i] + 1.5 * x * s_trial[i] / q_trial;
  }
  new_state[6] = old_state[6] + x;
  new_state[7] = x / in.time_step;
  if (!in.derivatives)
    return;

  // The consistent tangent: dσ = K I tr(dε) + (1 − β) 2G dev(dε) − s_tr (3G dx − β dq_tr)/q_tr,
  // dq_tr = 2G N : dε with N = (3/2) s_tr/q_tr, and dx = c dq_tr + d dT from r(x) = 0.
  // At the root dt g = x, so dt ∂g/∂q = x ∂ ln g/∂q (and alike in T).
  double c = 0.0, d = 0.0;
  if (!relaxed && x > 0.0)
  {
    const FlowRate log_g = log_flow_rate_at(q_trial - 3.0 * G * x, factors);
    if (std::isfinite(log_g.d_stress))
    {
      const double denominator = 1.0 + 3.0 * G * x * log_g.d_stress;
      c = x * log_g.d_stress / denominator;
      d = x * log_g.d_temperature / denominator;
    }
    else
      c = 1.0 / (3.0 * G);
  }
  for (int i = 0; i < 6; ++i)
    out.stress_temperature_derivative[i] -= s_trial[i] / q_trial * 3.0 * G * d;
  for (int i = 0; i < 6 && in.full_tangent; ++i)
  {
    const double s_i = s_trial[i] / q_trial;
    for (int j = 0; j < 6; ++j)
    {
      const double deviatoric = (i == j ? 1.0 : 0.0) - (i < 3 && j < 3 ? 1.0 / 3.0 : 0.0);
      const double dq_trial_j = 2.0 * G * 1.5 * s_trial[j] / q_trial * contraction_weight(j);
      out.tangent[i][j] = (i < 3 && j < 3 ? K : 0.0) + (1.0 - beta) * 2.0 * G * deviatoric -
                          s_i * (relaxed ? 0.0 : 3.0 * G * c - beta) * dq_trial_j;
    }
  }
  // The same tangent in isotropic form: λ_t 1⊗1 + 2 μ_t 𝕀 + γ n⊗n with n = s_tr / q_tr.
  out.isotropic.lambda = K - 2.0 * G * (1.0 - beta) / 3.0;
  out.isotropic.shear = G * (1.0 - beta);
  out.isotropic.rank_one = relaxed ? 0.0 : -3.0 * G * (3.0 * G * c - beta);
  for (int i = 0; i < 6; ++i)
    out.isotropic.n[i] = s_trial[i] / q_trial;
}

VonMisesViscoplasticModel::FlowRate
VonMisesViscoplasticModel::log_flow_rate_at(const double q, const TemperatureFactors &factors) const
{
  const FlowRate g = flow_rate_at(q, factors);
  if (!(g.value > 0.0))
    return {-INFINITY, 0.0, 0.0};
  return {std::log(g.value), g.d_stress / g.value, g.d_temperature / g.value};
}

double VonMisesViscoplasticModel::solve_increment(const PointInput &in,
                                                  const TemperatureFactors &factors,
                                                  const double q_trial, const double x_max,
                                                  const double start) const
{
  const double G = elasticity_.shear_modulus();
  const double dt = in.time_step;
  // r(x) = x - dt g(q_tr - 3G x): r(x_max) <= 0 means that the deviator relaxes to zero.
  if (dt * flow_rate_at(0.0, factors).value >= x_max)
    return x_max;
  // Newton on the equivalent phi(x) = ln x - ln dt - ln g(q_tr - 3G x), increasing in x: the
  // log tames exponential laws (MTS). phi = +inf where g = 0 (x past the root).
  const double log_dt = std::log(dt);
  const auto phi = [&](const double x, double &slope) -> double
  {
    const FlowRate log_g = log_flow_rate_at(std::max(q_trial - 3.0 * G * x, 0.0), factors);
    if (!(log_g.value > -INFINITY))
      return INFINITY;
    slope = 1.0 / x + 3.0 * G * log_g.d_stress;
    return std::log(x) - log_dt - log_g.value;
  };
  // phi is increasing: the root lies in [lo, hi], and a point where phi > 0 (< 0) is an upper
  // (lower) bound.
  double lo = 0.0, hi = x_max, x = -1.0, slope = 0.0;
  if (start > 0.0 && start < x_max) // (not a NaN)
  {
    // The point's last evaluation (the same strain in a Jacobian pass after a residual pass,
    // Newton's previous iterate, or the last step's rate): within a factor of about e of the
    // root (|phi| <= 1) the Newton iteration goes on from there, else it only narrows the
    // bracket (Newton on phi in x is slow from far below the root).
    const double f = phi(start, slope);
    if (f == 0.0)
      return start;
    (f > 0.0 ? hi : lo) = start;
    if (std::abs(f) <= 1.0 && std::isfinite(slope) && slope > 0.0)
    {
      const double step = f / slope;
      if (std::abs(step) <= tolerance_ * start && std::abs(f) <= 1e-3)
        return start - step;
      x = start - step;
      if (!(x > lo && x < hi))
        x = 0.5 * (lo + hi);
    }
  }
  if (x < 0.0)
  {
    // The explicit estimate bounds the root from above when g grows with the stress; else it
    // is a lower bound.
    const double estimate = std::min(dt * flow_rate_at(q_trial, factors).value, x_max);
    if (!(estimate > 0.0))
      return 0.0;
    if (estimate > lo && estimate < hi)
      (phi(estimate, slope) < 0.0 ? lo : hi) = estimate;
    // At x_max the stress is round-off and phi's slope singular: start inside instead.
    x = hi < x_max ? hi : 0.5 * (lo + hi);
  }
  for (int iteration = 0; iteration < max_iterations_; ++iteration)
  {
    const double f = phi(x, slope);
    if (f == 0.0)
      return x;
    (f > 0.0 ? hi : lo) = x;
    // No division by zero nor inf/inf (style.md §8: debug builds may trap FE_DIVBYZERO and
    // FE_INVALID).
    const bool newton = std::isfinite(f) && std::isfinite(slope) && slope > 0.0;
    const double step = newton ? f / slope : 0.0;
    // A small step with a large f is the singular slope where q_tr - 3G x is round-off.
    if (newton && std::abs(step) <= tolerance_ * x && std::abs(f) <= 1e-3)
      return x - step;
    x = newton ? x - step : lo;
    if (!(x > lo && x < hi))
      x = 0.5 * (lo + hi); // bisection
    if (hi - lo <= tolerance_ * hi)
      return x;
  }
  std::ostringstream why;
  why << "the local Newton solve for the equivalent plastic strain increment did not converge in "
      << max_iterations_ << " iterations (\"Local Iterations\"; bracket [" << lo << ", " << hi
      << "]); a smaller time step or a looser \"Local Tolerance\" may help";
  fail(in, q_trial, why.str());
}

void VonMisesViscoplasticModel::fail(const PointInput &in, const double q_trial,
                                     const std::string &why) const
{
  std::ostringstream s;
  s.precision(9);
  s << "the \"" << name_
    << "\" viscoplastic model at a quadrature point with T = " << in.temperature << " K, time step "
    << in.time_step << " s, strain [";
  for (int i = 0; i < 6; ++i)
    s << (i == 0 ? "" : ", ") << in.strain[i];
  s << "] and trial von Mises stress " << q_trial << " Pa: " << why << "; the step is cut";
  throw StepFailure(s.str());
}
} // namespace kiln
