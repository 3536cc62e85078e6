#include "solvers/crs_preconditioner_factory.hpp"

#include <Thyra_DefaultPreconditioner.hpp>
#include <Thyra_TpetraLinearOp.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_CrsMatrix.hpp>

namespace kiln
{
namespace internal
{
using Teuchos::ParameterList;
using Teuchos::RCP;
using Teuchos::rcp;
using Map = Tpetra::Map<>;
using LO = Map::local_ordinal_type;
using GO = Map::global_ordinal_type;
using Node = Map::node_type;

bool CrsPreconditionerFactory::isCompatible(const Thyra::LinearOpSourceBase<double> &fwdOpSrc) const
{
  return !crs_matrix(fwdOpSrc, false).is_null();
}

RCP<Thyra::PreconditionerBase<double>> CrsPreconditionerFactory::createPrec() const
{
  return rcp(new Thyra::DefaultPreconditioner<double>);
}

void CrsPreconditionerFactory::uninitializePrec(
    Thyra::PreconditionerBase<double> *prec, RCP<const Thyra::LinearOpSourceBase<double>> *fwdOpSrc,
    Thyra::ESupportSolveUse *supportSolveUse) const
{
  if (fwdOpSrc != nullptr)
    *fwdOpSrc = Teuchos::null;
  if (supportSolveUse != nullptr)
    *supportSolveUse = Thyra::SUPPORT_SOLVE_UNSPECIFIED;
  if (prec != nullptr)
    dynamic_cast<Thyra::DefaultPreconditioner<double> &>(*prec).uninitialize();
}

void CrsPreconditionerFactory::setParameterList(const RCP<ParameterList> &paramList)
{
  paramList->validateParametersAndSetDefaults(*getValidParameters(), 0);
  params_ = paramList;
  parameters_changed();
}

RCP<ParameterList> CrsPreconditionerFactory::getNonconstParameterList()
{
  if (params_.is_null())
    params_ = rcp(new ParameterList(*getValidParameters()));
  parameters_changed(); // the caller may change the list
  return params_;
}

RCP<ParameterList> CrsPreconditionerFactory::unsetParameterList()
{
  RCP<ParameterList> old = params_;
  params_ = Teuchos::null;
  parameters_changed();
  return old;
}

RCP<const ParameterList> CrsPreconditionerFactory::getParameterList() const
{
  if (params_.is_null())
    return getValidParameters();
  return params_;
}

RCP<const CrsPreconditionerFactory::Matrix>
CrsPreconditionerFactory::crs_matrix(const Thyra::LinearOpSourceBase<double> &source,
                                     const bool required)
{
  return Teuchos::rcp_dynamic_cast<const Matrix>(
      Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>::getConstTpetraOperator(
          source.getOp()),
      required);
}

void CrsPreconditionerFactory::set_operator(Thyra::PreconditionerBase<double> &prec,
                                            const Matrix &J,
                                            const RCP<Tpetra::Operator<double>> &op)
{
  const RCP<const Thyra::LinearOpBase<double>> thyra_op =
      Thyra::tpetraLinearOp<double, LO, GO, Node>(
          Thyra::tpetraVectorSpace<double>(J.getRangeMap()),
          Thyra::tpetraVectorSpace<double>(J.getDomainMap()), op);
  dynamic_cast<Thyra::DefaultPreconditioner<double> &>(prec).initializeUnspecified(thyra_op);
}
} // namespace internal
} // namespace kiln
