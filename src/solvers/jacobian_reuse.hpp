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
#include <functional>
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
  /// `within_solve` (Solver/"Keep Preconditioner Within Solve"): for a Jacobian that varies
  /// with x (no jacobian dependencies), the later Jacobians of a Newton solve keep the
  /// preconditioner of its first while the problem's preconditioner_dependencies() are those
  /// of the first and no linear solve since failed (failed_solves()).
  /// `across_steps` (Solver/"Keep Preconditioner Across Steps", with `within_solve`): the
  /// first Jacobian of a solve also keeps the preconditioner of the solve before, under the
  /// same conditions but the ||F|| one, the smooth preconditioner dependencies (a) within a
  /// factor 1 + `tolerance` of the version's, unless it is stale (end_solve()).
  /// `staleness` (Solver/"Preconditioner Staleness Factor"): a preconditioner kept across
  /// steps goes stale once a solve that kept it took more than this times the Krylov
  /// iterations per Newton iteration of the solve that built it.
  explicit JacobianReuse(bool enabled, double tolerance = 0.0, bool within_solve = false,
                         bool across_steps = false, double staleness = 2.0)
      : enabled_(enabled), tolerance_(tolerance), within_solve_(within_solve),
        across_steps_(across_steps), staleness_(staleness)
  {
  }

  /// Whether the Jacobian of the last can_keep() varies with x (no dependencies on some
  /// rank; the same answer on every rank): with Reuse, or with track_varying().
  bool varying() const { return varying_; }
  /// varying() is asked (Solver/"Adaptive Linear Tolerance Rate" > 0): can_keep() finds it
  /// with Reuse off too. Without it and without Reuse, can_keep() is false on every rank
  /// without asking the problem or the other ranks. Call alike on every rank.
  void track_varying() { track_varying_ = true; }
  /// A Newton solve begins: its first Jacobian begins a new version if it varies with x.
  void begin_solve()
  {
    solve_begun_ = true;
    solve_began_version_ = false;
  }
  /// A Newton solve ended (converged or not) after `newton_iterations` iterations with
  /// `linear_iterations` Krylov iterations in all (the same on every rank). With
  /// `across_steps`: an unconverged solve makes the preconditioner stale; a solve that began
  /// a version sets the fresh Krylov count per Newton iteration; a solve that kept the
  /// preconditioner throughout makes it stale once its count exceeds `staleness` times that.
  void end_solve(bool converged, int newton_iterations, int linear_iterations);
  /// A point a run can be restarted from (a checkpoint, a stop time): with `across_steps`
  /// the preconditioner kept across steps is given up, so that the next solve builds one
  /// from its first Jacobian, as a run restarted from here does: the two go on alike, to
  /// the last bit.
  void restart_point() { stale_ = true; }
  /// ||F|| of the residual just evaluated (as the solver sees it; the same on every rank).
  /// A preconditioner kept within a solve is given up at the next Jacobian unless the last
  /// Newton iteration at least halved ||F|| (the F evaluated before each Jacobian is that at
  /// its x).
  void residual_evaluated(double norm) { residual_norm_ = norm; }
  /// The count of linear solves that stopped short of their tolerance (the same on every
  /// rank): a preconditioner kept within a solve is given up at the next Jacobian once it
  /// grew since that preconditioner's version began.
  void set_failed_solves(std::function<int()> count) { failed_solves_ = std::move(count); }

  /// Whether J still holds the problem's Jacobian at x (x as the problem sees it): its
  /// dependencies are non-empty and equal to those of J's last evaluation, on every rank
  /// (never with Reuse off). Collective (no communication with Reuse off unless
  /// track_varying()). If not, the caller evaluates J and then calls evaluated(J).
  bool can_keep(NonlinearProblem &problem, const NonlinearProblem::Vector &x,
                const NonlinearProblem::Matrix &J);
  /// J now holds the Jacobian of the state of the last can_keep(), whose first `smooth`
  /// dependencies are smooth coefficients. Collective.
  void evaluated(const NonlinearProblem::Matrix &J, std::size_t smooth = 0);
  /// J's values are no longer known (an evaluation into it threw): the next can_keep() is
  /// false and the next evaluated() begins a new version. Collective (called alike on every
  /// rank).
  void forget()
  {
    matrix_ = nullptr;
    dependencies_.clear();
    pending_.clear();
  }
  /// Changes with every evaluated() whose Jacobian the last preconditioner does not serve:
  /// a preconditioner built at one version is used while it lasts.
  std::uint64_t version() const { return version_; }

  /// Builds the preconditioner of the current version by calling `build` with J holding the
  /// Jacobian it is to be built from: the last evaluated, or after restore_origin() the
  /// one the uninterrupted run built it from (by the function given to
  /// set_jacobian_with()). Collective.
  void build(const std::function<void()> &build);
  /// J as NonlinearProblem::jacobian_with(smooth, x, J) for the last evaluated J and its x,
  /// scaled as the solver sees it; false if the problem cannot.
  using JacobianWith = std::function<bool(const std::vector<double> &smooth)>;
  void set_jacobian_with(JacobianWith f) { jacobian_with_ = std::move(f); }
  /// What a restarted run needs to go on with the preconditioner this one keeps, exactly
  /// (with a tolerance > 0; empty otherwise or if none is built for the current version):
  /// this rank's record of the smooth dependencies that began the version and those of
  /// the Jacobian the preconditioner was built from, with a hash of the others.
  std::vector<double> origin() const;
  /// Given a record of origin() (this rank's, from a checkpoint of a run on as many ranks):
  /// at the first evaluated(), if that run's preconditioner serves the new Jacobian as it
  /// would have there, the version goes on from the record and its preconditioner is built
  /// from the Jacobian with the recorded coefficients. Otherwise nothing changes.
  void restore_origin(std::vector<double> record) { restored_ = std::move(record); }
  /// Whether restore_origin() waits for its first evaluated() (the solver then keeps x).
  bool restoring() const { return !restored_.empty(); }

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
  /// restore_origin() at the first evaluated(): whether it took (on every rank).
  bool restore(const NonlinearProblem::Matrix &J, std::size_t smooth);

  /// Whether the preconditioner of a varying Jacobian serves J within the solve (the
  /// version's preconditioner dependencies equal, no failed linear solve since, ||F||
  /// halved by the last Newton iteration; collective).
  /// `first_of_solve` (across_steps_): the same without the ||F|| condition. With
  /// across_steps_ the smooth preconditioner dependencies are compared within the tolerance.
  bool serves_within_solve(const NonlinearProblem::Matrix &J, double last_norm,
                           bool first_of_solve = false) const;

  bool enabled_;
  double tolerance_;
  bool within_solve_;
  bool across_steps_;
  double staleness_;
  bool stale_ = true;                ///< across_steps_: no fresh count yet, or stale
  double fresh_krylov_ = 0.0;        ///< Krylov per Newton iteration of the version's solve
  bool solve_began_version_ = false; ///< since begin_solve()
  bool solve_begun_ = false;
  bool track_varying_ = false;
  bool varying_ = false;
  std::vector<double> pending_preconditioner_; ///< of the last can_keep(), varying J only
  std::vector<double> version_preconditioner_; ///< those of the version's first Jacobian
  int version_failed_solves_ = 0;              ///< failed_solves_() then
  double residual_norm_ = 0.0;                 ///< of the last residual_evaluated()
  double jacobian_residual_norm_ = 0.0;        ///< residual_norm_ at the last evaluated()
  std::function<int()> failed_solves_;
  std::uint64_t version_ = 0;
  const NonlinearProblem::Matrix *matrix_ = nullptr; ///< the last evaluated
  std::vector<double> dependencies_;                 ///< of its last evaluation
  std::vector<double> pending_;                      ///< of the last can_keep()
  std::vector<double> version_dependencies_;         ///< of the evaluation that began version_
  std::size_t smooth_ = 0;                           ///< smooth dependencies (leading)
  std::vector<double> built_;       ///< of the Jacobian the preconditioner was built from
  std::uint64_t built_version_ = 0; ///< the version it was built at (0: none)
  std::vector<double> build_at_;    ///< smooth dependencies to build the next one at
  std::vector<double> restored_;    ///< restore_origin()'s record, until evaluated()
  JacobianWith jacobian_with_;
  Counts counts_;
};

/// A preconditioner factory whose preconditioners hold copies of the operator's values
/// (BlockTriangularPreconditionerFactory): ReusingPreconditionerFactory calls refresh() when
/// it keeps a preconditioner for a Jacobian evaluated anew, so that the copies read the new
/// values as MueLu's finest level reads J's own.
class RefreshingPreconditionerFactory
{
public:
  virtual ~RefreshingPreconditionerFactory() = default;
  virtual void refresh(const Thyra::LinearOpSourceBase<double> &fwdOpSrc) const = 0;
};

/// A preconditioner factory (MueLu's, Ifpack2's from Stratimikos) that builds a
/// preconditioner only when the operator or its JacobianReuse version changed since it last
/// built it; everything else is the wrapped factory's. The operator it puts in a
/// preconditioner (a Thyra::DefaultPreconditioner) is a handle that it empties before it
/// builds that preconditioner anew: the linear solver holds the last operator until it is
/// given the new one, so the two would otherwise live side by side during the build.
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
    int evaluated = 0; ///< JacobianReuse's count of Jacobians evaluated then
  };
  mutable Built built_;
};
} // namespace internal
} // namespace kiln
