#include "solvers/jacobian_reuse.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <algorithm>

namespace kiln
{
namespace internal
{
using Teuchos::RCP;

bool JacobianReuse::can_keep(NonlinearProblem &problem, const NonlinearProblem::Vector &x,
                             const NonlinearProblem::Matrix &J)
{
  if (!enabled_)
    return false;
  pending_ = problem.jacobian_dependencies(x);
  const int same_here = !pending_.empty() && &J == matrix_ && pending_ == dependencies_ ? 1 : 0;
  int same = 0;
  Teuchos::reduceAll(*J.getComm(), Teuchos::REDUCE_MIN, same_here, Teuchos::outArg(same));
  if (same == 1)
    ++counts_.jacobians_kept;
  return same == 1;
}

void JacobianReuse::evaluated(const NonlinearProblem::Matrix &J, const std::size_t smooth)
{
  const bool same_matrix = &J == matrix_;
  matrix_ = &J;
  dependencies_ = std::move(pending_);
  pending_.clear();
  ++counts_.jacobians_evaluated;
  if (enabled_ && tolerance_ > 0.0 && same_matrix)
  {
    const int serves_here = serves(version_dependencies_, dependencies_, smooth) ? 1 : 0;
    int served = 0;
    Teuchos::reduceAll(*J.getComm(), Teuchos::REDUCE_MIN, serves_here, Teuchos::outArg(served));
    if (served == 1)
      return;
  }
  version_dependencies_ = dependencies_;
  ++version_;
}

bool JacobianReuse::serves(const std::vector<double> &built, const std::vector<double> &now,
                           const std::size_t smooth) const
{
  if (built.empty() || built.size() != now.size() || smooth > now.size())
    return false;
  // Each coefficient within a factor 1 + tolerance of its value at the build, either way.
  for (std::size_t i = 0; i < smooth; ++i)
    if (now[i] != built[i] && !(now[i] * built[i] > 0.0 &&
                                std::max(now[i] / built[i], built[i] / now[i]) <= 1.0 + tolerance_))
      return false;
  return std::equal(built.begin() + smooth, built.end(), now.begin() + smooth);
}

ReusingPreconditionerFactory::ReusingPreconditionerFactory(
    RCP<Thyra::PreconditionerFactoryBase<double>> factory, RCP<JacobianReuse> reuse)
    : factory_(factory.assert_not_null()), reuse_(reuse.assert_not_null())
{
}

bool ReusingPreconditionerFactory::isCompatible(
    const Thyra::LinearOpSourceBase<double> &fwdOpSrc) const
{
  return factory_->isCompatible(fwdOpSrc);
}

RCP<Thyra::PreconditionerBase<double>> ReusingPreconditionerFactory::createPrec() const
{
  return factory_->createPrec();
}

void ReusingPreconditionerFactory::initializePrec(
    const RCP<const Thyra::LinearOpSourceBase<double>> &fwdOpSrc,
    Thyra::PreconditionerBase<double> *precOp, const Thyra::ESupportSolveUse supportSolveUse) const
{
  const Thyra::LinearOpBase<double> *op = fwdOpSrc->getOp().get();
  if (reuse_->enabled() && precOp == built_.prec && op == built_.op &&
      reuse_->version() == built_.version)
  {
    ++reuse_->counts().preconditioners_kept;
    return;
  }
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Kiln: 7 preconditioner set-up"));
  factory_->initializePrec(fwdOpSrc, precOp, supportSolveUse);
  built_ = {precOp, op, reuse_->version()};
  ++reuse_->counts().preconditioners_built;
}

void ReusingPreconditionerFactory::uninitializePrec(
    Thyra::PreconditionerBase<double> *prec, RCP<const Thyra::LinearOpSourceBase<double>> *fwdOpSrc,
    Thyra::ESupportSolveUse *supportSolveUse) const
{
  if (prec == built_.prec)
    built_ = {};
  factory_->uninitializePrec(prec, fwdOpSrc, supportSolveUse);
}

void ReusingPreconditionerFactory::setParameterList(const RCP<Teuchos::ParameterList> &paramList)
{
  factory_->setParameterList(paramList);
}
RCP<Teuchos::ParameterList> ReusingPreconditionerFactory::getNonconstParameterList()
{
  return factory_->getNonconstParameterList();
}
RCP<Teuchos::ParameterList> ReusingPreconditionerFactory::unsetParameterList()
{
  return factory_->unsetParameterList();
}
RCP<const Teuchos::ParameterList> ReusingPreconditionerFactory::getParameterList() const
{
  return factory_->getParameterList();
}
RCP<const Teuchos::ParameterList> ReusingPreconditionerFactory::getValidParameters() const
{
  return factory_->getValidParameters();
}
} // namespace internal
} // namespace kiln
