#pragma once
/// Private to src/solvers: the preconditioner "Direct" for small problems: the sparse LU
/// factors of J (Amesos2's KLU2), J gathered onto rank 0 and factored there. Applying it
/// gathers the vector onto rank 0, solves there and scatters the solution back, so the
/// Krylov solver converges in one or two iterations on any number of ranks, where a
/// multigrid set-up and V-cycle cost more than the whole factorization (doc/solvers.md,
/// "Small problems: Direct"). The factorization runs on one rank because Debian's Amesos2
/// 13.2 returns wrong answers for a matrix distributed over more (the shared notes).
#include <Teuchos_ParameterList.hpp>
#include <Thyra_PreconditionerFactoryBase.hpp>

#include <memory>

namespace kiln
{
namespace internal
{
/// Up to this many unknowns Direct is the default Preconditioner Type, unless the input
/// names one or gives a "MueLu" or "Block Triangular" sublist (doc/solvers.md).
constexpr long long direct_up_to = 2000;

class DirectPreconditionerFactory final : public Thyra::PreconditionerFactoryBase<double>
{
public:
  DirectPreconditionerFactory();
  ~DirectPreconditionerFactory() override;

  bool isCompatible(const Thyra::LinearOpSourceBase<double> &fwdOpSrc) const override;
  Teuchos::RCP<Thyra::PreconditionerBase<double>> createPrec() const override;
  /// Gathers J onto rank 0 and factors it there; the gather's maps are made anew only for a
  /// new graph of J. Collective.
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

  /// How many factorizations initializePrec() has made.
  int factorizations() const { return factorizations_; }

  /// The gather and the factors of one initializePrec(), kept by the operator it made.
  struct Factors;

private:
  mutable std::shared_ptr<Factors> factors_; ///< shared with the operators it made
  mutable int factorizations_ = 0;
  Teuchos::RCP<Teuchos::ParameterList> params_;
};
} // namespace internal
} // namespace kiln
