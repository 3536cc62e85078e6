#include "solvers/newton_solver.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "solvers/model_evaluator.hpp"

#include <MueLu_ParameterListInterpreter.hpp>
#include <NOX_SolverStats.hpp>
#include <NOX_Solver_Factory.H>
#include <NOX_Solver_Generic.H>
#include <NOX_StatusTest_Combo.H>
#include <NOX_StatusTest_FiniteValue.H>
#include <NOX_StatusTest_MaxIters.H>
#include <NOX_StatusTest_NormF.H>
#include <NOX_Thyra_Group.H>
#include <NOX_Thyra_Vector.H>
#include <NOX_Utils.H>
#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Stratimikos_MueLuHelpers.hpp>
#include <Teuchos_AbstractFactoryStd.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Thyra_Ifpack2PreconditionerFactory.hpp>
#include <Thyra_LinearSolverBuilderBase.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include <cctype>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>

namespace kiln
{
namespace internal
{
using Teuchos::ParameterList;
using Teuchos::RCP;
using Node = Tpetra::Map<>::node_type;

const std::string solver_block = "Solver";
const std::string nonlinear_name = "Nonlinear Solver";
const std::string linear_name = "Linear Solver";

/// Kiln's defaults for NOX: Newton with a full step; the Belos tolerance in
/// "Linear Solver" governs each linear solve (see linear_solver_defaults()).
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

/// MueLu smoothed aggregation that works at np 1 and np > 1 in Debian's
/// Trilinos 13.2 (doc/solvers.md has the measurements): the default coarse
/// solver, Amesos2 KLU2, gives wrong answers on more than one rank, so the
/// coarsest level is smoothed instead of factored. The parameters of the
/// chosen smoother types are added by add_smoother_defaults().
ParameterList muelu_defaults()
{
  ParameterList p;
  p.set("verbosity", "none");
  p.set("multigrid algorithm", "sa");
  p.set("max levels", 10);
  p.set("coarse: max size", 500);
  // Weak couplings (the gap conductance across a split gap on fine meshes) stay out of the
  // aggregates; without it the iterations grew by 70% from 16^3 to 64^3 cells on the
  // contact box (doc/solvers.md).
  p.set("aggregation: drop tol", 0.02);
  // Smooth the prolongator with the whole matrix, not the one with the dropped entries
  // lumped into the diagonal: with the nonsymmetric rows of pairs in contact, the lumped
  // one gave a coarse level a zero diagonal (MueLu: "Prolongator damping factor needs to
  // be finite") on 3 ranks; the iteration counts are the same (doc/contact.md).
  p.set("sa: use filtered matrix", false);
  p.set("smoother: type", "RELAXATION");
  p.set("coarse: type", "RELAXATION");
  return p;
}

/// Whether the Stratimikos list asks for MueLu (Stratimikos checks the value).
bool uses_muelu(const ParameterList &stratimikos)
{
  return stratimikos.isType<std::string>("Preconditioner Type") &&
         stratimikos.get<std::string>("Preconditioner Type") == "MueLu";
}

/// Kiln's defaults for the parameters of the smoother types chosen, set
/// where the input gives none. They cannot be in valid_parameters(): they
/// would be merged into the input's list, where they are invalid for
/// another type (Amesos2 rejects "relaxation: type" if "coarse: type" is
/// "KLU2").
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
    // low and the preconditioner indefinite (notes: 3D elasticity, 40^3).
    ParameterList &chebyshev = muelu.sublist("smoother: params");
    chebyshev.get("chebyshev: degree", 2);
    chebyshev.get("chebyshev: ratio eigenvalue", 7.0);
    chebyshev.get("chebyshev: eigenvalue max iterations", 30);
  }
  if (is("smoother: type", "RELAXATION"))
  {
    ParameterList &relaxation = muelu.sublist("smoother: params");
    relaxation.get("relaxation: type", std::string("Symmetric Gauss-Seidel"));
    relaxation.get("relaxation: sweeps", 1);
  }
  if (is("coarse: type", "RELAXATION"))
  {
    ParameterList &coarse = muelu.sublist("coarse: params");
    coarse.get("relaxation: type", std::string("Symmetric Gauss-Seidel"));
    coarse.get("relaxation: sweeps", 4);
  }
}

