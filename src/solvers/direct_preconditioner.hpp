#pragma once
/// Private to src/solvers: the preconditioner "Direct" for small problems: the sparse LU
/// factors of J (Amesos2's KLU2), J gathered onto rank 0 and factored there. Applying it
/// gathers the vector onto rank 0, solves there and scatters the solution back, so the
/// Krylov solver converges in one or two iterations on any number of ranks, where a
/// multigrid set-up and V-cycle cost more than the whole factorization (doc/solvers.md,
/// "Small problems: Direct"). The factorization runs on one rank because Debian's Amesos2
/// 13.2 returns wrong answers for a matrix distributed over more (the shared notes).
#include "solvers/crs_preconditioner_factory.hpp"

#include <memory>

namespace kiln
{
namespace internal
{
/// Up to this many unknowns Direct is the default Preconditioner Type, unless the input
/// names one or gives a "MueLu" or "Block Triangular" sublist (doc/solvers.md).
constexpr long long direct_up_to = 2000;

class DirectPreconditionerFactory final : public CrsPreconditionerFactory
{
public:
  DirectPreconditionerFactory();
  ~DirectPreconditionerFactory() override;

  /// Gathers J onto rank 0 and factors it there; the gather's maps are made anew only for a
  /// new row map of J. Collective.
  void initializePrec(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> &fwdOpSrc,
                      Thyra::PreconditionerBase<double> *precOp,
                      Thyra::ESupportSolveUse supportSolveUse) const override;
  /// No parameters.
  Teuchos::RCP<const Teuchos::ParameterList> getValidParameters() const override;

  /// How many factorizations initializePrec() has made.
  int factorizations() const { return factorizations_; }

  /// The gather and the factors of one initializePrec(), kept by the operator it made.
  struct Factors;

private:
  mutable std::shared_ptr<Factors> factors_; ///< shared with the operators it made
  mutable int factorizations_ = 0;
};
} // namespace internal
} // namespace kiln
