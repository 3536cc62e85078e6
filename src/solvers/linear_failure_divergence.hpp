#pragma once
/// A NOX status test that stops a Newton solve diverging on the steps of failed linear solves.
#include <NOX_StatusTest_Generic.H>

#include <functional>
#include <ostream>

namespace kiln
{
namespace internal
{
/// The growth of ||F|| over its start, after a linear solve short of its tolerance, that
/// stops a Newton solve (LinearFailureDivergence).
constexpr double linear_divergence_growth = 1e6;

/// Failed once a linear solve of this Newton solve stopped short of its tolerance and ||F||
/// has grown above `growth` times its value at the start of the solve. NOX's "Rescue Bad
/// Newton Solve" (kept true) takes the step of such a solve; with a preconditioner that does
/// not solve the Jacobian, those steps make ||F|| grow without end (1e4 to 1e33 in 20 Newton
/// iterations on a linear problem, doc/solvers.md "Linear solves short of their tolerance"),
/// and Newton would otherwise stop only at its iteration limit, with advice that does not name
/// the linear solver.
class LinearFailureDivergence : public NOX::StatusTest::Generic
{
public:
  /// `failures`: the linear solves short of their tolerance in this Newton solve so far;
  /// `initial_norm`: ||F|| at its start.
  LinearFailureDivergence(std::function<int()> failures, double initial_norm, double growth);

  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic &problem,
                                          NOX::StatusTest::CheckType check_type) override;
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream &print(std::ostream &stream, int indent = 0) const override;

private:
  std::function<int()> failures_;
  double initial_norm_;
  double growth_;
  double norm_ = 0.0;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};
} // namespace internal
} // namespace kiln
