#include "solvers/linear_failure_divergence.hpp"

#include <NOX_Abstract_Group.H>
#include <NOX_Solver_Generic.H>

#include <utility>

namespace kiln
{
namespace internal
{
LinearFailureDivergence::LinearFailureDivergence(std::function<int()> failures,
                                                 const double initial_norm, const double growth)
    : failures_(std::move(failures)), initial_norm_(initial_norm), growth_(growth)
{
}

NOX::StatusTest::StatusType
LinearFailureDivergence::checkStatus(const NOX::Solver::Generic &problem,
                                     const NOX::StatusTest::CheckType check_type)
{
  if (check_type == NOX::StatusTest::None)
  {
    status_ = NOX::StatusTest::Unevaluated;
    return status_;
  }
  // ||F|| of the current group, the same on every rank (a reduction NOX has made).
  norm_ = problem.getSolutionGroup().getNormF();
  status_ = failures_() > 0 && norm_ > growth_ * initial_norm_ ? NOX::StatusTest::Failed
                                                               : NOX::StatusTest::Unconverged;
  return status_;
}

std::ostream &LinearFailureDivergence::print(std::ostream &stream, const int indent) const
{
  for (int i = 0; i < indent; ++i)
    stream << ' ';
  stream << status_ << "||F|| = " << norm_ << " after linear solves short of their tolerance, "
         << "against " << growth_ << " x " << initial_norm_ << "\n";
  return stream;
}
} // namespace internal
} // namespace kiln
