#pragma once
/// Newton's method by NOX on Tpetra objects, through Thyra (a model evaluator
/// over the NonlinearProblem) and Stratimikos: Belos Krylov solvers with MueLu
/// (or Ifpack2) preconditioning. The "Nonlinear Solver" and "Linear Solver"
/// sublists of the input are handed to NOX and Stratimikos as they are, so
/// every option those packages document can be set from the XML.
#include "discretization/nonlinear_problem.hpp"

#include <Teuchos_FancyOStream.hpp>
#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <string>
#include <vector>

namespace kiln
{
class NewtonSolver
{
public:
  /// "Nonlinear Solver" (NOX, default: Line Search Based Newton with a full
  /// step, convergence when ||F|| <= "Absolute Tolerance" or
  /// ||F|| <= "Relative Tolerance" * ||F(x0)|| , at most "Maximum Iterations")
  /// and "Linear Solver" (Stratimikos; default: Belos flexible Block GMRES with
  /// MueLu, with a coarse solver that works on more than one rank in
  /// Debian's Trilinos 13.2), each with documented defaults.
  static Teuchos::ParameterList valid_parameters();

  /// `params` is the validated "Solver" block; `where` names it in messages ("in.xml:
  /// Kiln/Solver"). The package sublists are checked here (solver_parameter_checks.hpp).
  NewtonSolver(const Teuchos::ParameterList &params, Teuchos::RCP<NonlinearProblem> problem,
               Teuchos::RCP<Teuchos::FancyOStream> out, const std::string &where = "Solver");
  ~NewtonSolver();

  struct Result
  {
    bool converged = false;
    int newton_iterations = 0;
    int linear_iterations = 0; ///< summed over the Newton iterations
    /// Linear solves that stopped short of their tolerance (NOX warns of each and goes on
    /// with its step; the Newton test decides).
    int linear_failures = 0;
    /// The solve stopped as ||F|| grew a millionfold after linear solves short of their
    /// tolerance (internal::LinearFailureDivergence): the preconditioner does not solve J.
    bool linear_divergence = false;
    double initial_residual_norm = 0.0;
    double final_residual_norm = 0.0;
    /// Jacobians evaluated or kept (Solver/"Reuse"), preconditioners built or kept.
    int jacobians_evaluated = 0;
    int jacobians_kept = 0;
    int preconditioners_built = 0;
    int preconditioners_kept = 0;
    /// The ||F|| that counts as converged: max("Absolute Tolerance", "Relative Tolerance"
    /// * initial_residual_norm).
    double tolerance = 0.0;
    /// Not empty: the solve ended unconverged because an evaluation threw a StepFailure
    /// (base/errors.hpp; on every rank alike), its message; x is then the initial guess.
    std::string step_failure;
  };

  /// Solves F(x) = 0 from the initial guess in x; x holds the last iterate on
  /// return (converged or not). With `first_step`, a guess of the first Newton step, the
  /// first Krylov solve starts from it instead of zero if that leaves the smaller residual
  /// (the same answer to the Krylov tolerance). A StepFailure in an evaluation ends the solve
  /// unconverged (Result::step_failure), with the kept Jacobian and preconditioner forgotten.
  /// Collective.
  /// With `start_at_first_step` (and a first_step), Newton starts at x + first_step instead
  /// (a predictor), its relative tolerance still that of ||F(x)||, and the Krylov solves
  /// start from zero.
  Result solve(NonlinearProblem::Vector &x, const NonlinearProblem::Vector *first_step = nullptr,
               bool start_at_first_step = false);
  /// Whether the problem's Jacobian varies with the state on some rank (a viscoplastic
  /// model, a property of T: NonlinearProblem::jacobian_varies()), from the problem alone, so
  /// that a run restarted before its first solve answers as the run it continues.
  /// Collective.
  bool jacobian_varies() const;
  /// "Maximum Iterations" of the input.
  int max_iterations() const;
  /// The linear solver's Preconditioner Type as used ("MueLu", "Block Triangular", ...: the
  /// input's, or the one Kiln picked), for the log.
  const std::string &preconditioner() const;

  /// With a "Preconditioner Reuse Tolerance": what a checkpoint keeps so that a run restarted
  /// from it on as many ranks builds its first preconditioner from the Jacobian this run
  /// built the preconditioner it keeps from, and so goes on exactly as this run would
  /// (this rank's record; empty if there is nothing to keep).
  std::vector<double> preconditioner_origin() const;
  /// A record of preconditioner_origin() from a checkpoint, before the first solve.
  void restore_preconditioner_origin(std::vector<double> record);
  /// The run reached a point it can be restarted from (a checkpoint written, a stop time):
  /// a preconditioner kept across steps (Keep Preconditioner Across Steps) is given up, so
  /// that the next solve builds its own as a run restarted from here does (bit-identical
  /// continuation). Call alike on every rank.
  void restart_point();

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
} // namespace kiln
