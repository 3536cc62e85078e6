#pragma once
/// Private to src/solvers: the minimum-norm solution of a problem with free rigid motions
/// (NonlinearProblem::free_motions(); doc/solvers.md, "Free motions").
#include "discretization/nonlinear_problem.hpp"

#include <Tpetra_MultiVector.hpp>

#include <string>
#include <vector>

namespace kiln
{
namespace internal
{
/// For k free motions V (J V = 0, V^T J = 0, F(x + V t) = F(x)), in the solver's unknowns
/// x̂ = x / c as V̂ = V / c:
/// - pins: k unknowns p chosen by full pivoting on V̂, so that V̂_p (the pins' rows) is
///   regular. pin() turns the rows and columns of the pins in Ĵ into those of the identity
///   times their diagonal and residual() zeroes the pins' rows of F̂: the Newton system is
///   then regular (direct and multigrid preconditioners factor it), and its solution, the
///   one with dx_p = 0, solves the full system whenever V^T F = 0 (the rows of the pins
///   follow from the others);
/// - V^T F, the net force [N] along a free translation or moment [N m] about a free axis
///   (whatever x is), is kept by residual() before the pins' rows are zeroed;
///   pin_residual() is what it leaves at the pins once the other rows vanish,
///   ||V̂_p^{-T} V̂^T F̂||, which the Newton solver checks against its target;
/// - project() removes the motions from x̂ (x̂ -= Q Q^T x̂, Q orthonormal with V̂'s span): the
///   solution with no component in them, F unchanged.
class FreeMotionPins
{
public:
  using MultiVector = Tpetra::MultiVector<double>;
  using Vector = NonlinearProblem::Vector;
  using Matrix = NonlinearProblem::Matrix;

  /// `motions`: V in the problem's unknowns x; `inverse_scale`: 1 / c, or null (c = 1).
  /// Collective.
  FreeMotionPins(const MultiVector &motions, const Vector *inverse_scale,
                 std::vector<std::string> names);

  int size() const { return static_cast<int>(pins_.size()); }
  /// The global ids of the pinned unknowns.
  const std::vector<NonlinearProblem::Map::global_ordinal_type> &pins() const { return pins_; }
  /// Ĵ's pins: rows and columns zero but for the diagonal (kept; 1 if it is not > 0).
  void pin(Matrix &J) const;
  /// Keeps V^T F̂ and zeroes the pins' rows of F̂. Collective.
  void residual(Vector &f);
  /// x̂ without its components along the motions. Collective.
  void project(Vector &x) const;
  /// ||V̂_p^{-T} V̂^T F̂|| of the last residual().
  double pin_residual() const;
  /// The load's net force or moment along each motion at the last residual(), in words:
  /// "7 N along the translation along z".
  std::string imbalance() const;

private:
  Teuchos::RCP<MultiVector> V_; ///< V̂
  Teuchos::RCP<MultiVector> Q_; ///< orthonormal, the span of V̂
  std::vector<NonlinearProblem::Map::global_ordinal_type> pins_;
  std::vector<double> V_pins_; ///< V̂_p: row s = pin s, column j = motion j (k x k, row-major)
  std::vector<std::string> names_;
  std::vector<double> load_; ///< V^T F of the last residual()
};
} // namespace internal
} // namespace kiln