/// Kiln's defaults for Stratimikos: Belos Pseudo Block GMRES preconditioned
/// by MueLu.
ParameterList linear_solver_defaults()
{
  ParameterList p;
  p.set("Linear Solver Type", "Belos");
  ParameterList &belos = p.sublist("Linear Solver Types").sublist("Belos");
  belos.set("Solver Type", "Pseudo Block GMRES");
  ParameterList &gmres = belos.sublist("Solver Types").sublist("Pseudo Block GMRES");
  gmres.set("Convergence Tolerance", 1e-10);
  gmres.set("Maximum Iterations", 500);
  gmres.set("Num Blocks", 200);
  p.set("Preconditioner Type", "MueLu");
  p.sublist("Preconditioner Types").sublist("MueLu").setParameters(muelu_defaults());
  return p;
}

/// Erases from `text` every block that starts with `begin` and ends with the
/// first `end` after it (inclusive).
void erase_blocks(std::string &text, const std::string &begin, const std::string &end)
{
  for (std::size_t at = text.find(begin); at != std::string::npos; at = text.find(begin, at))
  {
    const std::size_t stop = text.find(end, at + begin.size());
    text.erase(at, stop == std::string::npos ? std::string::npos : stop + end.size() - at);
  }
}

/// The message of a Trilinos exception without what TEUCHOS_TEST_FOR_EXCEPTION
/// puts before it (file, line, throw number, the test), and without Teuchos'
/// list of every valid MueLu parameter (MueLu adds "Did you mean ...?").
std::string package_message(std::string message)
{
  const std::string test = "Throw test that evaluated to true: ";
  for (std::size_t at = message.find(test); at != std::string::npos; at = message.find(test))
  {
    const std::size_t number = message.rfind("\n\nThrow number = ", at);
    const std::size_t line = number == std::string::npos || number == 0
                                 ? std::string::npos
                                 : message.rfind('\n', number - 1);
    const std::size_t begin = number == std::string::npos ? at
                              : line == std::string::npos ? 0
                                                          : line + 1;
    const std::size_t end = message.find("\n\n", at);
    message.erase(begin, end == std::string::npos ? std::string::npos : end + 2 - begin);
  }
  erase_blocks(message, "Throw number = ", "\n");
  erase_blocks(message, "The valid parameters and types are:", "\n  }\n");
  for (std::size_t at = message.find("\n\n\n"); at != std::string::npos;
       at = message.find("\n\n\n"))
    message.erase(at, 1);
  while (!message.empty() && std::isspace(static_cast<unsigned char>(message.back())))
    message.pop_back();
  return message;
}

/// Runs `f`; an exception becomes the same InputError on every rank,
/// "Solver/<sublist>: <the package's message>".
template <typename F>
void as_input_error(const Teuchos::Comm<int> &comm, const std::string &sublist, F &&f)
{
  bool ok = true;
  std::string message;
  try
  {
    f();
  }
  catch (const std::exception &e)
  {
    ok = false;
    message = package_message(e.what());
  }
  check_collectively(comm, ok, solver_block + "/" + sublist, message);
}

/// MueLu reads its list only when the first preconditioner is built; check
/// it now so that a wrong option is an input error before any solve.
void check_muelu_parameters(const ParameterList &stratimikos,
                            const RCP<const Teuchos::Comm<int>> &comm)
{
  if (!uses_muelu(stratimikos))
    return;
  ParameterList muelu;
  if (stratimikos.isSublist("Preconditioner Types") &&
      stratimikos.sublist("Preconditioner Types").isSublist("MueLu"))
    muelu = stratimikos.sublist("Preconditioner Types").sublist("MueLu");
  // MueLu prints its distance to every valid name on std::cout; the message
  // has the closest one.
  std::ostringstream muelu_chatter;
  std::streambuf *const cout_buffer = std::cout.rdbuf(muelu_chatter.rdbuf());
  try
  {
    as_input_error(
        *comm, linear_name + "/Preconditioner Types/MueLu",
        [&] { MueLu::ParameterListInterpreter<double, int, long long, Node> check(muelu, comm); });
  }
  catch (...)
  {
    std::cout.rdbuf(cout_buffer);
    throw;
  }
  std::cout.rdbuf(cout_buffer);
}

