#include "solvers/package_parameters.hpp"

#include "base/errors.hpp"

#include <NOX_Utils.H>
#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <initializer_list>

namespace kiln
{
namespace internal
{
using Teuchos::ParameterList;
using Teuchos::RCP;

ParameterList nonlinear_solver_defaults()
{
  ParameterList p;
  p.set("Nonlinear Solver", "Line Search Based");
  p.sublist("Line Search").set("Method", "Full Step");
  ParameterList &direction = p.sublist("Direction");
  direction.set("Method", "Newton");
  ParameterList &newton = direction.sublist("Newton");
  newton.set("Forcing Term Method", "Constant");
  // A linear solve that does not converge is reported, and Newton goes on
  // with the step it got (NOX's "rescue"); the status tests decide.
  newton.set("Rescue Bad Newton Solve", true);
  // "None"/"None" makes Thyra use the Belos list's own "Convergence
  // Tolerance"; otherwise NOX's "Tolerance" (default 1e-6) would override it.
  // For an inexact Newton forcing term (Type 1, Type 2) set these to
  // "Norm Residual" and "Norm Initial Residual".
  ParameterList &linear = newton.sublist("Linear Solver");
  linear.set("Solve Measure Numerator", "None");
  linear.set("Solve Measure Denominator", "None");
  ParameterList &printing = p.sublist("Printing");
  printing.set("Output Information", NOX::Utils::Error + NOX::Utils::Warning);
  printing.set("Output Precision", 3);
  p.sublist("Solver Options").set("Status Test Check Type", "Minimal");
  return p;
}

ParameterList muelu_defaults()
{
  ParameterList p;
  p.set("verbosity", "none");
  p.set("multigrid algorithm", "sa");
  p.set("max levels", 10);
  p.set("coarse: max size", 500);
  // Weak couplings stay out of the aggregates. With the distance Laplacian below, 0.02 keeps
  // every neighbour of a node of a cube mesh (the corner ones at 0.023); with the matrix
  // values ("classical") it kept the gap conductance of fine meshes out, without which the
  // iterations grew by 70% from 16^3 to 64^3 cells on the contact box (doc/solvers.md).
  p.set("aggregation: drop tol", 0.02);
  // Drop by the distance Laplacian of MueLu's coordinates, in which the bodies a gap
  // separates lie far apart (SolverHints): no aggregate crosses the gap. With the values
  // of the matrix ("classical"), the rows of pairs in contact joined the two sides and
  // closed contact took 2.3 times the iterations of an open gap at 64^3 cells (37.0
  // against 16.0 per solve; now 16.0 both; doc/solvers.md).
  p.set("aggregation: drop scheme", "distance laplacian");
  // Smooth the prolongator with the whole matrix, not the one with the dropped entries
  // lumped into the diagonal: with the nonsymmetric rows of pairs in contact, the lumped
  // one gave a coarse level a zero diagonal (MueLu: "Prolongator damping factor needs to
  // be finite") on 3 ranks; the iteration counts are the same (doc/contact.md).
  p.set("sa: use filtered matrix", false);
  p.set("smoother: type", "RELAXATION");
  p.set("coarse: type", "RELAXATION");
  return p;
}

ParameterList linear_solver_defaults()
{
  ParameterList p;
  p.set("Linear Solver Type", "Belos");
  ParameterList &belos = p.sublist("Linear Solver Types").sublist("Belos");
  // Flexible GMRES keeps the preconditioned basis vectors, so the solution needs no further
  // application of the preconditioner, and it stops on its implicit residual without the
  // product with J that confirms it: one application and one product fewer per solve than
  // Pseudo Block GMRES, with the same iterations (a fixed preconditioner makes it right-
  // preconditioned GMRES; 32^3 contact box to 60 s, np 2: Belos 10.3 -> 9.6 s, changelog
  // 0022). Its basis is twice as large per vector: 100 restart vectors keep the memory of
  // Pseudo Block GMRES' 200; the longest solve of the 64^3 contact box to 60 s takes 32.
  belos.set("Solver Type", "Block GMRES");
  ParameterList &gmres = belos.sublist("Solver Types").sublist("Block GMRES");
  gmres.set("Convergence Tolerance", 1e-10);
  gmres.set("Maximum Iterations", 500);
  gmres.set("Num Blocks", 100);
  gmres.set("Flexible Gmres", true);
  p.set("Preconditioner Type", "MueLu");
  p.sublist("Preconditioner Types").sublist("MueLu").setParameters(muelu_defaults());
  return p;
}

bool uses_muelu(const ParameterList &stratimikos)
{
  return stratimikos.isType<std::string>("Preconditioner Type") &&
         stratimikos.get<std::string>("Preconditioner Type") == "MueLu";
}

namespace
{
/// Whether the Belos "Solver Type" of a Stratimikos list is one of `types`.
bool belos_solver_is(const ParameterList &stratimikos, std::initializer_list<const char *> types)
{
  if (!stratimikos.isSublist("Linear Solver Types") ||
      !stratimikos.sublist("Linear Solver Types").isSublist("Belos"))
    return false;
  const ParameterList &belos = stratimikos.sublist("Linear Solver Types").sublist("Belos");
  if (!belos.isType<std::string>("Solver Type"))
    return false;
  const std::string type = belos.get<std::string>("Solver Type");
  return std::any_of(types.begin(), types.end(), [&](const char *t) { return type == t; });
}
} // namespace

bool symmetric_krylov(const ParameterList &stratimikos)
{
  return belos_solver_is(stratimikos, {"Block CG", "Pseudo Block CG", "Pseudo Block Stochastic CG",
                                       "MINRES", "PCPG", "RCG"});
}

bool conjugate_gradients(const ParameterList &stratimikos)
{
  return belos_solver_is(stratimikos,
                         {"Block CG", "Pseudo Block CG", "Pseudo Block Stochastic CG", "RCG"});
}

void add_smoother_defaults(ParameterList &stratimikos)
{
  if (!uses_muelu(stratimikos))
    return;
  ParameterList &muelu = stratimikos.sublist("Preconditioner Types").sublist("MueLu");
  const auto is = [&](const std::string &name, const std::string &type)
  { return muelu.isType<std::string>(name) && muelu.get<std::string>(name) == type; };
  if (is("smoother: type", "CHEBYSHEV"))
  {
    // With Ifpack2's 10 power iterations the eigenvalue estimate can be too
    // low and the preconditioner indefinite (notes: 3D elasticity, 40^3): 30. Under CG the
    // matrix is symmetric positive definite, and 10 iterations of Ifpack2's CG (Lanczos)
    // estimate do better than 30 of the power method, in a third of the products with A
    // (doc/solvers.md). MueLu's prolongator smoothing reuses the estimate.
    ParameterList &chebyshev = muelu.sublist("smoother: params");
    chebyshev.get("chebyshev: degree", 2);
    chebyshev.get("chebyshev: ratio eigenvalue", 7.0);
    const bool spd = conjugate_gradients(stratimikos);
    if (!chebyshev.isParameter("eigen-analysis: type") &&
        !chebyshev.isParameter("chebyshev: eigenvalue max iterations"))
    {
      chebyshev.set("eigen-analysis: type", std::string(spd ? "cg" : "power method"));
      chebyshev.set("chebyshev: eigenvalue max iterations", spd ? 10 : 30);
    }
    else
      chebyshev.get("chebyshev: eigenvalue max iterations", 30);
  }
  if (is("smoother: type", "RELAXATION"))
  {
    // Forward Gauss-Seidel costs half a symmetric sweep: on the coupled problems the Krylov
    // solves take a quarter less time. On a scalar problem (heat conduction) both take the
    // same time and the symmetric one fewer iterations under refinement (doc/solvers.md);
    // CG and MINRES need the symmetric one.
    const bool scalar =
        muelu.isType<int>("number of equations") && muelu.get<int>("number of equations") == 1;
    ParameterList &relaxation = muelu.sublist("smoother: params");
    relaxation.get("relaxation: type",
                   std::string(symmetric_krylov(stratimikos) || scalar ? "Symmetric Gauss-Seidel"
                                                                       : "Gauss-Seidel"));
    relaxation.get("relaxation: sweeps", 1);
    // Across ranks Gauss-Seidel is Jacobi; l1 Gauss-Seidel adds half the magnitudes of a
    // row's off-rank entries to its diagonal where they outweigh it, which keeps those
    // updates from overshooting. One rank is unchanged. Contact box np 2, GMRES iterations:
    // 16^3 to 150 s 480 -> 462, 32^3 to 60 s 244 -> 231, 64^3 to 60 s 261 -> 242
    // (doc/solvers.md).
    relaxation.get("relaxation: use l1", true);
  }
  // The restriction of smoothed or plain aggregation is P^T: applied as a transpose, not
  // formed (32^3 contact box, np 2: the same iterations, 10% less peak memory, 6% less
  // set-up; doc/solvers.md). Petrov-Galerkin ("pg") has a restriction of its own.
  if (is("multigrid algorithm", "sa") || is("multigrid algorithm", "unsmoothed"))
    muelu.get("transpose: use implicit", true);
  // The coarse level (at most "coarse: max size" rows) is solved by 10 symmetric Gauss-Seidel
  // sweeps: with 4 it was not solved well enough, on one rank and more so on two (the sweeps
  // are Jacobi across ranks): the elastic cube took 15 instead of 14 CG iterations at N = 60
  // (np 1; np 2 16 instead of 14), the 32^3 contact box 8% more GMRES iterations at np 2.
  // 30 or 100 sweeps take the iterations of 10 (doc/solvers.md).
  if (is("coarse: type", "RELAXATION"))
  {
    ParameterList &coarse = muelu.sublist("coarse: params");
    coarse.get("relaxation: type", std::string("Symmetric Gauss-Seidel"));
    coarse.get("relaxation: sweeps", 10);
  }
}

int unknowns_per_node(const NonlinearProblem &problem, const Teuchos::Comm<int> &comm)
{
  const RCP<const Tpetra::MultiVector<double>> coordinates = problem.node_coordinates();
  if (coordinates.is_null())
    return 0;
  const auto n_rows = static_cast<long long>(problem.solution_map()->getNodeNumElements());
  const auto n_nodes = static_cast<long long>(coordinates->getLocalLength());
  long long local[2] = {n_nodes > 0 && n_rows % n_nodes == 0 ? n_rows / n_nodes : -1, 0};
  local[1] = n_nodes > 0 ? -local[0] : -1; // min and max of the ratio in one reduction
  long long global[2] = {0, 0};
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, 2, local, global);
  if (global[0] < 1 || global[0] != -global[1])
    throw InternalError("NonlinearProblem::node_coordinates(): the owned rows are not a fixed "
                        "multiple of the owned nodes on every rank");
  return static_cast<int>(global[0]);
}

void add_coordinates(ParameterList &stratimikos, const NonlinearProblem &problem,
                     const Teuchos::Comm<int> &comm, const bool near_null_space,
                     const RCP<const NonlinearProblem::Vector> &scale)
{
  const RCP<const Tpetra::MultiVector<double>> coordinates = problem.node_coordinates();
  if (coordinates.is_null() || !uses_muelu(stratimikos))
    return;
  const int unknowns = unknowns_per_node(problem, comm);
  ParameterList &muelu = stratimikos.sublist("Preconditioner Types").sublist("MueLu");
  muelu.set("Coordinates", Teuchos::rcp_const_cast<Tpetra::MultiVector<double>>(coordinates));
  if (!muelu.isParameter("number of equations"))
    muelu.set("number of equations", unknowns);
  // The near-null space, divided by the unknown scale as the solver sees it.
  if (near_null_space && !muelu.isParameter("Nullspace"))
  {
    const RCP<Tpetra::MultiVector<double>> modes = scaled_near_null_space(problem, scale);
    if (!modes.is_null())
      muelu.set("Nullspace", modes);
  }
}

RCP<Tpetra::MultiVector<double>>
scaled_near_null_space(const NonlinearProblem &problem,
                       const RCP<const NonlinearProblem::Vector> &scale)
{
  const RCP<const Tpetra::MultiVector<double>> modes = problem.near_null_space();
  if (modes.is_null())
    return Teuchos::null;
  auto scaled = Teuchos::rcp(new Tpetra::MultiVector<double>(*modes, Teuchos::Copy));
  if (!scale.is_null())
  {
    NonlinearProblem::Vector inverse(scale->getMap());
    inverse.reciprocal(*scale);
    for (std::size_t j = 0; j < scaled->getNumVectors(); ++j)
      scaled->getVectorNonConst(j)->elementWiseMultiply(1.0, inverse, *modes->getVector(j), 0.0);
  }
  return scaled;
}
} // namespace internal
} // namespace kiln
