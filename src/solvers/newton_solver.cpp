#include "solvers/newton_solver.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "solvers/block_triangular_preconditioner.hpp"
#include "solvers/direct_preconditioner.hpp"
#include "solvers/jacobian_reuse.hpp"
#include "solvers/linear_failure_divergence.hpp"
#include "solvers/linear_tolerance.hpp"
#include "solvers/model_evaluator.hpp"
#include "solvers/package_errors.hpp"
#include "solvers/package_parameters.hpp"
#include "solvers/solver_parameter_checks.hpp"
#include "solvers/starting_guess.hpp"

#include <NOX_SolverStats.hpp>
#include <NOX_Solver_Factory.H>
#include <NOX_Solver_Generic.H>
#include <NOX_StatusTest_Combo.H>
#include <NOX_StatusTest_FiniteValue.H>
#include <NOX_StatusTest_MaxIters.H>
#include <NOX_StatusTest_NormF.H>
#include <NOX_Thyra_Group.H>
#include <NOX_Thyra_Vector.H>
#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Stratimikos_MueLuHelpers.hpp>
#include <Teuchos_AbstractFactoryStd.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Thyra_Ifpack2PreconditionerFactory.hpp>
#include <Thyra_LinearSolverBuilderBase.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

namespace kiln
{
namespace internal
{
using Teuchos::ParameterList;
using Teuchos::RCP;
using Node = Tpetra::Map<>::node_type;

/// The input block and its sublists handed to NOX and Stratimikos.
const std::string solver_block = "Solver";
const std::string nonlinear_name = "Nonlinear Solver";
const std::string linear_name = "Linear Solver";

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
        "hand MueLu the problem's near-null space (the constant temperature, with displacements "
        "its free thermal expansion alpha (x - centre), and the six rigid-body modes) instead "
        "of MueLu's default (a constant per unknown of a node) [-]");
  p.set("Reuse", true,
        "keep the Jacobian and its preconditioner while the problem says they are unchanged "
        "(every term linear in the state, the same time-step coefficient, constraints and "
        "contact decision; doc/solvers.md): the result is the same to the last bit, without "
        "the assembly and the preconditioner set-up. false: build both at every Newton "
        "iteration [-]");
  p.set("Preconditioner Reuse Tolerance", 1.0,
        "with Reuse: keep the preconditioner (not the Jacobian, which is evaluated anew) "
        "while the time-derivative coefficient a (about 1/dt) is within a factor 1 + this of "
        "the a it was built for (1: from half to twice it), the constraints and the contact "
        "decision unchanged: the Krylov solver then sees the new Jacobian with the "
        "preconditioner of an earlier one (its finest level reads the new matrix; "
        "doc/solvers.md): fewer set-ups, the answer the same to the Krylov tolerance. A "
        "checkpoint records what the kept preconditioner was built from, so that a restart "
        "on as many ranks goes on to the last bit as the uninterrupted run. 0: build one for "
        "every new Jacobian [-], must be >= 0",
        nonnegative_double_validator());
  p.set("Keep Preconditioner Within Solve", true,
        "with Reuse, for a Jacobian that varies with the state (viscoplastic flow, a modulus "
        "or conductivity that depends on T): the later Newton iterations of a solve (a time "
        "step) keep the preconditioner built at its first, while the time-derivative "
        "coefficient, the constraints and the contact decision are unchanged and no linear "
        "solve fell short of its tolerance (then the next iteration builds one). The Jacobian "
        "is still evaluated at every iteration (Newton converges as with the consistent "
        "tangent); the Krylov solver sees it with the first iteration's preconditioner (its "
        "finest level reads the new matrix; doc/solvers.md): fewer set-ups, the answer the "
        "same to the Newton tolerance. false: a preconditioner for every new Jacobian [-]");
  p.set("Keep Preconditioner Across Steps", true,
        "with Keep Preconditioner Within Solve, for a Jacobian that varies with the state: the "
        "first Newton iteration of a solve (a time step) also keeps the preconditioner of the "
        "solve before, under the same conditions (the constraints and the contact decision "
        "unchanged, no linear solve short of its tolerance) but that the time-derivative "
        "coefficient a may be within a factor 1 + Preconditioner Reuse Tolerance of the one "
        "it was built for, until it is stale: the solve before did not converge, or it took more "
        "than Preconditioner Staleness Factor times the Krylov iterations per Newton "
        "iteration of the solve that built it (doc/solvers.md). The answer is the same to the "
        "Newton tolerance, not to the last bit; it is given up at every output or checkpoint "
        "time and checkpoint, so that a run restarted from there goes on bit for bit (a run "
        "stopped by a signal excepted). A problem with a constant Jacobian is not affected. "
        "false: one per solve [-]");
  p.set("Preconditioner Staleness Factor", 2.0,
        "with Keep Preconditioner Across Steps: the growth of the Krylov iterations per Newton "
        "iteration, against the solve that built the preconditioner, that makes it stale (the "
        "next solve builds one) [-], from 1 to 1000",
        double_range_validator(1.0, 1000.0));
  p.set("Adaptive Linear Tolerance", true,
        "true: stop the Krylov solve of each Newton iteration once its residual, relative to "
        "||F_k||, is below s max(Absolute Tolerance, Relative Tolerance ||F(x0)||) / ||F_k||, "
        "s the Safety below (what the Newton test above asks, with a factor 1/s to spare), but "
        "never tighter than the Belos solver's Convergence Tolerance (default 1e-10) nor "
        "looser than 0.1. With the default s = 0.001 only the solves that start from a small "
        "residual stop early (no Krylov residual below 1e-11 with the default tolerances); "
        "fewer Krylov iterations, the answer 1000 times more accurate than the Newton test "
        "asks (doc/solvers.md). false: every Krylov solve to the Convergence Tolerance. Only "
        "with Belos and NOX's Constant forcing term [-]");
  p.set("Adaptive Linear Tolerance Safety", 0.001,
        "with Adaptive Linear Tolerance: the fraction s of the Newton target the Krylov "
        "residual may keep (0.1 stops at a tenth of what the Newton test asks, the answer "
        "then about as accurate as that test: 1e-9 instead of 1e-12 on a uniform state; 0: "
        "every solve to the Belos tolerance) [-], from 0 to 1",
        double_range_validator(0.0, 1.0));
  p.set("Adaptive Linear Tolerance Rate", 0.1,
        "with Adaptive Linear Tolerance, for a Jacobian that varies with the state "
        "(viscoplastic flow, a modulus or conductivity that depends on T): from the second "
        "Newton iteration of a solve on, the Krylov solve may also stop at this times "
        "(||F_k|| / ||F_k-1||)^2 relative to ||F_k||, this times the residual Newton's "
        "quadratic convergence predicts for the next iteration (Eisenstat and Walker's second "
        "choice): the early iterations are not solved far beyond what their Newton step is "
        "worth, the last one still to the Newton target with the Safety above "
        "(doc/solvers.md). A problem whose Jacobian is constant between changes of the "
        "contact set is not affected. 0: not used [-], from 0 to 1",
        double_range_validator(0.0, 1.0));
  p.set("Adaptive Linear Tolerance First", 1e-3,
        "with Adaptive Linear Tolerance, for a Jacobian that varies with the state: the first "
        "Newton iteration of a solve that starts from the last state (not from the "
        "Extrapolated Newton Start's predictor: the first step of a run, a step after a cut or "
        "without the predictor) may stop its Krylov solve at this relative to ||F_0|| "
        "(Eisenstat and Walker's fixed first forcing term): from the last state the tangent "
        "does not know the step's flow, so that iteration's Newton step leaves a part of "
        "||F_0|| far above it, which the next iterations remove with the Rate above "
        "(doc/solvers.md). A problem whose Jacobian is constant between changes of the "
        "contact set is not affected. A solve that would converge in one iteration from the "
        "last state takes two. 0: not used [-], from 0 to 0.1",
        double_range_validator(0.0, 0.1));
  p.set("Maximum Iterations", 20,
        "Newton iterations before giving up [count]; a solve that reaches it is not converged",
        positive_int_validator());
  set_pass_through_sublist(
      p, nonlinear_name, "NOX",
      "NOX parameters (default: Line Search Based, Full Step, Newton with a constant forcing "
      "term; Printing/\"Output Information\" quiet). Convergence is set by the three parameters "
      "above, not by NOX status tests. Only the sublist of the chosen \"Line Search\" and "
      "\"Direction\" \"Method\" is read: one filled for another is an input error",
      internal::nonlinear_solver_defaults());
  set_pass_through_sublist(
      p, linear_name, "Stratimikos (Belos, MueLu, Ifpack2)",
      "Stratimikos parameters (default: Belos Block GMRES, flexible, relative tolerance 1e-10, "
      "500 iterations, preconditioned by MueLu smoothed aggregation (distance-Laplacian drop "
      "tolerance 0.02, no aggregate across a gap that separates bodies) with Gauss-Seidel "
      "smoothing and a Gauss-Seidel coarse level; see doc/solvers.md). With temperature and "
      "displacement (Thermo-Elasticity) and at least 50,000 unknowns the default "
      "Preconditioner Type is \"Block Triangular\" (the set-up log says which is used): one "
      "MueLu hierarchy for the temperatures, one for the displacements "
      "(with the six rigid-body modes and Chebyshev smoothing), applied in turn with the coupling "
      "of the force rows to T between them; the \"MueLu\" list applies to both, \"Preconditioner "
      "Types\"/\"Block Triangular\"/\"Temperature\" and \"Displacement\" add to one "
      "(doc/solvers.md). "
      "\"MueLu\" as the Preconditioner Type keeps one hierarchy for the whole system. With "
      "at most 2,000 unknowns the default is \"Direct\" (unless the input gives a \"MueLu\" "
      "or \"Block Triangular\" list): J gathered onto rank 0 and factored there by Amesos2's "
      "KLU2, so that each Krylov solve takes one or two iterations (doc/solvers.md). "
      "Unless the input sets them, Kiln adds to \"smoother: params\" of a RELAXATION smoother "
      "1 forward Gauss-Seidel sweep (symmetric Gauss-Seidel under CG or MINRES or for one "
      "unknown per node) and \"relaxation: use l1\" true (l1 Gauss-Seidel across ranks), of a "
      "CHEBYSHEV smoother degree 2, ratio eigenvalue 7 and an eigenvalue estimate by 30 "
      "power iterations (by 10 of CG's under a CG solver), and to "
      "\"coarse: params\" of a RELAXATION coarse level 10 symmetric Gauss-Seidel sweeps, and "
      "with the sa or unsmoothed algorithm \"transpose: use implicit\" true. Only the sublists "
      "of the chosen types are read: one filled for another (\"Solver Types\"/\"Pseudo Block "
      "GMRES\" under the default \"Solver Type\") is an input error",
      internal::linear_solver_defaults());
  return p;
}