/// Hands the problem's node coordinates (if any) to MueLu, for aggregation
/// and repartitioning; the number of unknowns per node is the ratio of owned
/// rows to owned nodes, the same on every rank.
void add_coordinates(ParameterList &stratimikos, const NonlinearProblem &problem,
                     const Teuchos::Comm<int> &comm, const bool near_null_space,
                     const RCP<const NonlinearProblem::Vector> &scale)
{
  const RCP<const Tpetra::MultiVector<double>> coordinates = problem.node_coordinates();
  if (coordinates.is_null() || !uses_muelu(stratimikos))
    return;
  const auto n_rows = static_cast<long long>(problem.solution_map()->getNodeNumElements());
  const auto n_nodes = static_cast<long long>(coordinates->getLocalLength());
  long long local[2] = {n_nodes > 0 && n_rows % n_nodes == 0 ? n_rows / n_nodes : -1, 0};
  local[1] = n_nodes > 0 ? -local[0] : -1; // min and max of the ratio in one reduction
  long long global[2] = {0, 0};
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, 2, local, global);
  if (global[0] < 1 || global[0] != -global[1])
    throw InternalError("NonlinearProblem::node_coordinates(): the owned rows are not a fixed "
                        "multiple of the owned nodes on every rank");
  ParameterList &muelu = stratimikos.sublist("Preconditioner Types").sublist("MueLu");
  muelu.set("Coordinates", Teuchos::rcp_const_cast<Tpetra::MultiVector<double>>(coordinates));
  if (!muelu.isParameter("number of equations"))
    muelu.set("number of equations", static_cast<int>(global[0]));
  // The near-null space, divided by the unknown scale as the solver sees it.
  const RCP<const Tpetra::MultiVector<double>> modes = problem.near_null_space();
  if (near_null_space && !modes.is_null() && !muelu.isParameter("Nullspace"))
  {
    auto scaled = Teuchos::rcp(new Tpetra::MultiVector<double>(*modes, Teuchos::Copy));
    if (!scale.is_null())
    {
      NonlinearProblem::Vector inverse(scale->getMap());
      inverse.reciprocal(*scale);
      for (std::size_t j = 0; j < scaled->getNumVectors(); ++j)
        scaled->getVectorNonConst(j)->elementWiseMultiply(1.0, inverse, *modes->getVector(j), 0.0);
    }
    muelu.set("Nullspace", scaled);
  }
}
} // namespace internal

using internal::linear_name;
using internal::nonlinear_name;
using Teuchos::ParameterList;
using Teuchos::RCP;

Teuchos::ParameterList NewtonSolver::valid_parameters()
{
  ParameterList p(internal::solver_block);
  p.set("Absolute Tolerance", 1e-8,
        "Converged when ||F||_2 <= this [units of the residual F as the solver sees it: W for "
        "heat; with Scale Unknowns and a displacement, N times sqrt(k / (lambda + 2G)) for "
        "force balance], must be > 0",
        positive_double_validator());
  p.set("Relative Tolerance", 1e-8,
        "Converged when ||F||_2 <= this * ||F(x0)||_2 [dimensionless], must be > 0",
        positive_double_validator());
  p.set("Scale Unknowns", true,
        "solve for x / c with rows times c, c the problem's scale of each unknown (with "
        "temperature and displacement: 1 for T, sqrt(k / (lambda + 2G)) for u; see "
        "doc/mechanics.md); the tolerances above then apply to the scaled residual [-]");
  p.set("Near-Null Space", true,
        "hand MueLu the problem's near-null space (the constant temperature and the six "
        "rigid-body modes) instead of MueLu's default (a constant per unknown of a node) [-]");
  p.set("Maximum Iterations", 20,
        "Newton iterations before giving up [count]; a solve that reaches it is not converged",
        positive_int_validator());
  set_pass_through_sublist(
      p, nonlinear_name, "NOX",
      "NOX parameters (default: Line Search Based, Full Step, Newton with a constant forcing "
      "term; Printing/\"Output Information\" quiet). Convergence is set by the three parameters "
      "above, not by NOX status tests",
      internal::nonlinear_solver_defaults());
  set_pass_through_sublist(
      p, linear_name, "Stratimikos (Belos, MueLu, Ifpack2)",
      "Stratimikos parameters (default: Belos Pseudo Block GMRES, relative tolerance 1e-10, "
      "500 iterations, preconditioned by MueLu smoothed aggregation (drop tolerance 0.02) with "
      "symmetric Gauss-Seidel smoothing and a Gauss-Seidel coarse level; see doc/solvers.md). "
      "Unless the input sets them, Kiln adds to \"smoother: params\" of a RELAXATION smoother "
      "1 symmetric Gauss-Seidel sweep, of a CHEBYSHEV smoother degree 2, ratio eigenvalue 7 and "
      "30 eigenvalue iterations, and to \"coarse: params\" of a RELAXATION coarse level 4 "
      "symmetric Gauss-Seidel sweeps",
      internal::linear_solver_defaults());
  return p;
}

