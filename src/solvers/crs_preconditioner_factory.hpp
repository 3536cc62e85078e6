#pragma once
/// Private to src/solvers: what Kiln's own preconditioner factories (Block Triangular,
/// Direct) share as Thyra factories of preconditioners for a Tpetra CrsMatrix: the matrix
/// behind the operator, the DefaultPreconditioner they fill with a Tpetra operator, and the
/// parameter list, validated against the factory's valid list. A factory adds
/// initializePrec() and getValidParameters().
#include <Teuchos_ParameterList.hpp>
#include <Thyra_PreconditionerFactoryBase.hpp>
#include <Tpetra_CrsMatrix_fwd.hpp>
#include <Tpetra_Operator.hpp>

namespace kiln
{
namespace internal
{
class CrsPreconditionerFactory : public Thyra::PreconditionerFactoryBase<double>
{
public:
  using Matrix = Tpetra::CrsMatrix<double>;

  /// Whether the operator is a Tpetra CrsMatrix.
  bool isCompatible(const Thyra::LinearOpSourceBase<double> &fwdOpSrc) const override;
  Teuchos::RCP<Thyra::PreconditionerBase<double>> createPrec() const override;
  void uninitializePrec(Thyra::PreconditionerBase<double> *prec,
                        Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> *fwdOpSrc,
                        Thyra::ESupportSolveUse *supportSolveUse) const override;

  void setParameterList(const Teuchos::RCP<Teuchos::ParameterList> &paramList) override;
  Teuchos::RCP<Teuchos::ParameterList> getNonconstParameterList() override;
  Teuchos::RCP<Teuchos::ParameterList> unsetParameterList() override;
  /// The list set, or the valid list (the defaults) if none is.
  Teuchos::RCP<const Teuchos::ParameterList> getParameterList() const override;

protected:
  /// The Tpetra matrix behind a Thyra operator source: null if it is none, or an exception
  /// with `required`.
  static Teuchos::RCP<const Matrix> crs_matrix(const Thyra::LinearOpSourceBase<double> &source,
                                               bool required);
  /// Makes `prec` (one of createPrec()) apply `op`, whose maps are J's.
  static void set_operator(Thyra::PreconditionerBase<double> &prec, const Matrix &J,
                           const Teuchos::RCP<Tpetra::Operator<double>> &op);
  /// The list was set, handed out for changes or unset.
  virtual void parameters_changed() {}

private:
  Teuchos::RCP<Teuchos::ParameterList> params_;
};
} // namespace internal
} // namespace kiln
