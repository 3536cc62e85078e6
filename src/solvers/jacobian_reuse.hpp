#pragma once
/// Private to src/solvers: keeping the Jacobian and its preconditioner while they are
/// unchanged. The problem says what its Jacobian depends on
/// (NonlinearProblem::jacobian_dependencies: for Kiln's linear terms the time-derivative
/// coefficient, the constraints and the contact decision); while that is the same as at the
/// matrix's last evaluation, the model evaluator keeps the matrix and the preconditioner
/// factory keeps the preconditioner built from it (doc/solvers.md, "Reuse").
#include "discretization/nonlinear_problem.hpp"

#include <Thyra_PreconditionerFactoryBase.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace kiln
{
namespace internal
{
/// What was evaluated into the Jacobian matrix, and the counts of a run.
class JacobianReuse
{
public:
  /// `enabled` false: every Jacobian and preconditioner is built anew (Solver/"Reuse").
  /// `tolerance` > 0: a preconditioner is also kept for a Jacobian evaluated anew whose
  /// smooth dependencies (NonlinearProblem::smooth_dependencies) are each within a factor
  /// 1 + tolerance of those it was built for (same sign), the others equal
  /// (Solver/"Preconditioner Reuse Tolerance").
  explicit JacobianReuse(bool enabled, double tolerance = 0.0)
      : enabled_(enabled), tolerance_(tolerance)
  {
  }

  /// Whether J still holds the problem's Jacobian at x (x as the problem sees it): its
  /// dependencies are non-empty and equal to those of J's last evaluation, on every rank.
  /// Collective. If not, the caller evaluates J and then calls evaluated(J).
  bool can_keep(NonlinearProblem &problem, const NonlinearProblem::Vector &x,
                const NonlinearProblem::Matrix &J);
  /// J now holds the Jacobian of the state of the last can_keep(), whose first `smooth`
  /// dependencies are smooth coefficients. Collective.
  void evaluated(const NonlinearProblem::Matrix &J, std::size_t smooth = 0);
  /// Changes with every evaluated() whose Jacobian the last preconditioner does not serve:
  /// a preconditioner built at one version is used while it lasts.
  std::uint64_t version() const { return version_; }

  bool enabled() const { return enabled_; }
  struct Counts
  {
    int jacobians_evaluated = 0;
    int jacobians_kept = 0;
    int preconditioners_built = 0;
    int preconditioners_kept = 0;
  };
  const Counts &counts() const { return counts_; }
  Counts &counts() { return counts_; }

private:
  /// Whether a preconditioner built for a Jacobian with the dependencies `built` serves one
  /// with `now` (this rank's part).
  bool serves(const std::vector<double> &built, const std::vector<double> &now,
              std::size_t smooth) const;

  bool enabled_;
  double tolerance_;
  std::uint64_t version_ = 0;
  const NonlinearProblem::Matrix *matrix_ = nullptr; ///< the last evaluated
  std::vector<double> dependencies_;                 ///< of its last evaluation
  std::vector<double> pending_;                      ///< of the last can_keep()
  std::vector<double> version_dependencies_;         ///< of the evaluation that began version_
  Counts counts_;
};

/// A preconditioner factory (MueLu's, Ifpack2's from Stratimikos) that builds a
/// preconditioner only when the operator or its JacobianReuse version changed since it last
/// built it; everything else is the wrapped factory's.
class ReusingPreconditionerFactory final : public Thyra::PreconditionerFactoryBase<double>
{
public:
  ReusingPreconditionerFactory(Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>> factory,
                               Teuchos::RCP<JacobianReuse> reuse);

  bool isCompatible(const Thyra::LinearOpSourceBase<double> &fwdOpSrc) const override;
  Teuchos::RCP<Thyra::PreconditionerBase<double>> createPrec() const override;
  void initializePrec(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> &fwdOpSrc,
                      Thyra::PreconditionerBase<double> *precOp,
                      Thyra::ESupportSolveUse supportSolveUse) const override;
  void uninitializePrec(Thyra::PreconditionerBase<double> *prec,
                        Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> *fwdOpSrc,
                        Thyra::ESupportSolveUse *supportSolveUse) const override;

  void setParameterList(const Teuchos::RCP<Teuchos::ParameterList> &paramList) override;
  Teuchos::RCP<Teuchos::ParameterList> getNonconstParameterList() override;
  Teuchos::RCP<Teuchos::ParameterList> unsetParameterList() override;
  Teuchos::RCP<const Teuchos::ParameterList> getParameterList() const override;
  Teuchos::RCP<const Teuchos::ParameterList> getValidParameters() const override;

private:
  Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>> factory_;
  Teuchos::RCP<JacobianReuse> reuse_;
  /// The last preconditioner built: the object, its operator and the version.
  struct Built
  {
    const Thyra::PreconditionerBase<double> *prec = nullptr;
    const Thyra::LinearOpBase<double> *op = nullptr;
    std::uint64_t version = 0;
  };
  mutable Built built_;
};
} // namespace internal
} // namespace kiln
