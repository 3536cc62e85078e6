#pragma once
/// Private to src/solvers: a starting vector for the next Krylov solve. NOX zeroes the
/// solution vector before every linear solve; a time step of a problem that changes smoothly
/// knows better: its first Newton step is close to the step extrapolated from the last ones
/// (TimeStepper). StartingGuessSolveFactory wraps the Stratimikos linear solver factory so
/// that the next solve starts from a guess handed to a StartingGuess, if the guess leaves a
/// smaller residual than zero does (doc/solvers.md, "The first Krylov solve of a step").
#include <Teuchos_RCP.hpp>
#include <Thyra_LinearOpWithSolveFactoryBase.hpp>
#include <Thyra_VectorBase.hpp>

#include <string>

namespace kiln
{
namespace internal
{
/// The guess for the next solve, taken by it (set by NewtonSolver, read by the solves of
/// StartingGuessSolveFactory).
class StartingGuess
{
public:
  /// The next solve of J X = B starts from `guess`, in the solver's (scaled) unknowns.
  void set(Teuchos::RCP<const Thyra::VectorBase<double>> guess) { guess_ = std::move(guess); }
  /// Forgets a guess no solve took.
  void clear() { guess_ = Teuchos::null; }
  /// The pending guess, now forgotten (null if none).
  Teuchos::RCP<const Thyra::VectorBase<double>> take()
  {
    auto g = guess_;
    guess_ = Teuchos::null;
    return g;
  }
  /// Solves that started from a guess, and that were offered one and started from zero
  /// (the guess left a larger residual).
  int used = 0;
  int declined = 0;
  /// Solves (of StartingGuessSolveFactory, with or without a guess) that stopped short of
  /// their tolerance (Belos at its iteration limit): NOX goes on with their step ("Rescue Bad
  /// Newton Solve", with a warning), the Newton test on ||F|| decides; NewtonSolver counts
  /// them per solve.
  int unconverged = 0;

private:
  Teuchos::RCP<const Thyra::VectorBase<double>> guess_;
};

/// A linear solver factory that does what `inner` does, except that the first solve after
/// StartingGuess::set starts from the guess when ||B - A g|| < ||B||, else from zero (as
/// NOX asks). The solve's tolerance is measured as the inner solver measures it: relative
/// to ||B|| with Kiln's adaptive tolerance, so that a better start means fewer iterations.
class StartingGuessSolveFactory final : public Thyra::LinearOpWithSolveFactoryBase<double>
{
public:
  using Base = Thyra::LinearOpWithSolveFactoryBase<double>;
  StartingGuessSolveFactory(Teuchos::RCP<Base> inner, Teuchos::RCP<StartingGuess> guess);

  // ParameterListAcceptor: the inner factory's list.
  void setParameterList(const Teuchos::RCP<Teuchos::ParameterList> &list) override;
  Teuchos::RCP<Teuchos::ParameterList> getNonconstParameterList() override;
  Teuchos::RCP<Teuchos::ParameterList> unsetParameterList() override;
  Teuchos::RCP<const Teuchos::ParameterList> getParameterList() const override;
  Teuchos::RCP<const Teuchos::ParameterList> getValidParameters() const override;
  std::string description() const override;

  // LinearOpWithSolveFactoryBase: the inner factory's, on the inner solve of the wrapper.
  bool acceptsPreconditionerFactory() const override;
  void
  setPreconditionerFactory(const Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>> &factory,
                           const std::string &name) override;
  Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>> getPreconditionerFactory() const override;
  void unsetPreconditionerFactory(Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>> *factory,
                                  std::string *name) override;
  bool isCompatible(const Thyra::LinearOpSourceBase<double> &source) const override;
  Teuchos::RCP<Thyra::LinearOpWithSolveBase<double>> createOp() const override;
  void initializeOp(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> &source,
                    Thyra::LinearOpWithSolveBase<double> *op,
                    Thyra::ESupportSolveUse use) const override;
  void initializeAndReuseOp(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> &source,
                            Thyra::LinearOpWithSolveBase<double> *op) const override;
  void uninitializeOp(Thyra::LinearOpWithSolveBase<double> *op,
                      Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> *source,
                      Teuchos::RCP<const Thyra::PreconditionerBase<double>> *prec,
                      Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> *approx_source,
                      Thyra::ESupportSolveUse *use) const override;
  bool supportsPreconditionerInputType(Thyra::EPreconditionerInputType type) const override;
  void
  initializePreconditionedOp(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> &source,
                             const Teuchos::RCP<const Thyra::PreconditionerBase<double>> &prec,
                             Thyra::LinearOpWithSolveBase<double> *op,
                             Thyra::ESupportSolveUse use) const override;
  void initializeApproxPreconditionedOp(
      const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> &source,
      const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> &approx_source,
      Thyra::LinearOpWithSolveBase<double> *op, Thyra::ESupportSolveUse use) const override;

private:
  Teuchos::RCP<Base> inner_;
  Teuchos::RCP<StartingGuess> guess_;
};
} // namespace internal
} // namespace kiln
