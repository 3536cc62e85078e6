#pragma once
/// The tolerance of the Krylov solve inside each Newton iteration (inexact Newton,
/// doc/solvers.md): loose enough to stop once the Newton test will pass with a margin, never
/// tighter than the Belos solver's own Convergence Tolerance.

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <functional>

namespace NOX
{
class Observer;
}

namespace kiln
{
namespace internal
{
/// eta_k, the Krylov residual over ||F_k||: safety * target / ||F_k||, clamped to
/// [floor, ceiling]. Newton's next residual is ||F_k + J dx|| <= eta_k ||F_k|| on a problem
/// linear between changes of the contact set, so it meets `target` with the factor `safety`
/// to spare, in one Newton iteration.
struct LinearTolerance
{
  double floor = 1e-10; ///< the Belos solver's Convergence Tolerance
  double ceiling = 0.1; ///< never looser: the Newton step must stay a descent direction
  /// Fraction of the Newton target left for the Krylov residual (Solver/"Adaptive Linear
  /// Tolerance Safety"; 0: always the floor).
  double safety = 0.0;
  /// For a Jacobian that varies with the state, from the second Newton iteration on, while
  /// ||F|| falls: eta_k is at least rate (||F_k|| / ||F_{k-1}||)^2 (Solver/"Adaptive Linear
  /// Tolerance Rate"; 0: not used). Newton with the consistent tangent converges quadratically, so
  /// its next residual is about ||F_k|| (||F_k|| / ||F_{k-1}||)^2: the Krylov residual is `rate`
  /// times that, and the iterations keep their order (Eisenstat and Walker's second choice).
  double rate = 0.0;
  /// For a Jacobian that varies with the state, the first Newton iteration of a solve: eta_0
  /// is at least this (Solver/"Adaptive Linear Tolerance First"; 0: not used), Eisenstat and
  /// Walker's fixed first forcing term: the first Newton step of a step with flow leaves the
  /// flow's share of ||F_0|| whatever the Krylov residual below it.
  double first = 0.0;
  /// `target`: the Newton test's ||F|| to reach; `residual_norm`: ||F_k||;
  /// `previous_norm`: ||F_{k-1}|| (0 at the first iteration or for a constant Jacobian);
  /// `first_varying`: the first iteration of a solve whose Jacobian varies (`first` applies).
  double operator()(double target, double residual_norm, double previous_norm = 0.0,
                    bool first_varying = false) const;
};

/// The Krylov tolerance of the Belos solver chosen in a Stratimikos list ("Convergence
/// Tolerance" of its Solver Types sublist, Belos' default 1e-8 if not set), or 0 when the
/// linear solver is not Belos (then the tolerance is not adapted).
double belos_convergence_tolerance(const Teuchos::ParameterList &stratimikos);

/// A NOX observer that sets NOX's Direction/Newton/Linear Solver "Tolerance" before every
/// Newton iteration from ||F_k|| of the solver's current group and the target set for the
/// solve (set_target). The list is NOX's, so it reads the tolerance when it solves.
class AdaptiveLinearTolerance
{
public:
  AdaptiveLinearTolerance(LinearTolerance rule, Teuchos::ParameterList &linear_solver);
  /// The Newton test's ||F|| to reach in this solve: max(absolute, relative ||F(x0)||).
  /// `varying`: whether the Jacobian varies with the state (the rule's `rate` applies), asked
  /// at each update() from the second Newton iteration on (the first Jacobian of the solve
  /// has then been evaluated); null: never.
  /// `first_varying`: the Jacobian varies (NewtonSolver::jacobian_varies(): the problem's, so
  /// alike in a restarted run), the rule's `first` applies to the first iteration.
  void set_target(double target, std::function<bool()> varying = {}, bool first_varying = false);
  /// Sets the Tolerance in the NOX linear solver list from the current residual norm (and
  /// the last one, for a varying Jacobian).
  void update(double residual_norm);
  /// The observer to register in NOX's "Solver Options"/"Observer".
  Teuchos::RCP<NOX::Observer> observer();

private:
  LinearTolerance rule_;
  Teuchos::ParameterList &linear_solver_;
  double target_ = 0.0;
  std::function<bool()> varying_;
  double previous_norm_ = 0.0; ///< ||F_{k-1}|| of this solve (0 before its first iteration)
  bool first_varying_ = false;
};

/// Prepares the NOX list's Direction/Newton/Linear Solver for the adapted tolerance: the
/// solve measure ||r|| / ||b|| (Belos' "Norm of RHS" scaling) and the first tolerance.
void use_relative_residual_measure(Teuchos::ParameterList &nox, double first_tolerance);

} // namespace internal
} // namespace kiln
