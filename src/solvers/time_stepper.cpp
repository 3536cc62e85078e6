#include "solvers/time_stepper.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "solvers/newton_solver.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <memory>
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

std::string norm(const double value)
{
  std::ostringstream s;
  s << std::scientific << std::setprecision(3) << value;
  return s.str();
}

/// The factor by which |F| fell ("1.2e+04"), or "none" if it did not.
std::string reduction(const NewtonSolver::Result &r)
{
  if (!(r.final_residual_norm < r.initial_residual_norm) || r.final_residual_norm <= 0.0)
    return r.final_residual_norm <= 0.0 ? "all" : "none";
  std::ostringstream s;
  s << std::setprecision(2) << r.initial_residual_norm / r.final_residual_norm;
  return s.str();
}

bool finite(const NewtonSolver::Result &r)
{
  return std::isfinite(r.initial_residual_norm) && std::isfinite(r.final_residual_norm);
}

/// |F| ended near its tolerance, or so far below where it started that the tolerance is
/// likely below the round-off of the problem.
bool near_tolerance(const NewtonSolver::Result &r)
{
  return r.final_residual_norm <= 100.0 * r.tolerance ||
         r.final_residual_norm <= 1e-8 * r.initial_residual_norm;
}

/// The weights of x_n, x_{n-1}, x_{n-2} in the accepted states extrapolated to t_n + h (the
/// last two steps k = t_n - t_{n-1}, k2 = t_{n-1} - t_{n-2}): quadratic through the three
/// states, or linear through the first two (the last weight 0).
std::array<double, 3> extrapolation_weights(const double h, const double k, const double k2,
                                            const bool quadratic)
{
  if (!quadratic)
    return {1.0 + h / k, -h / k, 0.0};
  return {(h + k) * (h + k + k2) / (k * (k + k2)), -h * (h + k + k2) / (k * k2),
          h * (h + k) / ((k + k2) * k2)};
}
} // namespace internal

std::string newton_failure(const NewtonSolver::Result &r, const int max_iterations)
{
  using internal::norm;
  std::ostringstream s;
  const std::string norms = "|F| " + norm(r.initial_residual_norm) + " -> " +
                            norm(r.final_residual_norm) + ", tolerance " + norm(r.tolerance);
  if (!r.step_failure.empty())
    s << "an evaluation failed after " << r.newton_iterations
      << " Newton iterations: " << r.step_failure;
  else if (!std::isfinite(r.initial_residual_norm))
    s << "the residual at the start of the step is not a finite number (NaN or Inf)";
  else if (r.linear_divergence)
    s << "the linear solves fell short of their tolerance (" << r.linear_failures
      << " of them) and Newton, taking their steps, diverged: " << norms << " after "
      << r.newton_iterations << " Newton iterations";
  else if (!std::isfinite(r.final_residual_norm))
    s << "the residual became NaN or Inf after " << r.newton_iterations
      << " Newton iterations (|F| " << norm(r.initial_residual_norm) << " before)";
  else if (r.newton_iterations >= max_iterations)
    s << "Newton reached its limit of " << max_iterations
      << " iterations (Solver/\"Maximum Iterations\") without converging (" << norms
      << "; |F| fell by a factor " << internal::reduction(r) << ")";
  else
    s << "NOX stopped after " << r.newton_iterations << " of " << max_iterations
      << " iterations without converging, as a line search or a linear solve failed (" << norms
      << ")";
  return s.str();
}

