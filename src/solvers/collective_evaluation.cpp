#include "solvers/collective_evaluation.hpp"

#include "base/errors.hpp"

#include <new>
#include <string>

namespace kiln
{
namespace internal
{
void evaluate_collectively(NonlinearProblem &problem, const NonlinearProblem::Vector &x,
                           NonlinearProblem::Vector *f, NonlinearProblem::Matrix *J)
{
  const Teuchos::Comm<int> &comm = *problem.solution_map()->getComm();
  std::string failure;
  bool step_failure = false;
  try
  {
    problem.evaluate(x, f, J);
  }
  catch (const std::bad_alloc &)
  {
    throw;
  }
  catch (const StepFailure &e)
  {
    failure = e.what();
    step_failure = true;
  }
  catch (const RunError &e)
  {
    failure = e.what();
  }
  catch (const std::exception &e)
  {
    failure = "rank " + std::to_string(comm.getRank()) + " of " + std::to_string(comm.getSize()) +
              " failed in the evaluation of the " + (f != nullptr ? "residual" : "Jacobian") +
              ": " + one_line_library_message(e.what()) +
              "; every rank stopped. This is a bug in Kiln or a library it uses: please report "
              "it with the input";
  }
  check_run_collectively(comm, failure.empty(), failure, step_failure);
}
} // namespace internal
} // namespace kiln
