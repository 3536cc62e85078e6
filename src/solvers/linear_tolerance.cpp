#include "solvers/linear_tolerance.hpp"

#include <NOX_Abstract_Group.H>
#include <NOX_Observer.hpp>
#include <NOX_Solver_Generic.H>

#include <algorithm>
#include <cmath>
#include <string>

namespace kiln
{
namespace internal
{
namespace
{
/// Calls back the adaptive tolerance before each Newton iteration, F_k already computed.
class ToleranceObserver final : public NOX::Observer
{
public:
  explicit ToleranceObserver(AdaptiveLinearTolerance &tolerance) : tolerance_(tolerance) {}
  void runPreIterate(const NOX::Solver::Generic &solver) override
  {
    tolerance_.update(solver.getSolutionGroup().getNormF());
  }

private:
  AdaptiveLinearTolerance &tolerance_;
};

Teuchos::ParameterList &newton_linear_solver(Teuchos::ParameterList &nox)
{
  return nox.sublist("Direction").sublist("Newton").sublist("Linear Solver");
}
} // namespace

double LinearTolerance::operator()(const double target, const double residual_norm,
                                   const double previous_norm, const bool first_varying) const
{
  if (!(residual_norm > 0.0) || !(target > 0.0))
    return floor;
  double eta = safety * target / residual_norm;
  if (first_varying)
    eta = std::max(eta, first);
  // Only while ||F|| falls: a residual that grew says nothing of the next one.
  if (rate > 0.0 && previous_norm > residual_norm && std::isfinite(previous_norm))
  {
    const double ratio = residual_norm / previous_norm;
    eta = std::max(eta, rate * ratio * ratio);
  }
  return std::clamp(eta, floor, std::max(floor, ceiling));
}

double belos_convergence_tolerance(const Teuchos::ParameterList &stratimikos)
{
  if (stratimikos.isType<std::string>("Linear Solver Type") &&
      stratimikos.get<std::string>("Linear Solver Type") != "Belos")
    return 0.0;
  constexpr double belos_default = 1e-8;
  if (!stratimikos.isSublist("Linear Solver Types") ||
      !stratimikos.sublist("Linear Solver Types").isSublist("Belos"))
    return belos_default;
  const Teuchos::ParameterList &belos = stratimikos.sublist("Linear Solver Types").sublist("Belos");
  if (!belos.isType<std::string>("Solver Type") || !belos.isSublist("Solver Types"))
    return belos_default;
  const Teuchos::ParameterList &types = belos.sublist("Solver Types");
  const std::string solver = belos.get<std::string>("Solver Type");
  if (!types.isSublist(solver) || !types.sublist(solver).isType<double>("Convergence Tolerance"))
    return belos_default;
  return types.sublist(solver).get<double>("Convergence Tolerance");
}

AdaptiveLinearTolerance::AdaptiveLinearTolerance(const LinearTolerance rule,
                                                 Teuchos::ParameterList &linear_solver)
    : rule_(rule), linear_solver_(linear_solver)
{
}

void AdaptiveLinearTolerance::set_target(const double target, std::function<bool()> varying,
                                         const bool first_varying)
{
  target_ = target;
  varying_ = std::move(varying);
  first_varying_ = first_varying;
  previous_norm_ = 0.0;
}

void AdaptiveLinearTolerance::update(const double residual_norm)
{
  const bool first = !(previous_norm_ > 0.0);
  const bool varying = !first && varying_ && varying_();
  linear_solver_.set("Tolerance", rule_(target_, residual_norm, varying ? previous_norm_ : 0.0,
                                        first && first_varying_));
  previous_norm_ = residual_norm;
}

Teuchos::RCP<NOX::Observer> AdaptiveLinearTolerance::observer()
{
  return Teuchos::rcp(new ToleranceObserver(*this));
}

void use_relative_residual_measure(Teuchos::ParameterList &nox, const double first_tolerance)
{
  Teuchos::ParameterList &linear = newton_linear_solver(nox);
  linear.set("Solve Measure Numerator", "Norm Residual");
  linear.set("Solve Measure Denominator", "Norm RHS");
  linear.set("Tolerance", first_tolerance);
}

} // namespace internal
} // namespace kiln