std::string newton_advice(const NewtonSolver::Result &r, const int max_iterations)
{
  if (!r.step_failure.empty())
    return "A constitutive model's local solve fails at too large a strain increment: take "
           "smaller steps (\"Maximum Step\", \"Initial Step\"), or loosen the model's \"Local "
           "Tolerance\" or raise its \"Local Iterations\"";
  if (r.linear_divergence)
    return "The preconditioner does not solve this Jacobian (the problem need not be "
           "nonlinear): try Solver/Linear Solver/\"Preconditioner Type\" \"Direct\" (small "
           "problems) or, with temperature and displacement, \"Block Triangular\", or raise the "
           "Krylov solver's iteration limit (doc/solvers.md, \"Linear solves short of their "
           "tolerance\")";
  if (!internal::finite(r))
    return "A NaN or Inf comes from a value out of its range at the state reached (material "
           "data, a condition's value) or from a diverging solve; smaller steps help with the "
           "latter (\"Maximum Step\", \"Initial Step\")";
  if (r.newton_iterations >= max_iterations && internal::near_tolerance(r))
    return "|F| came close to its tolerance or fell to the round-off of this problem: the "
           "tolerance may be out of reach; loosen Solver/\"Absolute Tolerance\" or \"Relative "
           "Tolerance\", or raise Solver/\"Maximum Iterations\"";
  if (r.newton_iterations >= max_iterations &&
      r.final_residual_norm < 1e-2 * r.initial_residual_norm)
    return "|F| was still falling: raise Solver/\"Maximum Iterations\", or take smaller steps "
           "(\"Maximum Step\")";
  return "Newton does not converge from this state with this step: take smaller steps "
         "(\"Maximum Step\", \"Initial Step\"), check that the linear solves converge "
         "(Solver/Linear Solver: its iteration limit and tolerance), or use a line search "
         "(Solver/Nonlinear Solver/Line Search/\"Method\" = \"Backtrack\")";
}

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
  p.set("Maximum Plastic Strain Increment", 1.0e-4,
        "a step in which the equivalent plastic strain grows by more than this at some "
        "quadrature point (a viscoplastic model: Power Law, MTS) is repeated with dt * "
        "max(0.2, 0.9 tolerance / increment), and an accepted step lets the next grow by at "
        "most that factor (MOOSE's max_inelastic_increment, whose default this is); the "
        "accuracy of backward Euler on the flow. Not for \"Steady\" (its steps are the output "
        "times); must be > 0 [-]",
        positive_double_validator());
  p.set("Maximum Steps", 100000, "steps (accepted and repeated) before the run stops [count]",
        positive_int_validator());
  p.set("Extrapolated Krylov Start", true,
        "true: the first Krylov solve of a step starts from the step extrapolated from the "
        "accepted ones before it (quadratic through the last three states, linear after the "
        "first step) where that leaves a smaller linear residual than zero: the same answer "
        "to the Krylov tolerance in fewer iterations (doc/solvers.md). false: from zero [-]");
  p.set("Extrapolated Newton Start", true,
        "for a problem whose Jacobian varies with the state (a viscoplastic model, a property "
        "of T): Newton starts each step after the first at the state extrapolated from the "
        "accepted ones (as Extrapolated Krylov Start extrapolates), a predictor of the flow "
        "going on, instead of at the last state; its tolerance stays relative to the residual "
        "at the last state. The answer is the same to the Newton tolerance, in fewer "
        "iterations where the state changes smoothly (doc/materials.md, \"Cost of a "
        "viscoplastic step\"); the states it extrapolates from are in the checkpoints, so a "
        "restart goes on bit for bit. A problem with a constant Jacobian is not affected. "
        "false: from the last state [-]");
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
      maximum_plastic_increment_(p.get<double>("Maximum Plastic Strain Increment")),
      maximum_steps_(p.get<int>("Maximum Steps")),
      extrapolated_start_(p.get<bool>("Extrapolated Krylov Start")),
      extrapolated_newton_start_(p.get<bool>("Extrapolated Newton Start")), where_(where),
      out_(std::move(out))
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

TimeStepper::State TimeStepper::initial_state(const double t0,
                                              const NonlinearProblem::Vector &x0) const
{
  using Vector = NonlinearProblem::Vector;
  State state;
  state.time = t0;
  state.next_step = initial_step_;
  state.x = Teuchos::rcp(new Vector(x0, Teuchos::Copy));
  state.x_1 = Teuchos::rcp(new Vector(x0.getMap()));
  state.x_2 = Teuchos::rcp(new Vector(x0.getMap()));
  return state;
}

TimeStepper::Statistics TimeStepper::run(TransientProblem &problem, NewtonSolver &newton,
                                         NonlinearProblem::Vector &x, const double t0,
                                         const std::vector<double> &output_times,
                                         const OutputFunction &output) const
{
  // The output function as an observer.
  struct Output final : Observer
  {
    explicit Output(const OutputFunction &f) : f_(f) {}
    void stop_time(const State &state) override
    {
      f_(state.time, state.statistics.steps, state.last_step, *state.x);
    }
    const OutputFunction &f_;
  } observer(output);
  State state = initial_state(t0, x);
  run(problem, newton, state, output_times, observer);
  Tpetra::deep_copy(x, *state.x);
  return state.statistics;
}

NewtonSolver::Result TimeStepper::steady_solve(TransientProblem &problem, NewtonSolver &newton,
                                               NonlinearProblem::Vector &x, const double time) const
{
  using internal::seconds;
  NonlinearProblem::Vector b(problem.solution_map());
  problem.set_time_derivative(time, 0.0, b);
  const NewtonSolver::Result r = newton.solve(x);
  if (!r.converged)
    throw RunError(where_ + ": the steady solve at t = " + seconds(time) +
                   " did not converge: " + newton_failure(r, newton.max_iterations()) + ". " +
                   newton_advice(r, newton.max_iterations()));
  return r;
}

