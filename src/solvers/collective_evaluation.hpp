#pragma once
/// Private to src/solvers: the problem's residual and Jacobian as the solvers ask for them,
/// with a failure on some ranks turned into the same RunError on every rank.
#include "discretization/nonlinear_problem.hpp"

namespace kiln
{
namespace internal
{
/// problem.evaluate(x, f, J), then one reduction: if it threw on any rank, every rank throws
/// the same RunError, with the message of the lowest rank that threw (a RunError's as it is;
/// another exception's named with its rank, as the bug it is); a StepFailure if every rank
/// that threw threw one (a smaller step may avoid it). std::bad_alloc passes as it is
/// (main ends the run). A problem that throws on some ranks must have taken part in all of
/// its collective steps before (ResidualTerms does so for the kernels). Collective.
void evaluate_collectively(NonlinearProblem &problem, const NonlinearProblem::Vector &x,
                           NonlinearProblem::Vector *f, NonlinearProblem::Matrix *J);
} // namespace internal
} // namespace kiln
