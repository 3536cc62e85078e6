#pragma once
/// Private to src/solvers: the Thyra model evaluator NOX sees, over a
/// NonlinearProblem. x and f live on solution_map(); W is a Tpetra::CrsMatrix
/// on jacobian_graph() (static graph), wrapped by Thyra::tpetraLinearOp and
/// solved with the Stratimikos factory given at construction. With the
/// unknown scale c (the problem's unknown_scale()), NOX sees the scaled system: x̂ = x / c,
/// F̂(x̂) = c F(c x̂), Ŵ = diag(c) J diag(c). W is evaluated only when JacobianReuse says the
/// matrix does not hold the Jacobian at x already.
#include "discretization/nonlinear_problem.hpp"
#include "solvers/free_motion_pins.hpp"
#include "solvers/jacobian_reuse.hpp"

#include <Thyra_LinearOpWithSolveFactoryBase.hpp>
#include <Thyra_StateFuncModelEvaluatorBase.hpp>

namespace kiln
{
namespace internal
{
class ModelEvaluator final : public Thyra::StateFuncModelEvaluatorBase<double>
{
public:
  /// `scale`: c, or null for none. `pins`: the free motions' pins (FreeMotionPins), or null
  /// for none: Ŵ pinned after scaling, F̂'s pin rows zeroed.
  ModelEvaluator(Teuchos::RCP<NonlinearProblem> problem,
                 Teuchos::RCP<const NonlinearProblem::Vector> scale,
                 Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> W_factory,
                 Teuchos::RCP<JacobianReuse> reuse, Teuchos::RCP<FreeMotionPins> pins);

  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_x_space() const override;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_f_space() const override;
  Thyra::ModelEvaluatorBase::InArgs<double> getNominalValues() const override;
  Thyra::ModelEvaluatorBase::InArgs<double> createInArgs() const override;
  /// A new matrix on the problem's Jacobian graph, fill-complete, zero.
  Teuchos::RCP<Thyra::LinearOpBase<double>> create_W_op() const override;
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> get_W_factory() const override;

private:
  Thyra::ModelEvaluatorBase::OutArgs<double> createOutArgsImpl() const override;
  /// f = F(x) and/or W = dF/dx through NonlinearProblem::evaluate; a failure on some ranks
  /// is the same RunError on every rank (evaluate_collectively).
  void evalModelImpl(const Thyra::ModelEvaluatorBase::InArgs<double> &in_args,
                     const Thyra::ModelEvaluatorBase::OutArgs<double> &out_args) const override;
  /// J (the last evaluated, at x_origin_) as the problem's jacobian_with(smooth), scaled;
  /// for JacobianReuse's restart. Collective.
  bool jacobian_with(const std::vector<double> &smooth) const;
  /// The scaling of W: diag(c) J diag(c) (nothing without c); then the pins, if any.
  void scale_jacobian(NonlinearProblem::Matrix &J) const;

  Teuchos::RCP<NonlinearProblem> problem_;
  Teuchos::RCP<const NonlinearProblem::Vector> scale_; ///< c, or null
  Teuchos::RCP<NonlinearProblem::Vector> x_unscaled_;  ///< c x̂
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> W_factory_;
  Teuchos::RCP<JacobianReuse> reuse_;
  Teuchos::RCP<FreeMotionPins> pins_; ///< or null
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> space_;
  Thyra::ModelEvaluatorBase::InArgs<double> nominal_values_;
  /// While JacobianReuse restores a checkpoint's preconditioner: the x (as the problem sees
  /// it) and the matrix of the Jacobian evaluated then.
  mutable Teuchos::RCP<NonlinearProblem::Vector> x_origin_;
  mutable Teuchos::RCP<NonlinearProblem::Matrix> J_origin_;
};
} // namespace internal
} // namespace kiln