bool TimeStepper::run(TransientProblem &problem, NewtonSolver &newton, State &state,
                      const std::vector<double> &stop_times, Observer &observer) const
{
  using internal::seconds;
  const auto same_time = [](const double a, const double c)
  { return std::abs(a - c) <= 1e-12 * std::max(1.0, std::abs(c)); };
  std::size_t next = 0;
  while (next < stop_times.size() && stop_times[next] < state.time &&
         !same_time(stop_times[next], state.time))
    ++next;

  if (method_ == Method::steady)
  {
    for (; next < stop_times.size(); ++next)
    {
      const double t = stop_times[next];
      // A solve that fails, or a state the problem refuses, ends the run at the last accepted
      // state: x is restored to it.
      const NonlinearProblem::Vector last(*state.x, Teuchos::Copy);
      NewtonSolver::Result r;
      try
      {
        r = steady_solve(problem, newton, *state.x, t);
        problem.step_accepted(t, *state.x);
      }
      catch (const RunError &)
      {
        Tpetra::deep_copy(*state.x, last);
        problem.step_rejected();
        throw;
      }
      state.time = t;
      ++state.accepted;
      ++state.statistics.steps;
      state.statistics.add_solve(r);
      // The observer reports the solve (app/progress_report).
      observer.step_accepted(state, r, -1.0);
      observer.stop_time(state);
      if (observer.stop_requested())
        return next + 1 == stop_times.size();
    }
    return true;
  }

  if (next < stop_times.size() && same_time(stop_times[next], state.time))
  {
    observer.stop_time(state);
    ++next;
    if (observer.stop_requested())
      return next == stop_times.size();
  }
  for (; next < stop_times.size(); ++next)
  {
    const double t_out = stop_times[next];
    while (!same_time(state.time, t_out))
    {
      NewtonSolver::Result r;
      double error = -1.0;
      if (!step(problem, newton, state, t_out, r, error))
        continue;
      const bool at_stop = same_time(state.time, t_out);
      observer.step_accepted(state, r, error);
      if (at_stop)
        observer.stop_time(state);
      if (observer.stop_requested())
        return at_stop && next + 1 == stop_times.size();
    }
  }
  return true;
}

