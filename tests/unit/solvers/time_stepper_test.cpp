// Tests solvers/time_stepper: on y' = -lambda y (a few unknowns per rank, diagonal
// Jacobian) the steps land exactly on the output times, the error control meets tighter
// tolerances with more steps and repeats steps it rejects, and a failed Newton solve is
// repeated with a smaller step; the message of a failed Newton solve says what happened and
// what to try, not "the boundary conditions"; the problem is told of each accepted and each
// rejected step (step_accepted, step_rejected); a state the problem refuses (a RunError from
// step_accepted) rejects the step and ends the run with the State at the last accepted step.
// KILN_TEST_NP: 1 2
#include "base/errors.hpp"
#include "discretization/nonlinear_problem.hpp"
#include "solvers/newton_solver.hpp"
#include "solvers/time_stepper.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_oblackholestream.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
using kiln::NonlinearProblem;
using kiln::TimeStepper;
using Teuchos::RCP;

/// F(x) = xdot + lambda x with xdot = a x + b; J = (a + lambda) I. With `max_step` > 0,
/// a step longer than it (a < 1/max_step for backward Euler) gives a NaN residual, which
/// Newton reports as not converged.
class Decay final : public kiln::TransientProblem
{
public:
  Decay(const double lambda, const double max_step) : lambda_(lambda), max_step_(max_step)
  {
    const auto comm = Teuchos::DefaultComm<int>::getComm();
    map_ = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(3 * comm->getSize()), 0, comm));
    auto graph = Teuchos::rcp(new Graph(map_, 1));
    for (std::size_t i = 0; i < map_->getNodeNumElements(); ++i)
    {
      const auto gid = map_->getGlobalElement(static_cast<int>(i));
      graph->insertGlobalIndices(gid, Teuchos::tuple(gid));
    }
    graph->fillComplete();
    graph_ = graph;
    b_ = Teuchos::rcp(new Vector(map_));
  }
  RCP<const Map> solution_map() const override { return map_; }
  RCP<const Graph> jacobian_graph() const override { return graph_; }
  void set_time_derivative(double, const double a, const Vector &b) override
  {
    a_ = a;
    Tpetra::deep_copy(*b_, b);
  }
  void evaluate(const Vector &x, Vector *f, Matrix *J) override
  {
    const bool too_long = max_step_ > 0.0 && a_ < 1.0 / max_step_ - 1e-12;
    if (f != nullptr)
    {
      f->update(a_ + lambda_, x, 1.0, *b_, 0.0);
      if (too_long)
        f->putScalar(std::numeric_limits<double>::quiet_NaN());
    }
    if (J != nullptr)
    {
      J->resumeFill();
      J->setAllToScalar(a_ + lambda_);
      J->fillComplete();
    }
  }

  void step_accepted(const double time, const Vector &) override
  {
    // Refused as a contact pair slid beyond its margin refuses it (PairResearch::rows_at).
    if (time > refuse_after)
      throw kiln::RunError("refused at t = " + std::to_string(time));
    ++accepted;
  }
  void step_rejected() override { ++rejected; }
  int accepted = 0; ///< step_accepted() calls
  int rejected = 0; ///< step_rejected() calls
  /// step_accepted() refuses a state after this time with a RunError [s].
  double refuse_after = std::numeric_limits<double>::infinity();

private:
  double lambda_;
  double max_step_;
  double a_ = 0.0;
  RCP<const Map> map_;
  RCP<const Graph> graph_;
  RCP<Vector> b_;
};

struct Outcome
{
  TimeStepper::Statistics stats;
  std::vector<double> times; ///< seen by the output function
  double error = 0.0;        ///< max |y - exp(-lambda t)| at the last output time
  int accepted = 0;          ///< the problem told of accepted steps
  int rejected = 0;          ///< and of rejected ones
};

Outcome run(const Teuchos::ParameterList &stepping, const std::vector<double> &output_times,
            const double lambda = 2.0, const double max_step = 0.0)
{
  auto problem = Teuchos::rcp(new Decay(lambda, max_step));
  auto quiet = Teuchos::getFancyOStream(Teuchos::rcp(new Teuchos::oblackholestream));
  Teuchos::ParameterList solver; // as an input gives it: NewtonSolver adds the defaults
  solver.set("Absolute Tolerance", 1e-13);
  solver.set("Relative Tolerance", 1e-13);
  solver.sublist("Linear Solver").set("Preconditioner Type", "None");
  kiln::NewtonSolver newton(solver, problem, quiet);
  Teuchos::ParameterList p = TimeStepper::valid_parameters();
  p.setParameters(stepping);
  const TimeStepper stepper(p, "test.xml: Kiln/Time Stepping", quiet);
  NonlinearProblem::Vector x(problem->solution_map());
  x.putScalar(1.0);
  Outcome r;
  r.stats = stepper.run(*problem, newton, x, 0.0, output_times,
                        [&](const double t, int, double, const NonlinearProblem::Vector &)
                        { r.times.push_back(t); });
  NonlinearProblem::Vector exact(problem->solution_map());
  exact.putScalar(std::exp(-lambda * output_times.back()));
  exact.update(1.0, x, -1.0);
  r.error = exact.normInf();
  r.accepted = problem->accepted;
  r.rejected = problem->rejected;
  return r;
}

