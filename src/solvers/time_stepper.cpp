#include "solvers/time_stepper.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "solvers/newton_solver.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace kiln
{
namespace internal
{
using Vector = NonlinearProblem::Vector;

/// sqrt(mean_i (e_i / (atol + rtol max(|x_i|, |y_i|)))^2) over all ranks and the unknowns i
/// where `mask` is not 0 (all if it is null); 0 if there are none.
double weighted_rms(const Vector &e, const Vector &x, const Vector &y, const double atol,
                    const double rtol, const Vector *mask)
{
  const auto e_v = e.getData();
  const auto x_v = x.getData();
  const auto y_v = y.getData();
  Teuchos::ArrayRCP<const double> m_v;
  if (mask != nullptr)
    m_v = mask->getData();
  double local[2] = {0.0, 0.0}; // sum, count
  for (std::size_t i = 0; i < e.getLocalLength(); ++i)
  {
    if (mask != nullptr && m_v[i] == 0.0)
      continue;
    const double w = atol + rtol * std::max(std::abs(x_v[i]), std::abs(y_v[i]));
    local[0] += (e_v[i] / w) * (e_v[i] / w);
    local[1] += 1.0;
  }
  double global[2] = {0.0, 0.0};
  Teuchos::reduceAll(*e.getMap()->getComm(), Teuchos::REDUCE_SUM, 2, local, global);
  return global[1] > 0.0 ? std::sqrt(global[0] / global[1]) : 0.0;
}

std::string seconds(const double t)
{
  std::ostringstream s;
  s << std::setprecision(6) << t << " s";
  return s.str();
}
} // namespace internal

Teuchos::ParameterList TimeStepper::valid_parameters()
{
  Teuchos::ParameterList p("Time Stepping");
  p.set("Method", "BDF2",
        "\"BDF2\": variable-step BDF2 (2nd order; the first step is backward Euler); "
        "\"Backward Euler\" (1st order); \"Steady\": a steady solve (no time derivative) at "
        "each output time",
        choice_validator({"BDF2", "Backward Euler", "Steady"}));
  p.set("Initial Step", 1.0, "the first step, must be > 0 [s]", positive_double_validator());
  p.set("Growth Factor", 5.0,
        "the largest ratio of a step to the one before, must be >= 1 (1: fixed steps) [-]",
        double_range_validator(1.0, 1.0e3));
  p.set("Maximum Step", 5.0, "the largest step, must be > 0 [s]", positive_double_validator());
  p.set("Minimum Step", 1.0e-6, "below this step the run stops with an error, must be > 0 [s]",
        positive_double_validator());
  p.set("Step Reduction", 0.25, "factor on the step when Newton fails, in (0, 1) [-]",
        double_range_validator(1e-3, 0.999));
  p.set("Error Control", true,
        "adapt the step to the local error estimate (from the second step on for backward "
        "Euler, from the third for BDF2) [-]");
  p.set("Relative Error Tolerance", 1.0e-3, "rtol of the error estimate, must be > 0 [-]",
        positive_double_validator());
  p.set("Absolute Error Tolerance", 1.0e-2,
        "atol of the error estimate, must be > 0 [unit of the unknowns: K; the estimate counts "
        "the temperature only, the displacement being quasi-static]",
        positive_double_validator());
  p.set("Maximum Steps", 100000, "steps (accepted and repeated) before the run stops [count]",
        positive_int_validator());
  return p;
}

TimeStepper::TimeStepper(const Teuchos::ParameterList &p, const std::string &where,
                         Teuchos::RCP<Teuchos::FancyOStream> out)
    : initial_step_(p.get<double>("Initial Step")), growth_factor_(p.get<double>("Growth Factor")),
      maximum_step_(p.get<double>("Maximum Step")), minimum_step_(p.get<double>("Minimum Step")),
      step_reduction_(p.get<double>("Step Reduction")),
      error_control_(p.get<bool>("Error Control")),
      relative_tolerance_(p.get<double>("Relative Error Tolerance")),
      absolute_tolerance_(p.get<double>("Absolute Error Tolerance")),
      maximum_steps_(p.get<int>("Maximum Steps")), where_(where), out_(std::move(out))
{
  const std::string method = p.get<std::string>("Method");
  method_ = method == "Steady"           ? Method::steady
            : method == "Backward Euler" ? Method::backward_euler
                                         : Method::bdf2;
  KILN_CHECK_INPUT(minimum_step_ <= initial_step_ && initial_step_ <= maximum_step_,
                   where + "/\"Initial Step\"",
                   "is " << initial_step_ << " s but must lie between \"Minimum Step\" = "
                         << minimum_step_ << " s and \"Maximum Step\" = " << maximum_step_ << " s");
}

TimeStepper::Statistics TimeStepper::run(TransientProblem &problem, NewtonSolver &newton,
                                         NonlinearProblem::Vector &x, const double t0,
                                         const std::vector<double> &output_times,
                                         const OutputFunction &output) const
{
  using internal::seconds;
  using Vector = NonlinearProblem::Vector;
  const auto map = problem.solution_map();
  Vector b(map), lte(map);
  Statistics stats;
  std::size_t next = 0;
  const auto same_time = [](const double a, const double c)
  { return std::abs(a - c) <= 1e-12 * std::max(1.0, std::abs(c)); };

  if (method_ == Method::steady)
  {
    for (; next < output_times.size(); ++next)
    {
      const double t = output_times[next];
      problem.set_time_derivative(t, 0.0, b);
      const NewtonSolver::Result r = newton.solve(x);
      if (!r.converged)
        throw RunError(where_ + ": the steady solve at t = " + seconds(t) +
                       " did not converge (|F| " + std::to_string(r.initial_residual_norm) +
                       " -> " + std::to_string(r.final_residual_norm) +
                       "); check the boundary conditions, or raise Solver/\"Maximum "
                       "Iterations\"");
      ++stats.steps;
      stats.newton_iterations += r.newton_iterations;
      stats.linear_iterations += r.linear_iterations;
      *out_ << "steady solve " << next + 1 << ": t = " << seconds(t) << ", Newton "
            << r.newton_iterations << " (" << r.linear_iterations << " linear), |F| "
            << std::scientific << std::setprecision(3) << r.initial_residual_norm << " -> "
            << r.final_residual_norm << std::defaultfloat << "\n";
      problem.step_accepted(t, x);
      output(t, static_cast<int>(next), 0.0, x);
    }
    return stats;
  }

  double t = t0;
  if (next < output_times.size() && same_time(output_times[next], t0))
    output(t0, 0, 0.0, x);
  while (next < output_times.size() && output_times[next] <= t0 + 1e-12 * std::max(1.0, t0))
    ++next;

  Vector x_n(map), x_nm1(map), x_nm2(map);
  Tpetra::deep_copy(x_n, x);
  double k = 0.0;  // t_n - t_{n-1}
  double k2 = 0.0; // t_{n-1} - t_{n-2}
  int n_past = 0;  // accepted steps so far
  double dt = initial_step_;
  int attempts = 0;
  bool newton_failed = false; // since the last accepted step

  for (; next < output_times.size(); ++next)
  {
    const double t_out = output_times[next];
    while (!same_time(t, t_out))
    {
      if (++attempts > maximum_steps_)
        throw RunError(where_ + "/\"Maximum Steps\": " + std::to_string(maximum_steps_) +
                       " steps were taken before t = " + seconds(t_out) +
                       " (now at t = " + seconds(t) + "); raise it or the step limits");
      // The step: limited, then fitted to the output time.
      const double wanted = std::min(dt, maximum_step_);
      double h = n_past > 0 ? std::min(wanted, growth_factor_ * k) : wanted;
      const double remaining = t_out - t;
      bool lands = false;
      if (h >= remaining * (1.0 - 1e-12))
      {
        h = remaining;
        lands = true;
      }
      else if (h > 0.5 * remaining)
        h = 0.5 * remaining;

      // xdot = a x + b
      const bool bdf2 = method_ == Method::bdf2 && n_past >= 1;
      double a = 1.0 / h;
      if (bdf2)
      {
        const double w = h / k;
        a = (1.0 + 2.0 * w) / ((1.0 + w) * h);
        b.update(-(1.0 + w) / h, x_n, w * w / ((1.0 + w) * h), x_nm1, 0.0);
      }
      else
        b.update(-1.0 / h, x_n, 0.0);
      problem.set_time_derivative(t + h, a, b);
      Tpetra::deep_copy(x, x_n);
      const NewtonSolver::Result r = newton.solve(x);

      if (!r.converged)
      {
        ++stats.newton_failures;
        newton_failed = true;
        dt = h * step_reduction_;
        std::ostringstream failure;
        failure << "Newton did not converge in the step from t = " << seconds(t)
                << " with dt = " << seconds(h) << " (|F| " << std::scientific
                << std::setprecision(3) << r.initial_residual_norm << " -> "
                << r.final_residual_norm << std::defaultfloat << " after " << r.newton_iterations
                << " iterations)";
        if (dt < minimum_step_)
          throw RunError(where_ + ": " + failure.str() + "; the next step, " + seconds(dt) +
                         ", would be below \"Minimum Step\" = " + seconds(minimum_step_) +
                         ". The results up to t = " + seconds(t) +
                         " are written. If |F| stalled near its tolerance, loosen Solver/"
                         "\"Absolute Tolerance\" or \"Relative Tolerance\"; otherwise check the "
                         "boundary conditions and material data, raise Solver/\"Maximum "
                         "Iterations\", or lower \"Minimum Step\"");
        *out_ << "  " << failure.str() << "; retrying with dt = " << seconds(dt) << "\n";
        continue;
      }

      // The local error estimate.
      const int order = bdf2 ? 2 : 1;
      double error = -1.0;
      if (error_control_ && (bdf2 ? n_past >= 2 : n_past >= 1))
      {
        if (bdf2)
        {
          const double l0 = (h + k) * (h + k + k2) / (k * (k + k2));
          const double l1 = -h * (h + k + k2) / (k * k2);
          const double l2 = h * (h + k) / ((k + k2) * k2);
          const double ratio = h * (h + k) / (3 * h * h + 4 * h * k + 2 * h * k2 + k * k + k * k2);
          lte.update(ratio, x, -ratio * l0, x_n, 0.0);
          lte.update(-ratio * l1, x_nm1, -ratio * l2, x_nm2, 1.0);
        }
        else
        {
          const double ratio = h / (2 * h + k);
          lte.update(ratio, x, -ratio * (1.0 + h / k), x_n, 0.0);
          lte.update(ratio * h / k, x_nm1, 1.0);
        }
        error = internal::weighted_rms(lte, x, x_n, absolute_tolerance_, relative_tolerance_,
                                       problem.time_error_mask().get());
        if (error > 1.0)
        {
          ++stats.error_rejections;
          dt = h * std::max(0.2, 0.9 * std::pow(error, -1.0 / (order + 1)));
          *out_ << "  step from t = " << seconds(t) << " with dt = " << seconds(h)
                << ": error estimate " << std::setprecision(3) << error
                << " > 1; retrying with dt = " << seconds(dt) << "\n";
          if (dt < minimum_step_)
            throw RunError(where_ + ": the error estimate needs a step below \"Minimum Step\" = " +
                           seconds(minimum_step_) + " at t = " + seconds(t) +
                           "; lower it or loosen the error tolerances");
          continue;
        }
      }

      // Accept.
      double factor = growth_factor_;
      if (error >= 0.0)
        factor =
            std::min(growth_factor_,
                     std::max(0.2, 0.9 * std::pow(std::max(error, 1e-10), -1.0 / (order + 1))));
      // After a hard solve, or one that failed at a larger step, the next step does not grow.
      if (2 * r.newton_iterations > newton.max_iterations() || newton_failed)
        factor = std::min(factor, 1.0);
      newton_failed = false;
      Tpetra::deep_copy(x_nm2, x_nm1);
      Tpetra::deep_copy(x_nm1, x_n);
      Tpetra::deep_copy(x_n, x);
      k2 = k;
      k = h;
      t = lands ? t_out : t + h;
      ++n_past;
      ++stats.steps;
      stats.newton_iterations += r.newton_iterations;
      stats.linear_iterations += r.linear_iterations;
      dt = h * factor;
      if (h < wanted && factor >= 1.0)
        dt = std::max(dt, wanted);

      std::ostringstream line;
      line << "step " << stats.steps << ": t = " << seconds(t) << ", dt = " << seconds(h)
           << (bdf2 ? " (BDF2)" : " (BE)") << ", Newton " << r.newton_iterations << " ("
           << r.linear_iterations << " linear), |F| " << std::scientific << std::setprecision(3)
           << r.initial_residual_norm << " -> " << r.final_residual_norm;
      if (error >= 0.0)
        line << ", error " << std::defaultfloat << std::setprecision(3) << error;
      *out_ << line.str() << "\n";
      problem.step_accepted(t, x);
    }
    output(t, stats.steps, k, x);
  }
  return stats;
}
} // namespace kiln