struct NewtonSolver::Impl
{
  RCP<NonlinearProblem> problem;
  RCP<Teuchos::FancyOStream> out;
  RCP<const Teuchos::Comm<int>> comm;
  double absolute_tolerance = 0.0;
  double relative_tolerance = 0.0;
  int max_iterations = 0;
  ParameterList nonlinear;
  RCP<Stratimikos::DefaultLinearSolverBuilder> builder;
  RCP<internal::ModelEvaluator> model;
  /// The unknowns' scale c (NOX sees x / c), or null.
  RCP<const NonlinearProblem::Vector> scale;
  /// Kept between solves: it owns the Jacobian and the linear solver.
  RCP<NOX::Thyra::Group> group;

  /// NOX's list for one solve, printing on rank 0 to `out`.
  RCP<ParameterList> nox_parameters() const
  {
    auto p = Teuchos::rcp(new ParameterList(nonlinear));
    ParameterList &printing = p->sublist("Printing");
    printing.set("MyPID", comm->getRank());
    printing.set("Output Processor", 0);
    printing.set("Output Stream", Teuchos::rcp_implicit_cast<std::ostream>(out));
    printing.set("Error Stream", Teuchos::rcp_implicit_cast<std::ostream>(out));
    return p;
  }
};

NewtonSolver::NewtonSolver(const Teuchos::ParameterList &params,
                           Teuchos::RCP<NonlinearProblem> problem,
                           Teuchos::RCP<Teuchos::FancyOStream> out)
    : impl_(std::make_unique<Impl>())
{
  Impl &s = *impl_;
  const ParameterList p = validated(params, valid_parameters(), "", internal::solver_block);
  s.problem = problem.assert_not_null();
  s.out = out.is_null() ? Teuchos::getFancyOStream(Teuchos::rcpFromRef(std::cout)) : out;
  s.comm = problem->solution_map()->getComm();
  s.absolute_tolerance = p.get<double>("Absolute Tolerance");
  s.relative_tolerance = p.get<double>("Relative Tolerance");
  s.max_iterations = p.get<int>("Maximum Iterations");
  s.nonlinear = p.sublist(nonlinear_name);

  // Stratimikos: validates its list and the Belos/Ifpack2 sublists when the
  // strategy is created; MueLu's list is checked separately.
  auto linear = Teuchos::rcp(new ParameterList(p.sublist(linear_name)));
  s.builder = Teuchos::rcp(new Stratimikos::DefaultLinearSolverBuilder);
  Stratimikos::enableMueLu<int, long long, internal::Node>(*s.builder);
  // Debian's Stratimikos does not register Ifpack2 itself.
  s.builder->setPreconditioningStrategyFactory(
      Teuchos::abstractFactoryStd<Thyra::PreconditionerFactoryBase<double>,
                                  Thyra::Ifpack2PreconditionerFactory<NonlinearProblem::Matrix>>(),
      "Ifpack2");
  internal::add_smoother_defaults(*linear);
  internal::check_muelu_parameters(*linear, s.comm);
  const RCP<const NonlinearProblem::Vector> scale =
      p.get<bool>("Scale Unknowns") ? problem->unknown_scale() : Teuchos::null;
  internal::add_coordinates(*linear, *problem, *s.comm, p.get<bool>("Near-Null Space"), scale);
  RCP<Thyra::LinearOpWithSolveFactoryBase<double>> lows_factory;
  internal::as_input_error(*s.comm, linear_name,
                           [&]
                           {
                             s.builder->setParameterList(linear);
                             lows_factory = Thyra::createLinearSolveStrategy(*s.builder);
                           });
  lows_factory->setOStream(s.out);
  s.scale = scale;
  s.model = Teuchos::rcp(new internal::ModelEvaluator(problem, scale, lows_factory));

  // NOX: build a solver once, so that a wrong option is an input error now.
  const NOX::Thyra::Vector x0(s.model->getNominalValues().get_x()->clone_v());
  s.group = Teuchos::rcp(new NOX::Thyra::Group(x0, s.model));
  internal::as_input_error(*s.comm, nonlinear_name,
                           [&]
                           {
                             NOX::Solver::buildSolver(
                                 s.group, Teuchos::rcp(new NOX::StatusTest::MaxIters(1)),
                                 s.nox_parameters());
                           });
}

