#pragma once
/// Private to src/solvers: the package sublists of the "Solver" block checked before the
/// packages read them, so that a misspelled name or a wrong type is one input error at
/// kiln --check and at the start of a run. Belos (through Stratimikos) and NOX read the names
/// they know and ignore the others: a misspelled "Convergence Tolerence" or line search
/// "Methd" would otherwise change nothing, without a word. They also read only the sublist of
/// the chosen type ("Solver Type", "Preconditioner Type", a line search's "Method"): one the
/// input fills for another type is refused as well (Kiln's defaults do not count).
///
/// Where the valid names come from:
/// - Belos: the valid list Stratimikos builds from every Belos solver manager's
///   getValidParameters() (Thyra::BelosLinearOpWithSolveFactory); Stratimikos itself checks
///   only the first two levels of it;
/// - MueLu: MueLu::ParameterListInterpreter, which checks its list when it is built;
/// - NOX 13.2: "Solver Options" has a validator in NOX (NOX::Solver::
///   validateSolverOptionsSublist), and so do the "Safeguarded Step" and "Safeguarded
///   Direction" line searches and the "Pseudo-Transient" solver, which NOX builds only
///   from objects an input cannot give (an "Update Limit Vector") or checks itself; the
///   other sublists have none, and their known names are written out in
///   nox_known_parameters() (nox_parameter_names.hpp).
#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>

#include <string>

namespace kiln
{
namespace internal
{
/// Checks the package sublists of the validated "Solver" block `solver`: "Linear Solver"
/// as Kiln hands it to Stratimikos (`stratimikos`, with Kiln's additions) against
/// `stratimikos_valid` (DefaultLinearSolverBuilder::getValidParameters()), MueLu's list
/// by MueLu, and "Nonlinear Solver" against NOX's names. `where` names the block in
/// messages ("in.xml: Kiln/Solver"). Throws the same InputError on every rank.
void check_solver_parameters(const Teuchos::ParameterList &solver,
                             const Teuchos::ParameterList &stratimikos,
                             const Teuchos::ParameterList &stratimikos_valid,
                             const Teuchos::RCP<const Teuchos::Comm<int>> &comm,
                             const std::string &where);

/// MueLu reads its list only when the first preconditioner is built; this builds MueLu's
/// interpreter now: "<where>/Preconditioner Types/MueLu: <MueLu's message>" (`where`: the
/// Stratimikos list's block). Collective.
void check_muelu_parameters(const Teuchos::ParameterList &stratimikos,
                            const Teuchos::RCP<const Teuchos::Comm<int>> &comm,
                            const std::string &where);

/// The Stratimikos list's names and types at its first level, the names of its "Linear Solver
/// Types" and the whole "Belos" sublist, against `valid`. The preconditioners' sublists are
/// left to MueLu (check_muelu_parameters) and Ifpack2. `where` names the list.
void check_stratimikos_parameters(const Teuchos::ParameterList &stratimikos,
                                  const Teuchos::ParameterList &valid, const std::string &where);

/// The NOX list's names, types and main choices ("Nonlinear Solver", the line search and
/// direction "Method", "Forcing Term Method", the solve measures). `where` names the list.
void check_nox_parameters(const Teuchos::ParameterList &nox, const std::string &where);
} // namespace internal
} // namespace kiln
