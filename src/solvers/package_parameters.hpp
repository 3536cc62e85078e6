#pragma once
/// Private to src/solvers: Kiln's defaults for the lists NewtonSolver hands to the Trilinos
/// packages (NOX, Stratimikos with Belos and MueLu) and what it adds to them (doc/solvers.md).
/// Only light package headers in package_parameters.cpp (a few seconds of compile): the
/// check of the MueLu list needs MueLu's headers (15 s alone) and stays in newton_solver.cpp,
/// which includes them anyway.
#include "discretization/nonlinear_problem.hpp"

#include <Teuchos_ParameterList.hpp>

namespace kiln
{
namespace internal
{
/// Kiln's defaults for NOX: Newton with a full step; the Belos tolerance in
/// "Linear Solver" governs each linear solve (see linear_solver_defaults()).
Teuchos::ParameterList nonlinear_solver_defaults();

/// MueLu smoothed aggregation that works at np 1 and np > 1 in Debian's
/// Trilinos 13.2 (doc/solvers.md has the measurements): the default coarse
/// solver, Amesos2 KLU2, gives wrong answers on more than one rank, so the
/// coarsest level is smoothed instead of factored. The parameters of the
/// chosen smoother types are added by add_smoother_defaults().
Teuchos::ParameterList muelu_defaults();

/// Kiln's defaults for Stratimikos: Belos (flexible) Block GMRES preconditioned
/// by MueLu.
Teuchos::ParameterList linear_solver_defaults();

/// Whether the Stratimikos list asks for MueLu (Stratimikos checks the value).
bool uses_muelu(const Teuchos::ParameterList &stratimikos);

/// Kiln's defaults for the parameters of the smoother types and algorithm chosen, set
/// where the input gives none. They cannot be in valid_parameters(): they
/// would be merged into the input's list, where they are invalid for
/// another type (Amesos2 rejects "relaxation: type" if "coarse: type" is
/// "KLU2"; "pg" aggregation forms its own restriction, so "transpose: use
/// implicit" is set only for "sa" and "unsmoothed"). Reads MueLu's "number of
/// equations" (add_coordinates sets it): call it after add_coordinates.
void add_smoother_defaults(Teuchos::ParameterList &stratimikos);

/// Whether the Belos solver chosen in a Stratimikos list needs a symmetric preconditioner
/// (CG, MINRES and their variants): then the default relaxation is symmetric Gauss-Seidel,
/// else forward Gauss-Seidel.
bool symmetric_krylov(const Teuchos::ParameterList &stratimikos);
/// Whether the Belos solver of a Stratimikos list is a conjugate-gradient method (the
/// operator and the preconditioner symmetric positive definite): Block CG, Pseudo Block
/// CG, Pseudo Block Stochastic CG, RCG.
bool conjugate_gradients(const Teuchos::ParameterList &stratimikos);

/// The problem's unknowns per node (the same on every rank), or 0 if it gives no node
/// coordinates. Collective.
int unknowns_per_node(const NonlinearProblem &problem, const Teuchos::Comm<int> &comm);

/// Hands the problem's node coordinates (if any) to MueLu, for aggregation
/// and repartitioning; the number of unknowns per node is the ratio of owned
/// rows to owned nodes, the same on every rank. With `near_null_space`, also the
/// problem's near-null space divided by the unknown scale `scale` (if not null).
/// Collective.
void add_coordinates(Teuchos::ParameterList &stratimikos, const NonlinearProblem &problem,
                     const Teuchos::Comm<int> &comm, bool near_null_space,
                     const Teuchos::RCP<const NonlinearProblem::Vector> &scale);
/// The problem's near-null space divided by the unknown scale c (NOX's unknowns are x / c), or
/// null if the problem has none.
Teuchos::RCP<Tpetra::MultiVector<double>>
scaled_near_null_space(const NonlinearProblem &problem,
                       const Teuchos::RCP<const NonlinearProblem::Vector> &scale);
} // namespace internal
} // namespace kiln