NewtonSolver::~NewtonSolver() = default;

int NewtonSolver::max_iterations() const
{
  return impl_->max_iterations;
}

NewtonSolver::Result NewtonSolver::solve(NonlinearProblem::Vector &x)
{
  namespace ST = NOX::StatusTest;
  using Extraction = Thyra::TpetraOperatorVectorExtraction<double>;
  Impl &s = *impl_;

  const RCP<const Thyra::VectorSpaceBase<double>> space = s.model->get_x_space();
  // NOX works on x̂ = x / c (ModelEvaluator); x is untouched until the end.
  const RCP<const NonlinearProblem::Vector> scale = s.scale;
  auto x_hat = Teuchos::rcp(new NonlinearProblem::Vector(x, Teuchos::Copy));
  if (!scale.is_null())
  {
    NonlinearProblem::Vector inverse(scale->getMap());
    inverse.reciprocal(*scale);
    x_hat->elementWiseMultiply(1.0, inverse, x, 0.0);
  }
  s.group->setX(NOX::Thyra::Vector(
      Thyra::createConstVector(Teuchos::rcp_implicit_cast<const NonlinearProblem::Vector>(x_hat),
                               space)
          ->clone_v()));
  s.group->computeF();
  Result result;
  result.initial_residual_norm = s.group->getNormF();

  // NaN/Inf first: with the "Minimal" check type the first test that is not
  // Unconverged decides.
  auto tests = Teuchos::rcp(new ST::Combo(ST::Combo::OR));
  tests->addStatusTest(Teuchos::rcp(new ST::FiniteValue));
  tests->addStatusTest(Teuchos::rcp(new ST::NormF(s.absolute_tolerance, ST::NormF::Unscaled)));
  tests->addStatusTest(
      Teuchos::rcp(new ST::NormF(*s.group, s.relative_tolerance, ST::NormF::Unscaled)));
  tests->addStatusTest(Teuchos::rcp(new ST::MaxIters(s.max_iterations)));

  const RCP<NOX::Solver::Generic> solver =
      NOX::Solver::buildSolver(s.group, tests, s.nox_parameters());
  const ST::StatusType status = solver->solve();

  const auto &solution = dynamic_cast<const NOX::Thyra::Group &>(solver->getSolutionGroup());
  const auto &x_nox = dynamic_cast<const NOX::Thyra::Vector &>(solution.getX());
  const auto x_final = Extraction::getConstTpetraVector(x_nox.getThyraRCPVector());
  if (scale.is_null())
    Tpetra::deep_copy(x, *x_final);
  else
    x.elementWiseMultiply(1.0, *scale, *x_final, 0.0);

  result.converged = status == ST::Converged;
  result.newton_iterations = solver->getNumIterations();
  result.linear_iterations =
      solver->getSolverStatistics()->linearSolve.lastNonlinearSolve_NumLinearIterations;
  result.final_residual_norm = solution.getNormF();
  return result;
}
} // namespace kiln
