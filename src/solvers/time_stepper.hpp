#pragma once
/// Implicit time integration with adaptive steps: backward Euler or variable-step
/// BDF2 (or a sequence of steady solves), each step one Newton solve.
#include "discretization/nonlinear_problem.hpp"
#include "solvers/newton_solver.hpp"

#include <Teuchos_FancyOStream.hpp>
#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <string>
#include <vector>

namespace kiln
{
/// What a Newton solve that did not converge did, for the log and messages: a residual that
/// is not finite (NaN or Inf), the iteration limit reached (with |F| at the start and the
/// end, its tolerance and how much it fell), or NOX stopping before it (a failed line search
/// or linear solve).
std::string newton_failure(const NewtonSolver::Result &r, int max_iterations);
/// What to try after such a solve, from what newton_failure() says of it.
std::string newton_advice(const NewtonSolver::Result &r, int max_iterations);

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
/// solve fails (or ends at a StepFailure: a model's local solve) is repeated with h *
/// "Step Reduction"; a Newton solve that needed more
/// than half of its allowed iterations, or that follows a failed attempt, keeps the next
/// step from growing. A step whose equivalent plastic strain grows by more than "Maximum
/// Plastic Strain Increment" at some point (TransientProblem::inelastic_strain_increment) is
/// repeated with h * max(0.2, 0.9 tolerance / increment), and that factor also caps the
/// growth of the next step. Steps never
/// exceed Maximum Step nor Growth Factor times the last step; they land exactly on every
/// stop time (output and checkpoint times), and the last two steps before one are split
/// evenly rather than leaving a sliver. Below Minimum Step the run stops with a RunError.
/// A converged state is accepted by the problem first (NonlinearProblem::step_accepted), which
/// may refuse it with a RunError (a contact pair slid beyond its small-sliding limit): the
/// step is rejected (step_rejected) and the RunError ends the run with the State at the last
/// accepted step, its x included (also for a steady solve that fails).
/// Everything the integration needs to go on from an accepted step is its State, so a run
/// continued from a saved State (a checkpoint) takes the same steps as one that never
/// stopped.
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
    int error_rejections = 0;  ///< repeated for the error estimate or the plastic increment
    int newton_failures = 0;   ///< repeated because Newton did not converge
    int newton_iterations = 0; ///< summed over accepted steps and the initial equilibrium
    int linear_iterations = 0; ///< summed over accepted steps and the initial equilibrium
    int linear_failures = 0;   ///< linear solves short of their tolerance, likewise
    /// Of this run's accepted steps (not in checkpoints): Jacobians and preconditioners
    /// built anew or kept (Solver/"Reuse").
    int jacobians_evaluated = 0;
    int jacobians_kept = 0;
    int preconditioners_built = 0;
    int preconditioners_kept = 0;
    /// Counts the iterations, Jacobians and preconditioners of an accepted solve.
    void add_solve(const NewtonSolver::Result &r)
    {
      newton_iterations += r.newton_iterations;
      linear_iterations += r.linear_iterations;
      linear_failures += r.linear_failures;
      jacobians_evaluated += r.jacobians_evaluated;
      jacobians_kept += r.jacobians_kept;
      preconditioners_built += r.preconditioners_built;
      preconditioners_kept += r.preconditioners_kept;
    }
  };

  /// The integration after an accepted step (or at its start).
  struct State
  {
    double time = 0.0;          ///< t_n [s]
    double next_step = 0.0;     ///< the step the next attempt starts from [s]
    double last_step = 0.0;     ///< t_n - t_{n-1} [s] (0 before the first step)
    double step_before = 0.0;   ///< t_{n-1} - t_{n-2} [s]
    int accepted = 0;           ///< accepted steps n
    int attempts = 0;           ///< steps tried, accepted or repeated (for Maximum Steps)
    bool newton_failed = false; ///< a Newton solve failed since the last accepted step
    Statistics statistics;
    Teuchos::RCP<NonlinearProblem::Vector> x;   ///< x_n
    Teuchos::RCP<NonlinearProblem::Vector> x_1; ///< x_{n-1} (BDF2, error estimates)
    Teuchos::RCP<NonlinearProblem::Vector> x_2; ///< x_{n-2}
  };
  /// The state at t0 with the unknowns x0 (copied); the next step is "Initial Step".
  State initial_state(double t0, const NonlinearProblem::Vector &x0) const;

  /// What the run is told between steps, and asked whether to go on.
  class Observer
  {
  public:
    virtual ~Observer() = default;
    /// After every accepted step, with its Newton solve and its error estimate (-1: none).
    virtual void step_accepted(const State & /*state*/, const NewtonSolver::Result & /*newton*/,
                               double /*error*/)
    {
    }
    /// At every stop time, reached exactly (after step_accepted).
    virtual void stop_time(const State &state) = 0;
    /// Asked after every accepted step and stop time (collective): true ends run() there.
    virtual bool stop_requested() { return false; }
  };

  /// Integrates `state` through every stop time (increasing) at or after state.time: a stop
  /// time equal to state.time is reached at once. Returns false if the observer stopped it
  /// early. Collective.
  bool run(TransientProblem &problem, NewtonSolver &newton, State &state,
           const std::vector<double> &stop_times, Observer &observer) const;

  /// Integrates from (t0, x) through output_times (increasing, >= t0); x holds the state
  /// at the last output time on return. Collective.
  Statistics run(TransientProblem &problem, NewtonSolver &newton, NonlinearProblem::Vector &x,
                 double t0, const std::vector<double> &output_times,
                 const OutputFunction &output) const;

private:
  /// One steady solve at `time`; throws RunError if it fails.
  NewtonSolver::Result steady_solve(TransientProblem &problem, NewtonSolver &newton,
                                    NonlinearProblem::Vector &x, double time) const;
  /// Takes one step from `state` towards t_out; on acceptance updates state and returns true,
  /// with the solve and the error estimate; false if the step is to be repeated.
  bool step(TransientProblem &problem, NewtonSolver &newton, State &state, double t_out,
            NewtonSolver::Result &result, double &error) const;

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
  double maximum_plastic_increment_; ///< "Maximum Plastic Strain Increment"
  int maximum_steps_;
  bool extrapolated_start_;        ///< "Extrapolated Krylov Start"
  bool extrapolated_newton_start_; ///< "Extrapolated Newton Start"
  std::string where_;
  Teuchos::RCP<Teuchos::FancyOStream> out_;
};
} // namespace kiln
