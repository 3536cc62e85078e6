#pragma once
/// Implicit time integration with adaptive steps: backward Euler or variable-step
/// BDF2 (or a sequence of steady solves), each step one Newton solve.
#include "discretization/nonlinear_problem.hpp"

#include <Teuchos_FancyOStream.hpp>
#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <string>
#include <vector>

namespace kiln
{
class NewtonSolver;

/// Steps a TransientProblem F(x, xdot, t) = 0 from t0 through every output time.
///
/// With h = t_{n+1} - t_n, k = t_n - t_{n-1}, w = h / k:
/// - backward Euler: xdot = (x - x_n) / h;
/// - BDF2 (the first step is backward Euler):
///   xdot = [(1+2w)/(1+w) x - (1+w) x_n + w^2/(1+w) x_{n-1}] / h.
/// Local error estimates (derived by Taylor expansion; doc/heat.md):
/// - backward Euler, linear predictor p = x_n + h (x_n - x_{n-1}) / k:
///   LTE = h / (2h + k) (x - p);
/// - BDF2, quadratic predictor p through x_{n-2}, x_{n-1}, x_n (k2 = t_{n-1} - t_{n-2}):
///   LTE = h (h+k) / (3h^2 + 4hk + 2hk2 + k^2 + k k2) (x - p).
/// The error e is the weighted RMS norm of LTE_i / (atol + rtol max(|x_i|, |x_n,i|)). A step
/// with e > 1 is repeated with h * max(0.2, 0.9 e^(-1/(p+1))); an accepted one lets the
/// next grow by min(Growth Factor, 0.9 e^(-1/(p+1))), p the order. A step whose Newton
/// solve fails is repeated with h * "Step Reduction"; a Newton solve that needed more
/// than half of its allowed iterations, or that follows a failed attempt, keeps the next
/// step from growing. Steps never
/// exceed Maximum Step nor Growth Factor times the last step; they land exactly on every
/// output time, and the last two steps before one are split evenly rather than leaving a
/// sliver. Below Minimum Step the run stops with a RunError.
class TimeStepper
{
public:
  static Teuchos::ParameterList valid_parameters();
  /// `p` validated against valid_parameters(); `where` names it ("in.xml: Kiln/Time
  /// Stepping"). Log lines go to `out`.
  TimeStepper(const Teuchos::ParameterList &p, const std::string &where,
              Teuchos::RCP<Teuchos::FancyOStream> out);

  /// Called at t0 (if it is the first output time) and at every output time.
  using OutputFunction =
      std::function<void(double time, int step, double dt, const NonlinearProblem::Vector &x)>;

  struct Statistics
  {
    int steps = 0;             ///< accepted
    int error_rejections = 0;  ///< repeated because of the error estimate
    int newton_failures = 0;   ///< repeated because Newton did not converge
    int newton_iterations = 0; ///< summed over accepted steps
    int linear_iterations = 0; ///< summed over accepted steps
  };

  /// Integrates from (t0, x) through output_times (increasing, >= t0); x holds the state
  /// at the last output time on return. Collective.
  Statistics run(TransientProblem &problem, NewtonSolver &newton, NonlinearProblem::Vector &x,
                 double t0, const std::vector<double> &output_times,
                 const OutputFunction &output) const;

private:
  enum class Method
  {
    steady,
    backward_euler,
    bdf2
  };
  Method method_;
  double initial_step_;
  double growth_factor_;
  double maximum_step_;
  double minimum_step_;
  double step_reduction_;
  bool error_control_;
  double relative_tolerance_;
  double absolute_tolerance_;
  int maximum_steps_;
  std::string where_;
  Teuchos::RCP<Teuchos::FancyOStream> out_;
};
} // namespace kiln
