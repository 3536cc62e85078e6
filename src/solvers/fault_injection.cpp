#include "solvers/fault_injection.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace kiln
{
Teuchos::ParameterList FaultInjection::valid_parameters()
{
  Teuchos::ParameterList p("Debug");
  p.set("Fault", "None",
        "a testing aid, never for real runs: \"Exception In Assembly\" throws an exception in "
        "the residual evaluation of one rank (the run must stop on every rank with one "
        "message, exit status 2, its last good state written); \"NaN In Residual\" makes one "
        "entry of that rank's residual NaN (the step must be repeated with a smaller step, "
        "and the run stop at \"Minimum Step\" if the NaN stays); \"Step Failure In Assembly\" "
        "throws on that rank the exception of a constitutive model whose local solve does "
        "not converge (a StepFailure: the step must be repeated smaller on every rank, and "
        "the run stop at \"Minimum Step\" if it stays); \"None\": no fault",
        choice_validator(
            {"None", "Exception In Assembly", "NaN In Residual", "Step Failure In Assembly"}));
  p.set("Rank", 0, "the MPI rank the fault happens on, < the number of ranks [-]",
        nonnegative_int_validator());
  p.set("Time", 0.0,
        "the fault starts with the first residual evaluation of a step ending at or after this "
        "time (the equilibrium at t = 0 counts as t = 0) [s]",
        nonnegative_double_validator());
  p.set("Evaluations", 1,
        "how many residual evaluations from then on have the fault; -1: all of them [count]");
  return p;
}

Teuchos::RCP<TransientProblem> FaultInjection::wrap(Teuchos::RCP<TransientProblem> problem,
                                                    const Teuchos::ParameterList &debug,
                                                    const std::string &where,
                                                    Teuchos::FancyOStream &out)
{
  if (debug.get<std::string>("Fault") == "None")
    return problem;
  auto faulty = Teuchos::rcp(new FaultInjection(std::move(problem), debug, where));
  out << "kiln: warning: " << where << "/\"Fault\" = \"" << debug.get<std::string>("Fault")
      << "\" injects a fault on rank " << debug.get<int>("Rank")
      << " from t = " << debug.get<double>("Time")
      << " s (a testing aid: remove Kiln/Debug for real runs)\n";
  return faulty;
}

FaultInjection::FaultInjection(Teuchos::RCP<TransientProblem> problem,
                               const Teuchos::ParameterList &debug, const std::string &where)
    : problem_(problem.assert_not_null()), where_(where), fault_(debug.get<std::string>("Fault")),
      rank_(debug.get<int>("Rank")), time_(debug.get<double>("Time")),
      evaluations_(debug.get<int>("Evaluations"))
{
  const int n_ranks = problem_->solution_map()->getComm()->getSize();
  KILN_CHECK_INPUT(rank_ < n_ranks, where + "/\"Rank\"",
                   "is " << rank_ << " but the run has " << n_ranks << " rank"
                         << (n_ranks > 1 ? "s" : "") << ": give a rank below " << n_ranks);
  KILN_CHECK_INPUT(evaluations_ == -1 || evaluations_ >= 1, where + "/\"Evaluations\"",
                   "is " << evaluations_ << "; give a count >= 1, or -1 for all");
}

void FaultInjection::set_time_derivative(const double time, const double a, const Vector &b)
{
  now_ = time;
  problem_->set_time_derivative(time, a, b);
}

void FaultInjection::evaluate(const Vector &x, Vector *f, Matrix *J)
{
  problem_->evaluate(x, f, J);
  const bool due = f != nullptr && now_ >= time_ - 1e-12 * std::max(1.0, time_) &&
                   (evaluations_ < 0 || faults_ < evaluations_);
  if (!due)
    return;
  ++faults_; // on every rank: the evaluations are collective
  if (solution_map()->getComm()->getRank() != rank_)
    return;
  if (fault_ == "NaN In Residual")
  {
    if (f->getLocalLength() > 0)
      f->replaceLocalValue(0, std::numeric_limits<double>::quiet_NaN());
    return;
  }
  std::ostringstream message;
  message << where_ << "/\"Fault\" = \"" << fault_ << "\": the exception injected on rank " << rank_
          << " of " << solution_map()->getComm()->getSize()
          << " in the residual evaluation at t = " << now_ << " s";
  if (fault_ == "Step Failure In Assembly")
    throw StepFailure(message.str() + " (a testing aid: remove Kiln/Debug for real runs)");
  message << "; every rank stopped (a testing aid: remove Kiln/Debug for real runs)";
  throw RunError(message.str());
}
} // namespace kiln