Teuchos::ParameterList stepping(const std::string &method, const double initial,
                                const double maximum, const bool error_control,
                                const double rtol = 1e-3)
{
  Teuchos::ParameterList p;
  p.set("Method", method);
  p.set("Initial Step", initial);
  p.set("Maximum Step", maximum);
  p.set("Error Control", error_control);
  p.set("Relative Error Tolerance", rtol);
  p.set("Absolute Error Tolerance", 1e-12);
  return p;
}
} // namespace

TEST(TimeStepper, LandsExactlyOnEveryOutputTime)
{
  const std::vector<double> times{0.0, 0.3, 0.35, 1.0};
  for (const char *method : {"BDF2", "Backward Euler"})
  {
    const Outcome r = run(stepping(method, 0.1, 0.25, false), times);
    EXPECT_EQ(r.times, times) << method;
    EXPECT_EQ(r.stats.error_rejections, 0);
    EXPECT_EQ(r.stats.newton_failures, 0);
  }
}

TEST(TimeStepper, TighterToleranceGivesSmallerErrorWithMoreSteps)
{
  for (const char *method : {"BDF2", "Backward Euler"})
  {
    const Outcome loose = run(stepping(method, 0.01, 1.0, true, 1e-3), {2.0});
    const Outcome tight = run(stepping(method, 0.01, 1.0, true, 1e-5), {2.0});
    std::cout << method << ": rtol 1e-3: " << loose.stats.steps << " steps, error " << loose.error
              << "; rtol 1e-5: " << tight.stats.steps << " steps, error " << tight.error << "\n";
    EXPECT_GT(tight.stats.steps, loose.stats.steps) << method;
    EXPECT_LT(tight.error, loose.error / 10) << method;
  }
}

TEST(TimeStepper, RejectsStepsTheErrorEstimateFindsTooLong)
{
  // Steps of 0.5 s on a decay rate of 2 /s: the first two (no estimate yet) are taken, the
  // next is rejected by the estimate and repeated shorter.
  const Outcome r = run(stepping("BDF2", 0.5, 0.5, true, 1e-4), {3.0});
  EXPECT_GT(r.stats.error_rejections, 0);
  EXPECT_EQ(r.times, std::vector<double>{3.0});
  // The problem is told of every step: accepted, or rejected (its state restored).
  EXPECT_EQ(r.rejected, r.stats.error_rejections);
  EXPECT_EQ(r.accepted, r.stats.steps);
}

TEST(TimeStepper, FailedNewtonSolveIsRepeatedWithASmallerStep)
{
  Teuchos::ParameterList p = stepping("Backward Euler", 1.0, 1.0, false);
  p.set("Step Reduction", 0.25);
  const Outcome r = run(p, {2.0}, 2.0, 0.3); // steps over 0.3 s fail
  // 1.0 s fails and 0.25 s passes; each time the step grows back past 0.3 s it fails
  // again and is repeated shorter, so the run goes on to the end.
  EXPECT_GE(r.stats.newton_failures, 1);
  EXPECT_GT(r.stats.steps, r.stats.newton_failures);
  EXPECT_EQ(r.rejected, r.stats.newton_failures);
  EXPECT_EQ(r.accepted, r.stats.steps);
  EXPECT_EQ(r.times, std::vector<double>{2.0});
  EXPECT_LT(r.error, 0.1);
  // The step after one that followed a failure does not grow: each failure is followed by
  // at least two accepted steps of 0.25 s (growing right away, every other attempt failed).
  std::cout << r.stats.steps << " steps, " << r.stats.newton_failures << " Newton failures\n";
  EXPECT_LE(2 * r.stats.newton_failures, r.stats.steps + 1);
}

TEST(TimeStepper, StepBelowMinimumIsARunError)
{
  Teuchos::ParameterList p = stepping("Backward Euler", 1.0, 1.0, false);
  p.set("Minimum Step", 0.5);
  EXPECT_THROW(run(p, {2.0}, 2.0, 0.3), kiln::RunError);
}

namespace
{
/// A Newton solve that did not converge.
kiln::NewtonSolver::Result failed(const double initial, const double final_norm,
                                  const int iterations, const double tolerance)
{
  kiln::NewtonSolver::Result r;
  r.newton_iterations = iterations;
  r.initial_residual_norm = initial;
  r.final_residual_norm = final_norm;
  r.tolerance = tolerance;
  return r;
}
} // namespace

