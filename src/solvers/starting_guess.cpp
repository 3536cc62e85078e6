#include "solvers/starting_guess.hpp"

#include "base/errors.hpp"

#include <Thyra_LinearOpWithSolveBase.hpp>
#include <Thyra_MultiVectorStdOps.hpp>
#include <Thyra_VectorStdOps.hpp>

#include <utility>

namespace kiln
{
namespace internal
{
namespace
{
using Teuchos::Ptr;
using Teuchos::RCP;

/// The inner solve, started from the pending guess when that leaves the smaller residual.
class StartingGuessSolve final : public Thyra::LinearOpWithSolveBase<double>
{
public:
  StartingGuessSolve(RCP<Thyra::LinearOpWithSolveBase<double>> inner, RCP<StartingGuess> guess)
      : inner_(std::move(inner)), guess_(std::move(guess))
  {
  }
  Thyra::LinearOpWithSolveBase<double> &inner() const { return *inner_; }

  RCP<const Thyra::VectorSpaceBase<double>> range() const override { return inner_->range(); }
  RCP<const Thyra::VectorSpaceBase<double>> domain() const override { return inner_->domain(); }

protected:
  bool opSupportedImpl(Thyra::EOpTransp transp) const override
  {
    return inner_->opSupported(transp);
  }
  void applyImpl(Thyra::EOpTransp transp, const Thyra::MultiVectorBase<double> &X,
                 const Ptr<Thyra::MultiVectorBase<double>> &Y, double alpha,
                 double beta) const override
  {
    inner_->apply(transp, X, Y, alpha, beta);
  }
  bool solveSupportsImpl(Thyra::EOpTransp transp) const override
  {
    return inner_->solveSupports(transp);
  }
  bool solveSupportsSolveMeasureTypeImpl(Thyra::EOpTransp transp,
                                         const Thyra::SolveMeasureType &type) const override
  {
    return inner_->solveSupportsSolveMeasureType(transp, type);
  }
  Thyra::SolveStatus<double>
  solveImpl(Thyra::EOpTransp transp, const Thyra::MultiVectorBase<double> &B,
            const Ptr<Thyra::MultiVectorBase<double>> &X,
            const Ptr<const Thyra::SolveCriteria<double>> criteria) const override
  {
    const RCP<const Thyra::VectorBase<double>> g = guess_->take();
    if (!g.is_null() && transp == Thyra::NOTRANS && B.domain()->dim() == 1)
    {
      // r = B - A g: the guess is used if it leaves less than B (the residual of zero).
      const RCP<Thyra::MultiVectorBase<double>> r = B.clone_mv();
      inner_->apply(Thyra::NOTRANS, *g, r.ptr(), -1.0, 1.0);
      if (Thyra::norm_2(*r->col(0)) < Thyra::norm_2(*B.col(0)))
      {
        Thyra::assign(X->col(0).ptr(), *g);
        ++guess_->used;
      }
      else
        ++guess_->declined;
    }
    const Thyra::SolveStatus<double> status = inner_->solve(transp, B, X, criteria);
    if (status.solveStatus == Thyra::SOLVE_STATUS_UNCONVERGED)
      ++guess_->unconverged;
    return status;
  }

private:
  RCP<Thyra::LinearOpWithSolveBase<double>> inner_;
  RCP<StartingGuess> guess_;
};

/// The wrapper's inner solve (an exception if `op` is not one of this factory's).
Thyra::LinearOpWithSolveBase<double> &inner_of(Thyra::LinearOpWithSolveBase<double> *op)
{
  auto *wrapper = dynamic_cast<StartingGuessSolve *>(op);
  KILN_ASSERT(wrapper != nullptr, "StartingGuessSolveFactory: not one of its solves");
  return wrapper->inner();
}
} // namespace

StartingGuessSolveFactory::StartingGuessSolveFactory(RCP<Base> inner, RCP<StartingGuess> guess)
    : inner_(inner.assert_not_null()), guess_(guess.assert_not_null())
{
}

void StartingGuessSolveFactory::setParameterList(const RCP<Teuchos::ParameterList> &list)
{
  inner_->setParameterList(list);
}
RCP<Teuchos::ParameterList> StartingGuessSolveFactory::getNonconstParameterList()
{
  return inner_->getNonconstParameterList();
}
RCP<Teuchos::ParameterList> StartingGuessSolveFactory::unsetParameterList()
{
  return inner_->unsetParameterList();
}
RCP<const Teuchos::ParameterList> StartingGuessSolveFactory::getParameterList() const
{
  return inner_->getParameterList();
}
RCP<const Teuchos::ParameterList> StartingGuessSolveFactory::getValidParameters() const
{
  return inner_->getValidParameters();
}
std::string StartingGuessSolveFactory::description() const
{
  return "kiln::StartingGuessSolveFactory{" + inner_->description() + "}";
}

bool StartingGuessSolveFactory::acceptsPreconditionerFactory() const
{
  return inner_->acceptsPreconditionerFactory();
}
void StartingGuessSolveFactory::setPreconditionerFactory(
    const RCP<Thyra::PreconditionerFactoryBase<double>> &factory, const std::string &name)
{
  inner_->setPreconditionerFactory(factory, name);
}
RCP<Thyra::PreconditionerFactoryBase<double>>
StartingGuessSolveFactory::getPreconditionerFactory() const
{
  return inner_->getPreconditionerFactory();
}
void StartingGuessSolveFactory::unsetPreconditionerFactory(
    RCP<Thyra::PreconditionerFactoryBase<double>> *factory, std::string *name)
{
  inner_->unsetPreconditionerFactory(factory, name);
}
bool StartingGuessSolveFactory::isCompatible(const Thyra::LinearOpSourceBase<double> &source) const
{
  return inner_->isCompatible(source);
}
RCP<Thyra::LinearOpWithSolveBase<double>> StartingGuessSolveFactory::createOp() const
{
  return Teuchos::rcp(new StartingGuessSolve(inner_->createOp(), guess_));
}
void StartingGuessSolveFactory::initializeOp(
    const RCP<const Thyra::LinearOpSourceBase<double>> &source,
    Thyra::LinearOpWithSolveBase<double> *op, const Thyra::ESupportSolveUse use) const
{
  inner_->initializeOp(source, &inner_of(op), use);
}
void StartingGuessSolveFactory::initializeAndReuseOp(
    const RCP<const Thyra::LinearOpSourceBase<double>> &source,
    Thyra::LinearOpWithSolveBase<double> *op) const
{
  inner_->initializeAndReuseOp(source, &inner_of(op));
}
void StartingGuessSolveFactory::uninitializeOp(
    Thyra::LinearOpWithSolveBase<double> *op, RCP<const Thyra::LinearOpSourceBase<double>> *source,
    RCP<const Thyra::PreconditionerBase<double>> *prec,
    RCP<const Thyra::LinearOpSourceBase<double>> *approx_source, Thyra::ESupportSolveUse *use) const
{
  inner_->uninitializeOp(&inner_of(op), source, prec, approx_source, use);
}
bool StartingGuessSolveFactory::supportsPreconditionerInputType(
    const Thyra::EPreconditionerInputType type) const
{
  return inner_->supportsPreconditionerInputType(type);
}
void StartingGuessSolveFactory::initializePreconditionedOp(
    const RCP<const Thyra::LinearOpSourceBase<double>> &source,
    const RCP<const Thyra::PreconditionerBase<double>> &prec,
    Thyra::LinearOpWithSolveBase<double> *op, const Thyra::ESupportSolveUse use) const
{
  inner_->initializePreconditionedOp(source, prec, &inner_of(op), use);
}
void StartingGuessSolveFactory::initializeApproxPreconditionedOp(
    const RCP<const Thyra::LinearOpSourceBase<double>> &source,
    const RCP<const Thyra::LinearOpSourceBase<double>> &approx_source,
    Thyra::LinearOpWithSolveBase<double> *op, const Thyra::ESupportSolveUse use) const
{
  inner_->initializeApproxPreconditionedOp(source, approx_source, &inner_of(op), use);
}
} // namespace internal
} // namespace kiln
