#include "solvers/model_evaluator.hpp"

#include "base/errors.hpp"
#include "solvers/collective_evaluation.hpp"

#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>

namespace kiln
{
namespace internal
{
using Teuchos::RCP;
using MEB = Thyra::ModelEvaluatorBase;
using Extraction = Thyra::TpetraOperatorVectorExtraction<double>;

ModelEvaluator::ModelEvaluator(RCP<NonlinearProblem> problem,
                               RCP<const NonlinearProblem::Vector> scale,
                               RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> W_factory,
                               RCP<JacobianReuse> reuse, RCP<FreeMotionPins> pins)
    : problem_(std::move(problem)), scale_(std::move(scale)), W_factory_(std::move(W_factory)),
      reuse_(reuse.assert_not_null()), pins_(std::move(pins)),
      space_(Thyra::createVectorSpace<double>(problem_->solution_map()))
{
  if (!scale_.is_null())
    x_unscaled_ = Teuchos::rcp(new NonlinearProblem::Vector(problem_->solution_map()));
  MEB::InArgsSetup<double> in_args;
  in_args.setModelEvalDescription(description());
  in_args.setSupports(MEB::IN_ARG_x);
  nominal_values_ = in_args;
  const RCP<Thyra::VectorBase<double>> x0 = Thyra::createMember(space_);
  Thyra::assign(x0.ptr(), 0.0);
  nominal_values_.set_x(x0);
  reuse_->set_jacobian_with([this](const std::vector<double> &smooth)
                            { return jacobian_with(smooth); });
}

bool ModelEvaluator::jacobian_with(const std::vector<double> &smooth) const
{
  if (x_origin_.is_null() || J_origin_.is_null() ||
      !problem_->jacobian_with(smooth, *x_origin_, *J_origin_))
    return false;
  scale_jacobian(*J_origin_);
  return true;
}

void ModelEvaluator::scale_jacobian(NonlinearProblem::Matrix &J) const
{
  if (!scale_.is_null())
  {
    J.leftScale(*scale_);
    J.rightScale(*scale_);
  }
  if (!pins_.is_null())
    pins_->pin(J);
}

RCP<const Thyra::VectorSpaceBase<double>> ModelEvaluator::get_x_space() const
{
  return space_;
}
RCP<const Thyra::VectorSpaceBase<double>> ModelEvaluator::get_f_space() const
{
  return space_;
}
MEB::InArgs<double> ModelEvaluator::getNominalValues() const
{
  return nominal_values_;
}

MEB::InArgs<double> ModelEvaluator::createInArgs() const
{
  MEB::InArgsSetup<double> in_args;
  in_args.setModelEvalDescription(description());
  in_args.setSupports(MEB::IN_ARG_x);
  return std::move(in_args);
}

MEB::OutArgs<double> ModelEvaluator::createOutArgsImpl() const
{
  MEB::OutArgsSetup<double> out_args;
  out_args.setModelEvalDescription(description());
  out_args.setSupports(MEB::OUT_ARG_f);
  out_args.setSupports(MEB::OUT_ARG_W_op);
  return std::move(out_args);
}

RCP<Thyra::LinearOpBase<double>> ModelEvaluator::create_W_op() const
{
  const RCP<const NonlinearProblem::Graph> graph = problem_->jacobian_graph();
  KILN_ASSERT(graph->isFillComplete(), "the Jacobian graph must be fill-complete");
  const auto J = Teuchos::rcp(new NonlinearProblem::Matrix(graph));
  J->fillComplete(graph->getDomainMap(), graph->getRangeMap());
  return Thyra::tpetraLinearOp<double>(Thyra::createVectorSpace<double>(J->getRangeMap()),
                                       Thyra::createVectorSpace<double>(J->getDomainMap()),
                                       Teuchos::rcp_implicit_cast<Tpetra::Operator<>>(J));
}

RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> ModelEvaluator::get_W_factory() const
{
  return W_factory_;
}

void ModelEvaluator::evalModelImpl(const MEB::InArgs<double> &in_args,
                                   const MEB::OutArgs<double> &out_args) const
{
  const RCP<const NonlinearProblem::Vector> x =
      Extraction::getConstTpetraVector(in_args.get_x().assert_not_null());
  const RCP<Thyra::VectorBase<double>> f_thyra = out_args.get_f();
  const RCP<Thyra::LinearOpBase<double>> W_thyra = out_args.get_W_op();
  RCP<NonlinearProblem::Vector> f;
  if (!f_thyra.is_null())
    f = Extraction::getTpetraVector(f_thyra);
  RCP<NonlinearProblem::Matrix> J;
  if (!W_thyra.is_null())
    J = Teuchos::rcp_dynamic_cast<NonlinearProblem::Matrix>(Extraction::getTpetraOperator(W_thyra),
                                                            true);
  if (!scale_.is_null())
    x_unscaled_->elementWiseMultiply(1.0, *scale_, *x, 0.0);
  const NonlinearProblem::Vector &x_problem = scale_.is_null() ? *x : *x_unscaled_;
  if (!J.is_null() && reuse_->can_keep(*problem_, x_problem, *J))
  {
    problem_->jacobian_kept(x_problem);
    J = Teuchos::null;
  }
  if (!f.is_null() || !J.is_null())
    evaluate_collectively(*problem_, x_problem, f.get(), J.get());
  if (!J.is_null() && reuse_->restoring())
  {
    x_origin_ = Teuchos::rcp(new NonlinearProblem::Vector(x_problem, Teuchos::Copy));
    J_origin_ = J;
  }
  if (!J.is_null())
  {
    scale_jacobian(*J);
    reuse_->evaluated(*J, problem_->smooth_dependencies());
  }
  if (!f.is_null() && !scale_.is_null())
    f->elementWiseMultiply(1.0, *scale_, *f, 0.0);
  if (!f.is_null() && !pins_.is_null())
    pins_->residual(*f);
  if (!f.is_null())
    reuse_->residual_evaluated(f->norm2());
}
} // namespace internal
} // namespace kiln