TEST(NewtonFailure, SaysWhatHappenedAndWhatToTryWithoutBlamingTheConditions)
{
  using kiln::newton_advice;
  using kiln::newton_failure;
  using testing::HasSubstr;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // The iteration limit at a tiny residual: the tolerance is out of reach.
  auto r = failed(2.036e2, 2.9e-13, 20, 1e-300);
  EXPECT_EQ(newton_failure(r, 20),
            "Newton reached its limit of 20 iterations (Solver/\"Maximum Iterations\") without "
            "converging (|F| 2.036e+02 -> 2.900e-13, tolerance 1.000e-300; |F| fell by a factor "
            "7e+14)");
  EXPECT_THAT(newton_advice(r, 20), HasSubstr("the tolerance may be out of reach; loosen "
                                              "Solver/\"Absolute Tolerance\""));
  // Still falling at the limit.
  r = failed(1e2, 1e-3, 20, 1e-8);
  EXPECT_THAT(newton_advice(r, 20), HasSubstr("|F| was still falling: raise Solver/\"Maximum "
                                              "Iterations\""));
  // Not falling.
  r = failed(1e2, 50.0, 20, 1e-8);
  EXPECT_THAT(newton_failure(r, 20), HasSubstr("|F| fell by a factor 2"));
  EXPECT_THAT(newton_advice(r, 20), HasSubstr("take smaller steps"));
  // NOX stopped before the limit.
  r = failed(1e2, 50.0, 3, 1e-8);
  EXPECT_THAT(newton_failure(r, 20), HasSubstr("NOX stopped after 3 of 20 iterations without "
                                               "converging, as a line search or a linear solve "
                                               "failed"));
  // Not a number, at the start or on the way.
  r = failed(nan, nan, 0, nan);
  EXPECT_EQ(newton_failure(r, 20),
            "the residual at the start of the step is not a finite number (NaN or Inf)");
  r = failed(1e2, nan, 2, 1e-8);
  EXPECT_EQ(newton_failure(r, 20),
            "the residual became NaN or Inf after 2 Newton iterations (|F| 1.000e+02 before)");
  EXPECT_THAT(newton_advice(r, 20), HasSubstr("A NaN or Inf comes from a value out of its range"));
  for (const auto &c : {failed(2e2, 3e-13, 20, 1e-300), failed(1e2, 1e-3, 20, 1e-8),
                        failed(1e2, 50.0, 20, 1e-8), failed(nan, nan, 0, nan)})
    EXPECT_THAT(newton_failure(c, 20) + newton_advice(c, 20), testing::Not(HasSubstr("boundary")));
}

TEST(TimeStepper, RefusedStateEndsAtTheLastAcceptedStep)
{
  struct Stops final : TimeStepper::Observer
  {
    void stop_time(const TimeStepper::State &state) override { times.push_back(state.time); }
    std::vector<double> times;
  };
  auto quiet = Teuchos::getFancyOStream(Teuchos::rcp(new Teuchos::oblackholestream));
  for (const char *method : {"BDF2", "Backward Euler", "Steady"})
  {
    auto problem = Teuchos::rcp(new Decay(2.0, 0.0));
    problem->refuse_after = 0.35;
    Teuchos::ParameterList solver;
    solver.set("Absolute Tolerance", 1e-13);
    solver.set("Relative Tolerance", 1e-13);
    solver.sublist("Linear Solver").set("Preconditioner Type", "None");
    kiln::NewtonSolver newton(solver, problem, quiet);
    Teuchos::ParameterList p = TimeStepper::valid_parameters();
    p.setParameters(stepping(method, 0.1, 0.1, false));
    const TimeStepper stepper(p, "test.xml: Kiln/Time Stepping", quiet);
    NonlinearProblem::Vector x0(problem->solution_map());
    x0.putScalar(1.0);
    TimeStepper::State state = stepper.initial_state(0.0, x0);
    Stops stops;
    EXPECT_THROW(stepper.run(*problem, newton, state, {0.0, 0.3, 0.4, 1.0}, stops), kiln::RunError)
        << method;
    // The last accepted state is 0.3 s (a step or a steady solve lands there), and x is its.
    EXPECT_DOUBLE_EQ(state.time, 0.3) << method;
    EXPECT_EQ(stops.times, (std::vector<double>{0.0, 0.3})) << method;
    EXPECT_EQ(problem->rejected, 1) << method;
    EXPECT_EQ(problem->accepted, state.accepted) << method;
    // x at 0.3 s: backward Euler's three steps of 0.1 s give 1/1.2^3; BDF2's exp(-0.6) to
    // its error; the steady solve's x is 0.
    const std::string m = method;
    const double expected = m == "Steady" ? 0.0 : m == "BDF2" ? std::exp(-0.6) : 1.0 / 1.728;
    EXPECT_NEAR(state.x->normInf(), expected, m == "BDF2" ? 0.02 : 1e-12) << method;
  }
}