struct NewtonSolver::Impl
{
  RCP<NonlinearProblem> problem;
  RCP<Teuchos::FancyOStream> out;
  RCP<const Teuchos::Comm<int>> comm;
  std::string where;               ///< the block in messages ("in.xml: Kiln/Solver")
  std::string preconditioner_type; ///< the Preconditioner Type used
  double absolute_tolerance = 0.0;
  double relative_tolerance = 0.0;
  int max_iterations = 0;
  /// The Krylov tolerance's rule (Adaptive Linear Tolerance): its floor is the Belos
  /// Convergence Tolerance if the tolerance is adapted, else 0.
  internal::LinearTolerance adaptive{0.0};
  ParameterList nonlinear;
  RCP<Stratimikos::DefaultLinearSolverBuilder> builder;
  RCP<internal::ModelEvaluator> model;
  RCP<internal::JacobianReuse> reuse;
  /// The start of the first Krylov solve of a solve (solve(x, first_step)).
  RCP<internal::StartingGuess> starting_guess = Teuchos::rcp(new internal::StartingGuess);
  /// The unknowns' scale c (NOX sees x / c) and 1 / c, or null.
  RCP<const NonlinearProblem::Vector> scale, inverse_scale;
  /// The free motions' pins (Minimum Norm; FreeMotionPins), or null.
  RCP<internal::FreeMotionPins> pins;
  /// Kept between solves: it owns the Jacobian and the linear solver.
  RCP<NOX::Thyra::Group> group;