bool TimeStepper::step(TransientProblem &problem, NewtonSolver &newton, State &state,
                       const double t_out, NewtonSolver::Result &r, double &error) const
{
  using internal::seconds;
  using Vector = NonlinearProblem::Vector;
  const auto map = problem.solution_map();
  const double t = state.time;
  const double k = state.last_step;
  const double k2 = state.step_before;
  const int n_past = state.accepted;
  if (++state.attempts > maximum_steps_)
    throw RunError(where_ + "/\"Maximum Steps\": " + std::to_string(maximum_steps_) +
                   " steps were taken before t = " + seconds(t_out) + " (now at t = " + seconds(t) +
                   "); raise it or the step limits");
  // The step: limited, then fitted to the stop time.
  const double wanted = std::min(state.next_step, maximum_step_);
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
  Vector b(map), x(map);
  double a = 1.0 / h;
  std::vector<double> weights{-1.0 / h};
  std::vector<const Vector *> past{state.x.get()};
  if (bdf2)
  {
    const double w = h / k;
    a = (1.0 + 2.0 * w) / ((1.0 + w) * h);
    weights = {-(1.0 + w) / h, w * w / ((1.0 + w) * h)};
    past.push_back(state.x_1.get());
    b.update(weights[0], *state.x, weights[1], *state.x_1, 0.0);
  }
  else
    b.update(weights[0], *state.x, 0.0);
  problem.set_time_derivative(t + h, a, b);
  problem.set_time_history(weights, past);
  Tpetra::deep_copy(x, *state.x);
  // The first Newton step, extrapolated from the accepted states: its Krylov start.
  // Or, for a Jacobian that varies (Extrapolated Newton Start), Newton's start.
  const bool predict = extrapolated_newton_start_ && n_past >= 1 && newton.jacobian_varies();
  std::unique_ptr<Vector> first_step;
  if ((extrapolated_start_ || predict) && n_past >= 1)
  {
    const auto w = internal::extrapolation_weights(h, k, k2, n_past >= 2);
    first_step = std::make_unique<Vector>(map);
    first_step->update(w[0] - 1.0, *state.x, w[1], *state.x_1, 0.0);
    if (n_past >= 2)
      first_step->update(w[2], *state.x_2, 1.0);
  }
  r = newton.solve(x, first_step.get(), predict);

  if (!r.converged)
  {
    problem.step_rejected();
    ++state.statistics.newton_failures;
    state.newton_failed = true;
    state.next_step = h * step_reduction_;
    const std::string failure = "Newton did not converge in the step from t = " + seconds(t) +
                                " with dt = " + seconds(h) + ": " +
                                newton_failure(r, newton.max_iterations());
    if (state.next_step < minimum_step_)
      throw RunError(where_ + ": " + failure + "; the next step, " + seconds(state.next_step) +
                     ", would be below \"Minimum Step\" = " + seconds(minimum_step_) +
                     ". The results up to t = " + seconds(t) + " are written. " +
                     newton_advice(r, newton.max_iterations()) + "; or lower \"Minimum Step\"");
    *out_ << "  " << failure << "; retrying with dt = " << seconds(state.next_step) << "\n";
    return false;
  }

  // The plastic strain increment of the step (0 without a viscoplastic model).
  const double plastic = problem.inelastic_strain_increment();
  const double plastic_factor =
      plastic > 0.0 ? std::max(0.2, 0.9 * maximum_plastic_increment_ / plastic) : growth_factor_;
  if (plastic > maximum_plastic_increment_)
  {
    problem.step_rejected();
    ++state.statistics.error_rejections;
    state.next_step = h * plastic_factor;
    *out_ << "  step from t = " << seconds(t) << " with dt = " << seconds(h)
          << ": plastic strain increment " << std::setprecision(3) << plastic
          << " > \"Maximum Plastic Strain Increment\" = " << maximum_plastic_increment_
          << "; retrying with dt = " << seconds(state.next_step) << "\n";
    if (state.next_step < minimum_step_)
      throw RunError(where_ +
                     "/\"Maximum Plastic Strain Increment\": the plastic strain "
                     "increment needs a step below \"Minimum Step\" = " +
                     seconds(minimum_step_) + " at t = " + seconds(t) +
                     "; lower it or raise the tolerance");
    return false;
  }

  // The local error estimate.
  const int order = bdf2 ? 2 : 1;
  error = -1.0;
  if (error_control_ && (bdf2 ? n_past >= 2 : n_past >= 1))
  {
    // A multiple of the step's distance from the predictor, the extrapolated states.
    Vector lte(map);
    const auto w = internal::extrapolation_weights(h, k, k2, bdf2);
    if (bdf2)
    {
      const double ratio = h * (h + k) / (3 * h * h + 4 * h * k + 2 * h * k2 + k * k + k * k2);
      lte.update(ratio, x, -ratio * w[0], *state.x, 0.0);
      lte.update(-ratio * w[1], *state.x_1, -ratio * w[2], *state.x_2, 1.0);
    }
    else
    {
      const double ratio = h / (2 * h + k);
      lte.update(ratio, x, -ratio * w[0], *state.x, 0.0);
      lte.update(-ratio * w[1], *state.x_1, 1.0);
    }
    error = internal::weighted_rms(lte, x, *state.x, absolute_tolerance_, relative_tolerance_,
                                   problem.time_error_mask().get());
    if (error > 1.0)
    {
      problem.step_rejected();
      ++state.statistics.error_rejections;
      state.next_step = h * std::max(0.2, 0.9 * std::pow(error, -1.0 / (order + 1)));
      *out_ << "  step from t = " << seconds(t) << " with dt = " << seconds(h)
            << ": error estimate " << std::setprecision(3) << error
            << " > 1; retrying with dt = " << seconds(state.next_step) << "\n";
      if (state.next_step < minimum_step_)
        throw RunError(where_ + ": the error estimate needs a step below \"Minimum Step\" = " +
                       seconds(minimum_step_) + " at t = " + seconds(t) +
                       "; lower it or loosen the error tolerances");
      return false;
    }
  }

  // Accept: the problem first, which may refuse the state (a RunError: a contact pair slid
  // beyond its small-sliding limit); then the run ends at the last accepted state, kept.
  try
  {
    problem.step_accepted(lands ? t_out : t + h, x);
  }
  catch (const RunError &)
  {
    problem.step_rejected();
    throw;
  }
  double factor = growth_factor_;
  if (error >= 0.0)
    factor = std::min(growth_factor_,
                      std::max(0.2, 0.9 * std::pow(std::max(error, 1e-10), -1.0 / (order + 1))));
  factor = std::min(factor, plastic_factor);
  // After a hard solve, or one that failed at a larger step, the next step does not grow.
  if (2 * r.newton_iterations > newton.max_iterations() || state.newton_failed)
    factor = std::min(factor, 1.0);
  state.newton_failed = false;
  Tpetra::deep_copy(*state.x_2, *state.x_1);
  Tpetra::deep_copy(*state.x_1, *state.x);
  Tpetra::deep_copy(*state.x, x);
  state.step_before = k;
  state.last_step = h;
  state.time = lands ? t_out : t + h;
  ++state.accepted;
  Statistics &stats = state.statistics;
  ++stats.steps;
  stats.add_solve(r);
  state.next_step = h * factor;
  if (h < wanted && factor >= 1.0)
    state.next_step = std::max(state.next_step, wanted);
  // The observer reports the step (app/progress_report).
  return true;
}
} // namespace kiln