  /// factor v / c as a vector of NOX's space (`space`).
  RCP<const Thyra::VectorBase<double>>
  to_solver(const NonlinearProblem::Vector &v, double factor,
            const RCP<const Thyra::VectorSpaceBase<double>> &space) const
  {
    auto v_hat = Teuchos::rcp(new NonlinearProblem::Vector(v.getMap()));
    if (inverse_scale.is_null())
      v_hat->update(factor, v, 0.0);
    else
      v_hat->elementWiseMultiply(factor, *inverse_scale, v, 0.0);
    return Thyra::createConstVector(
        Teuchos::rcp_implicit_cast<const NonlinearProblem::Vector>(v_hat), space);
  }

  /// `preconditioner_given`: the input names the "Preconditioner Type" (else Kiln picks it).
  RCP<Thyra::LinearOpWithSolveFactoryBase<double>> create_linear_solver(const ParameterList &p,
                                                                        bool preconditioner_given);
  void check_nonlinear_parameters();
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

/// Stratimikos validates its list and the Belos/Ifpack2 sublists when the strategy is
/// created, but not the lists of Belos' solvers; those, NOX's and MueLu's lists are checked
/// before (solver_parameter_checks.hpp). Sets `scale` too.
RCP<Thyra::LinearOpWithSolveFactoryBase<double>>
NewtonSolver::Impl::create_linear_solver(const ParameterList &p, const bool preconditioner_given)
{
  auto linear = Teuchos::rcp(new ParameterList(p.sublist(linear_name)));
  // Temperature and displacement, and enough unknowns for it to pay: the block triangular
  // preconditioner unless the input chooses (doc/solvers.md, "Block Triangular").
  // Few enough unknowns: J's LU factors on rank 0, unless the input tunes a multigrid
  // (doc/solvers.md, "Small problems: Direct").
  const int unknowns = internal::unknowns_per_node(*problem, *comm);
  const auto global_unknowns =
      static_cast<long long>(problem->solution_map()->getGlobalNumElements());
  const bool multigrid_given =
      given_in_input(p.sublist(linear_name), "Preconditioner Types") &&
      (given_in_input(p.sublist(linear_name).sublist("Preconditioner Types"), "MueLu") ||
       given_in_input(p.sublist(linear_name).sublist("Preconditioner Types"), "Block Triangular"));
  // Kiln's pick stays a default: an unread sublist is reported against it as such.
  const auto pick = [&](const std::string &type)
  { linear->getEntryPtr("Preconditioner Type")->setValue(type, true); };
  if (!preconditioner_given && unknowns == 4 && global_unknowns >= internal::block_triangular_from)
    pick("Block Triangular");
  else if (!preconditioner_given && !multigrid_given && global_unknowns <= internal::direct_up_to)
    pick("Direct");
  preconditioner_type = linear->get<std::string>("Preconditioner Type");
  const bool block_triangular = preconditioner_type == "Block Triangular";
  // MueLu's list as the input and Kiln's defaults give it, for the blocks' hierarchies.
  const ParameterList muelu = linear->sublist("Preconditioner Types").sublist("MueLu");
  builder = Teuchos::rcp(new Stratimikos::DefaultLinearSolverBuilder);
  Stratimikos::enableMueLu<int, long long, internal::Node>(*builder);
  // Debian's Stratimikos does not register Ifpack2 itself.
  builder->setPreconditioningStrategyFactory(
      Teuchos::abstractFactoryStd<Thyra::PreconditionerFactoryBase<double>,
                                  Thyra::Ifpack2PreconditionerFactory<NonlinearProblem::Matrix>>(),
      "Ifpack2");
  builder->setPreconditioningStrategyFactory(
      Teuchos::abstractFactoryStd<Thyra::PreconditionerFactoryBase<double>,
                                  internal::BlockTriangularPreconditionerFactory>(),
      "Block Triangular");
  builder->setPreconditioningStrategyFactory(
      Teuchos::abstractFactoryStd<Thyra::PreconditionerFactoryBase<double>,
                                  internal::DirectPreconditionerFactory>(),
      "Direct");
  const std::string linear_block = where + "/" + linear_name;
  internal::check_solver_parameters(p, *linear, *builder->getValidParameters(), comm, where);
  scale = p.get<bool>("Scale Unknowns") ? problem->unknown_scale() : Teuchos::null;
  if (!scale.is_null())
  {
    auto inverse = Teuchos::rcp(new NonlinearProblem::Vector(scale->getMap()));
    inverse->reciprocal(*scale);
    inverse_scale = inverse;
  }
  internal::add_coordinates(*linear, *problem, *comm, p.get<bool>("Near-Null Space"), scale);
  KILN_CHECK_INPUT(!block_triangular || unknowns == 4, linear_block + "/\"Preconditioner Type\"",
                   "is \"Block Triangular\", which splits the temperature and the three "
                   "displacements of each node, but this problem has "
                       << unknowns
                       << " unknowns per node (Physics is not Thermo-Elasticity); remove the "
                          "parameter (Kiln then uses \"MueLu\") or set \"MueLu\"");
  internal::add_smoother_defaults(*linear);
  RCP<Thyra::LinearOpWithSolveFactoryBase<double>> lows_factory;
  internal::as_input_error(*comm, linear_block,
                           [&]
                           {
                             builder->setParameterList(linear);
                             lows_factory = Thyra::createLinearSolveStrategy(*builder);
                           });
  lows_factory->setOStream(out);
  // The preconditioner is built by a factory that keeps it while the Jacobian is kept.
  RCP<Thyra::PreconditionerFactoryBase<double>> preconditioner;
  std::string preconditioner_name;
  if (lows_factory->acceptsPreconditionerFactory() &&
      !lows_factory->getPreconditionerFactory().is_null())
  {
    lows_factory->unsetPreconditionerFactory(&preconditioner, &preconditioner_name);
    if (auto *blocks =
            dynamic_cast<internal::BlockTriangularPreconditionerFactory *>(preconditioner.get()))
      blocks->set_hints(problem->node_coordinates(),
                        p.get<bool>("Near-Null Space")
                            ? internal::scaled_near_null_space(*problem, scale)
                            : Teuchos::null,
                        muelu);
    lows_factory->setPreconditionerFactory(
        Teuchos::rcp(new internal::ReusingPreconditionerFactory(preconditioner, reuse)),
        preconditioner_name);
  }
  return lows_factory;
}

/// NOX: build a solver once, so that a wrong option is an input error now.
void NewtonSolver::Impl::check_nonlinear_parameters()
{
  const NOX::Thyra::Vector x0(model->getNominalValues().get_x()->clone_v());
  group = Teuchos::rcp(new NOX::Thyra::Group(x0, model));
  internal::as_input_error(*comm, where + "/" + nonlinear_name,
                           [&]
                           {
                             NOX::Solver::buildSolver(
                                 group, Teuchos::rcp(new NOX::StatusTest::MaxIters(1)),
                                 nox_parameters());
                           });
}

NewtonSolver::NewtonSolver(const Teuchos::ParameterList &params,
                           Teuchos::RCP<NonlinearProblem> problem,
                           Teuchos::RCP<Teuchos::FancyOStream> out, const std::string &where)
    : impl_(std::make_unique<Impl>())
{
  Impl &s = *impl_;
  s.where = where;
  const ParameterList p = validated(params, valid_parameters(), "", internal::solver_block);
  s.problem = problem.assert_not_null();
  s.out = out.is_null() ? Teuchos::getFancyOStream(Teuchos::rcpFromRef(std::cout)) : out;
  s.comm = problem->solution_map()->getComm();
  s.absolute_tolerance = p.get<double>("Absolute Tolerance");
  s.relative_tolerance = p.get<double>("Relative Tolerance");
  s.max_iterations = p.get<int>("Maximum Iterations");
  s.nonlinear = p.sublist(nonlinear_name);
  const ParameterList &newton = s.nonlinear.sublist("Direction").sublist("Newton");
  const bool constant_forcing = !newton.isType<std::string>("Forcing Term Method") ||
                                newton.get<std::string>("Forcing Term Method") == "Constant";
  if (p.get<bool>("Adaptive Linear Tolerance") && constant_forcing)
  {
    s.adaptive.floor = internal::belos_convergence_tolerance(p.sublist(linear_name));
    s.adaptive.safety = p.get<double>("Adaptive Linear Tolerance Safety");
    s.adaptive.rate = p.get<double>("Adaptive Linear Tolerance Rate");
    s.adaptive.first = p.get<double>("Adaptive Linear Tolerance First");
  }
  s.reuse = Teuchos::rcp(new internal::JacobianReuse(
      p.get<bool>("Reuse"), p.get<double>("Preconditioner Reuse Tolerance"),
      p.get<bool>("Keep Preconditioner Within Solve"),
      p.get<bool>("Keep Preconditioner Across Steps"),
      p.get<double>("Preconditioner Staleness Factor")));
  s.reuse->set_failed_solves([guess = s.starting_guess] { return guess->unconverged; });
  if (s.adaptive.floor > 0.0 && s.adaptive.rate > 0.0) // solve(): its target asks varying()
    s.reuse->track_varying();
  const bool preconditioner_given =
      params.isSublist(linear_name) &&
      given_in_input(params.sublist(linear_name), "Preconditioner Type");
  const RCP<Thyra::LinearOpWithSolveFactoryBase<double>> lows_factory =
      Teuchos::rcp(new internal::StartingGuessSolveFactory(
          s.create_linear_solver(p, preconditioner_given), s.starting_guess));
  if (const auto motions = problem->free_motions(); !motions.is_null())
    s.pins = Teuchos::rcp(new internal::FreeMotionPins(*motions, s.inverse_scale.get(),
                                                       problem->free_motion_names()));
  s.model =
      Teuchos::rcp(new internal::ModelEvaluator(problem, s.scale, lows_factory, s.reuse, s.pins));
  s.check_nonlinear_parameters();
}

NewtonSolver::~NewtonSolver() = default;

int NewtonSolver::max_iterations() const
{
  return impl_->max_iterations;
}

const std::string &NewtonSolver::preconditioner() const
{
  return impl_->preconditioner_type;
}

std::vector<double> NewtonSolver::preconditioner_origin() const
{
  return impl_->reuse->origin();
}

void NewtonSolver::restore_preconditioner_origin(std::vector<double> record)
{
  impl_->reuse->restore_origin(std::move(record));
}

void NewtonSolver::restart_point()
{
  impl_->reuse->restart_point();
}

namespace
{
/// The Jacobians and preconditioners of a solve, evaluated, built or kept: the counts `after`
/// it less those `before`.
void set_reuse_counts(const internal::JacobianReuse::Counts &before,
                      const internal::JacobianReuse::Counts &after, NewtonSolver::Result &result)
{
  result.jacobians_evaluated = after.jacobians_evaluated - before.jacobians_evaluated;
  result.jacobians_kept = after.jacobians_kept - before.jacobians_kept;
  result.preconditioners_built = after.preconditioners_built - before.preconditioners_built;
  result.preconditioners_kept = after.preconditioners_kept - before.preconditioners_kept;
}
} // namespace

bool NewtonSolver::jacobian_varies() const
{
  const int varies_here = impl_->problem->jacobian_varies() ? 1 : 0;
  int varies = 0;
  Teuchos::reduceAll(*impl_->problem->solution_map()->getComm(), Teuchos::REDUCE_MAX, varies_here,
                     Teuchos::outArg(varies));
  return varies == 1;
}

NewtonSolver::Result NewtonSolver::solve(NonlinearProblem::Vector &x,
                                         const NonlinearProblem::Vector *first_step,
                                         const bool start_at_first_step)
{
  namespace ST = NOX::StatusTest;
  using Extraction = Thyra::TpetraOperatorVectorExtraction<double>;
  Impl &s = *impl_;
  const internal::JacobianReuse::Counts before = s.reuse->counts();
  const int unconverged_before = s.starting_guess->unconverged;

  const RCP<const Thyra::VectorSpaceBase<double>> space = s.model->get_x_space();
  // NOX works on x̂ = x / c (ModelEvaluator); x is untouched until the end.
  const RCP<const NonlinearProblem::Vector> scale = s.scale;
  RCP<Thyra::VectorBase<double>> x0 = s.to_solver(x, 1.0, space)->clone_v();
  if (!s.pins.is_null()) // the start without a part in the free motions
    s.pins->project(*Extraction::getTpetraVector(x0));
  s.group->setX(NOX::Thyra::Vector(x0));
  s.reuse->begin_solve();
  Result result;
  // A StepFailure (a model's local solve, on every rank alike): the solve ends unconverged, x
  // as it was; a Jacobian it interrupted is not kept.
  const auto failed = [&](const StepFailure &e)
  {
    s.starting_guess->clear();
    s.reuse->forget();
    s.group->setX(NOX::Thyra::Vector(x0));
    result.converged = false;
    result.step_failure = e.what();
    set_reuse_counts(before, s.reuse->counts(), result);
    s.reuse->end_solve(false, result.newton_iterations, 0);
    return result;
  };
  try
  {
    s.group->computeF();
  }
  catch (const StepFailure &e)
  {
    result.initial_residual_norm = result.final_residual_norm =
        std::numeric_limits<double>::quiet_NaN();
    return failed(e);
  }
  result.initial_residual_norm = s.group->getNormF();
  if (!std::isfinite(result.initial_residual_norm))
  {
    // F at the start is NaN or Inf: the solve fails here (the time stepper names it), also
    // when Newton would start from a predicted x + first_step, where F is evaluated anew.
    result.final_residual_norm = result.initial_residual_norm;
    return failed(StepFailure(""));
  }
  result.tolerance =
      std::max(s.absolute_tolerance, s.relative_tolerance * result.initial_residual_norm);
  // With free motions, a load with a part along them has no equilibrium: it would stay in
  // the rows of the pins, whatever x.
  if (!s.pins.is_null() && s.pins->pin_residual() > result.tolerance)
  {
    std::ostringstream message;
    message.precision(3);
    message << s.where
            << ": the load has a net force or moment along a free rigid motion "
               "(Kiln/Mechanics/\"Free Motions\" = \"Minimum Norm\"): "
            << s.pins->imbalance()
            << "; no displacement balances it, so there is no solution (the residual it "
               "leaves, "
            << s.pins->pin_residual() << ", is above the Newton target " << result.tolerance
            << "). Hold the motion with a displacement condition, or balance the load";
    throw RunError(message.str());
  }

  // NaN/Inf first: with the "Minimal" check type the first test that is not
  // Unconverged decides.
  auto tests = Teuchos::rcp(new ST::Combo(ST::Combo::OR));
  tests->addStatusTest(Teuchos::rcp(new ST::FiniteValue));
  tests->addStatusTest(Teuchos::rcp(new ST::NormF(s.absolute_tolerance, ST::NormF::Unscaled)));
  tests->addStatusTest(
      Teuchos::rcp(new ST::NormF(*s.group, s.relative_tolerance, ST::NormF::Unscaled)));
  // A linear solve short of its tolerance gives NOX's step anyway ("Rescue Bad Newton
  // Solve"): if ||F|| then grows a millionfold, the solve stops (Result::linear_divergence)
  // instead of going on to its iteration limit.
  const auto divergence = Teuchos::rcp(new internal::LinearFailureDivergence(
      [guess = s.starting_guess, unconverged_before]
      { return guess->unconverged - unconverged_before; },
      result.initial_residual_norm, internal::linear_divergence_growth));
  tests->addStatusTest(divergence);
  tests->addStatusTest(Teuchos::rcp(new ST::MaxIters(s.max_iterations)));

  const RCP<ParameterList> nox = s.nox_parameters();
  std::unique_ptr<internal::AdaptiveLinearTolerance> adaptive;
  if (s.adaptive.floor > 0.0)
  {
    internal::use_relative_residual_measure(*nox, s.adaptive.floor);
    adaptive = std::make_unique<internal::AdaptiveLinearTolerance>(
        s.adaptive, nox->sublist("Direction").sublist("Newton").sublist("Linear Solver"));
    // A Jacobian that varies with the state (no dependencies to keep it by), as the solve's
    // first Jacobian found it, and a start that is the last state: from a predictor (Extrapolated
    // Newton Start) the first iteration may be the last, so it is solved as any last one.
    const bool predicted = first_step != nullptr && start_at_first_step;
    const bool first_varying = s.adaptive.first > 0.0 && !predicted && jacobian_varies();
    if (s.adaptive.rate > 0.0)
      adaptive->set_target(
          result.tolerance, [reuse = s.reuse] { return reuse->varying(); }, first_varying);
    else
      adaptive->set_target(result.tolerance, {}, first_varying);
    nox->sublist("Solver Options").set("Observer", adaptive->observer());
  }
  if (first_step != nullptr && start_at_first_step)
  {
    // Newton starts at x + first_step (the tolerance stays that of F(x), set above).
    RCP<Thyra::VectorBase<double>> x_start = x0->clone_v();
    Thyra::Vp_V(x_start.ptr(), *s.to_solver(*first_step, 1.0, space));
    if (!s.pins.is_null())
      s.pins->project(*Extraction::getTpetraVector(x_start));
    s.group->setX(NOX::Thyra::Vector(x_start));
    try // F at the start, as NOX's first iteration expects it (and its observer reads it)
    {
      s.group->computeF();
    }
    catch (const StepFailure &e)
    {
      result.final_residual_norm = std::numeric_limits<double>::quiet_NaN();
      return failed(e);
    }
  }
  else if (first_step != nullptr) // NOX solves J X = F for X = -dx, in x / c.
    s.starting_guess->set(s.to_solver(*first_step, -1.0, space));
  const RCP<NOX::Solver::Generic> solver = NOX::Solver::buildSolver(s.group, tests, nox);
  ST::StatusType status = ST::Unevaluated;
  try
  {
    status = solver->solve();
  }
  catch (const StepFailure &e)
  {
    result.newton_iterations = solver->getNumIterations();
    result.final_residual_norm = std::numeric_limits<double>::quiet_NaN();
    return failed(e);
  }
  s.starting_guess->clear();

  const auto &solution = dynamic_cast<const NOX::Thyra::Group &>(solver->getSolutionGroup());
  const auto &x_nox = dynamic_cast<const NOX::Thyra::Vector &>(solution.getX());
  const auto x_final = Extraction::getConstTpetraVector(x_nox.getThyraRCPVector());
  if (scale.is_null())
    Tpetra::deep_copy(x, *x_final);
  else
    x.elementWiseMultiply(1.0, *scale, *x_final, 0.0);
  if (!s.pins.is_null()) // the Newton updates kept the pins: the minimum-norm solution
  {
    NonlinearProblem::Vector x_hat(x.getMap());
    if (s.inverse_scale.is_null())
      Tpetra::deep_copy(x_hat, x);
    else
      x_hat.elementWiseMultiply(1.0, *s.inverse_scale, x, 0.0);
    s.pins->project(x_hat);
    if (scale.is_null())
      Tpetra::deep_copy(x, x_hat);
    else
      x.elementWiseMultiply(1.0, *scale, x_hat, 0.0);
  }
  // The problem's own minimum-norm step (contact: the motions open pairs leave free), also
  // when the set-up leaves no motion free.
  if (status == ST::Converged)
    s.problem->to_minimum_norm(x);

  result.converged = status == ST::Converged;
  result.newton_iterations = solver->getNumIterations();
  result.linear_iterations =
      solver->getSolverStatistics()->linearSolve.lastNonlinearSolve_NumLinearIterations;
  result.final_residual_norm = solution.getNormF();
  result.linear_failures = s.starting_guess->unconverged - unconverged_before;
  result.linear_divergence = divergence->getStatus() == ST::Failed;
  set_reuse_counts(before, s.reuse->counts(), result);
  s.reuse->end_solve(result.converged, result.newton_iterations, result.linear_iterations);
  return result;
}
} // namespace kiln
