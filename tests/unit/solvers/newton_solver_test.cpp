// Tests src/solvers/newton_solver.cpp on a nonlinear diffusion problem,
// -div(k(u) grad u) = f with k(u) = 1 + u^2, finite differences on a box of
// n^d nodes (d = 1, 2, 3) split over the ranks, Dirichlet values on the box's
// faces, f manufactured from a discrete u* so that F(u*) = 0 exactly: Newton
// converges quadratically to u*, with the same iterates on one rank and on
// all, and the solver's options and failure paths behave.
// KILN_TEST_NP: 1 2
#include "solvers/newton_solver.hpp"

#include "base/errors.hpp"
#include "support/parameter_lists.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <vector>

namespace
{
using kiln::NewtonSolver;
using kiln::NonlinearProblem;
using Teuchos::RCP;
using GO = NonlinearProblem::Map::global_ordinal_type;
using LO = NonlinearProblem::Map::local_ordinal_type;

/// F_i = sum over neighbours j of k((u_i + u_j)/2) (u_i - u_j) - b_i in the
/// interior (the flux form scaled by h^2), F_i = u_i - u*_i on the faces;
/// b = the interior operator applied to u*. Records ||F||_2 of every
/// evaluation.
class NonlinearDiffusion final : public NonlinearProblem
{
public:
  /// `linear`: k = 1, F(u) = A u - b.
  NonlinearDiffusion(const RCP<const Teuchos::Comm<int>> &comm, const int n, const int dim,
                     const bool linear = false)
      : n_(n), dim_(dim), linear_(linear)
  {
    GO n_total = 1;
    for (int a = 0; a < dim; ++a)
      n_total *= n;
    map_ = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(n_total), GO(0), comm));
    const size_t n_owned = map_->getNodeNumElements();
    auto graph = Teuchos::rcp(new Graph(map_, 2 * dim + 1));
    b_.resize(n_owned);
    coordinates_ = Teuchos::rcp(new Tpetra::MultiVector<double>(map_, 3));
    for (size_t lid = 0; lid < n_owned; ++lid)
    {
      const GO gid = map_->getGlobalElement(static_cast<LO>(lid));
      const std::array<double, 3> p = point(gid);
      for (int a = 0; a < 3; ++a)
        coordinates_->replaceLocalValue(static_cast<LO>(lid), a, p[a]);
      std::vector<GO> columns{gid};
      if (!on_boundary(gid))
        for (const GO j : neighbours(gid))
        {
          columns.push_back(j);
          b_[lid] += flux(u_star(gid), u_star(j));
        }
      graph->insertGlobalIndices(gid, Teuchos::arrayViewFromVector(columns));
    }
    graph->fillComplete();
    graph_ = graph;
  }

  RCP<const Map> solution_map() const override { return map_; }
  RCP<const Graph> jacobian_graph() const override { return graph_; }
  RCP<const Tpetra::MultiVector<double>> node_coordinates() const override { return coordinates_; }

  void evaluate(const Vector &x, Vector *f, Matrix *J) override
  {
    Vector x_col(graph_->getColMap());
    if (graph_->getImporter().is_null())
      Tpetra::deep_copy(x_col, x);
    else
      x_col.doImport(x, *graph_->getImporter(), Tpetra::INSERT);
    const auto u = x_col.getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto &col_map = *graph_->getColMap();
    if (J != nullptr)
    {
      J->resumeFill();
      ++jacobian_evaluations;
    }
    std::vector<double> F_values(map_->getNodeNumElements());
    {
      for (size_t lid = 0; lid < map_->getNodeNumElements(); ++lid)
      {
        const GO gid = map_->getGlobalElement(static_cast<LO>(lid));
        const double u_i = u(col_map.getLocalElement(gid), 0);
        std::vector<LO> columns{col_map.getLocalElement(gid)};
        std::vector<double> values{0.0};
        double F = 0.0;
        if (on_boundary(gid))
        {
          F = u_i - u_star(gid);
          values[0] = 1.0;
        }
        else
        {
          // shift (u - u*): a term the Jacobian varies with smoothly, zero at u*.
          F = -b_[lid] + shift * (u_i - u_star(gid));
          values[0] = shift;
          for (const GO j : neighbours(gid))
          {
            const LO c = col_map.getLocalElement(j);
            const double u_j = u(c, 0);
            F += flux(u_i, u_j);
            const double m = 0.5 * (u_i + u_j), k = linear_ ? 1.0 : 1.0 + m * m,
                         dk = linear_ ? 0.0 : 2.0 * m;
            values[0] += 0.5 * dk * (u_i - u_j) + k;
            columns.push_back(c);
            values.push_back(0.5 * dk * (u_i - u_j) - k);
          }
        }
        F_values[lid] = F * residual_factor_;
        if (J != nullptr)
          J->replaceLocalValues(static_cast<LO>(lid), Teuchos::arrayViewFromVector(columns),
                                Teuchos::arrayViewFromVector(values));
      }
    }
    if (J != nullptr)
      J->fillComplete();
    if (f == nullptr)
      return;
    {
      const auto f_view = f->getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (size_t lid = 0; lid < F_values.size(); ++lid)
        f_view(lid, 0) = F_values[lid];
    }
    residual_norms.push_back(f->norm2());
  }

  /// u* at every owned row.
  Vector exact_solution() const
  {
    Vector u(map_);
    for (size_t lid = 0; lid < map_->getNodeNumElements(); ++lid)
      u.replaceLocalValue(static_cast<LO>(lid),
                          u_star(map_->getGlobalElement(static_cast<LO>(lid))));
    return u;
  }

  std::vector<double> jacobian_dependencies(const Vector & /*x*/) override
  {
    ++jacobian_dependency_calls;
    return dependencies;
  }
  int jacobian_dependency_calls = 0;
  /// The linear problem's Jacobian is constant (Adaptive Linear Tolerance First does not apply).
  bool jacobian_varies() const override { return !linear_ && dependencies.empty(); }
  std::vector<double> preconditioner_dependencies(const Vector & /*x*/) override
  {
    ++preconditioner_dependency_calls;
    // The discrete dependency of a varying Jacobian changes (on every rank) at the call
    // `change_at`, within a solve.
    if (preconditioner_dependency_calls == change_at)
      preconditioner_deps.push_back(1.0);
    return preconditioner_deps;
  }
  /// What preconditioner_dependencies() answers, the calls, and the call at which it changes.
  std::vector<double> preconditioner_deps;
  int preconditioner_dependency_calls = 0;
  int change_at = -1;
  std::size_t smooth_dependencies() const override { return smooth; }
  /// The coefficient of a term shift (u - u*) of the interior rows.
  double shift = 0.0;
  /// What smooth_dependencies() answers.
  std::size_t smooth = 0;
  void jacobian_kept(const Vector & /*x*/) override { ++jacobians_kept; }
  /// J at x with shift = smooth[0] (with one smooth dependency).
  bool jacobian_with(const std::vector<double> &s, const Vector &x, Matrix &J) override
  {
    if (smooth != 1 || s.size() != 1)
      return false;
    const double own = shift;
    shift = s[0];
    evaluate(x, nullptr, &J);
    shift = own;
    --jacobian_evaluations;
    ++jacobians_with;
    return true;
  }
  int jacobians_with = 0;
  /// What jacobian_dependencies() answers.
  std::vector<double> dependencies;
  int jacobian_evaluations = 0;
  int jacobians_kept = 0;

  /// Multiplies F by this (NaN makes a problem whose residual is NaN).
  void set_residual_factor(const double factor) { residual_factor_ = factor; }

  std::vector<double> residual_norms;

private:
  std::array<int, 3> index(const GO gid) const
  {
    return {static_cast<int>(gid % n_), static_cast<int>(gid / n_ % n_),
            static_cast<int>(gid / n_ / n_)};
  }
  std::array<double, 3> point(const GO gid) const
  {
    const auto ijk = index(gid);
    const double h = 1.0 / (n_ - 1);
    return {ijk[0] * h, dim_ > 1 ? ijk[1] * h : 0.0, dim_ > 2 ? ijk[2] * h : 0.0};
  }
  bool on_boundary(const GO gid) const
  {
    const auto ijk = index(gid);
    for (int a = 0; a < dim_; ++a)
      if (ijk[a] == 0 || ijk[a] == n_ - 1)
        return true;
    return false;
  }
  std::vector<GO> neighbours(const GO gid) const
  {
    std::vector<GO> result;
    GO stride = 1;
    for (int a = 0; a < dim_; ++a, stride *= n_)
      result.insert(result.end(), {gid - stride, gid + stride});
    return result;
  }
  double u_star(const GO gid) const
  {
    const auto p = point(gid);
    return 0.5 + p[0] + 2.0 * p[1] * p[2] + std::sin(3.0 * p[0] + p[1] - p[2]);
  }
  double flux(const double u_i, const double u_j) const
  {
    const double m = 0.5 * (u_i + u_j);
    return (linear_ ? 1.0 : 1.0 + m * m) * (u_i - u_j);
  }

  int n_, dim_;
  bool linear_ = false;
  double residual_factor_ = 1.0;
  RCP<const Map> map_;
  RCP<const Graph> graph_;
  RCP<Tpetra::MultiVector<double>> coordinates_;
  std::vector<double> b_;
};

Teuchos::ParameterList solver_parameters()
{
  Teuchos::ParameterList p; // as an input gives it: NewtonSolver adds the defaults
  p.set("Absolute Tolerance", 1e-10);
  p.set("Relative Tolerance", 1e-12);
  return p;
}

RCP<Teuchos::FancyOStream> quiet()
{
  return Teuchos::getFancyOStream(Teuchos::rcp(new Teuchos::oblackholestream));
}

struct Outcome
{
  NewtonSolver::Result result;
  std::vector<double> residual_norms;
  double error = 0.0; ///< max |u - u*| / max |u*|
};

Outcome solve(const RCP<const Teuchos::Comm<int>> &comm, const int n, const int dim,
              const Teuchos::ParameterList &params = solver_parameters(), const double factor = 1.0)
{
  auto problem = Teuchos::rcp(new NonlinearDiffusion(comm, n, dim));
  problem->set_residual_factor(factor);
  NewtonSolver solver(params, problem, quiet());
  NonlinearProblem::Vector x(problem->solution_map());
  Outcome outcome;
  outcome.result = solver.solve(x);
  outcome.residual_norms = problem->residual_norms;
  NonlinearProblem::Vector u_star = problem->exact_solution();
  const double scale = u_star.normInf();
  u_star.update(1.0, x, -1.0);
  outcome.error = u_star.normInf() / scale;
  return outcome;
}

class NewtonSolverTest : public testing::Test
{
protected:
  RCP<const Teuchos::Comm<int>> comm = Teuchos::DefaultComm<int>::getComm();
};

TEST_F(NewtonSolverTest, ConvergesQuadraticallyToTheManufacturedSolution)
{
  for (const int dim : {1, 3})
  {
    SCOPED_TRACE("dim " + std::to_string(dim));
    const Outcome run = solve(comm, dim == 1 ? 101 : 12, dim);
    const auto &r = run.residual_norms;
    ASSERT_TRUE(run.result.converged);
    EXPECT_LT(run.error, 1e-9);
    EXPECT_GE(run.result.newton_iterations, 3);
    EXPECT_LE(run.result.newton_iterations, 8);
    // One residual per Newton iterate, and the result reports the first and the last.
    ASSERT_EQ(static_cast<int>(r.size()), run.result.newton_iterations + 1);
    EXPECT_DOUBLE_EQ(run.result.initial_residual_norm, r.front());
    EXPECT_DOUBLE_EQ(run.result.final_residual_norm, r.back());
    EXPECT_LE(r.back(), std::max(1e-10, 1e-12 * r.front()));
    // Quadratic: once in the asymptotic range, the order estimate
    // log(r_{k+1}/r_0) / log(r_k/r_0) is near 2 (while above the linear
    // solver's relative tolerance, 1e-10).
    int checked = 0;
    for (size_t k = 1; k + 1 < r.size(); ++k)
    {
      EXPECT_LT(r[k + 1], r[k]);
      const double e_k = r[k] / r[0], e_next = r[k + 1] / r[0];
      if (e_k < 1e-2 && e_next > 1e-9)
      {
        const double order = std::log(e_next) / std::log(e_k);
        EXPECT_GT(order, 1.6) << "k = " << k;
        EXPECT_LT(order, 2.6) << "k = " << k;
        ++checked;
      }
    }
    EXPECT_GE(checked, 1);
    // Belos + MueLu: a few iterations per linear solve.
    EXPECT_GE(run.result.linear_iterations, run.result.newton_iterations);
    EXPECT_LE(run.result.linear_iterations, 30 * run.result.newton_iterations);
  }
}

TEST_F(NewtonSolverTest, SameIteratesOnOneRankAndOnAll)
{
  const int n = 12, dim = 3;
  const Outcome all = solve(comm, n, dim);
  // The same problem on this rank alone.
  const RCP<const Teuchos::Comm<int>> self = comm->split(comm->getRank(), 0);
  ASSERT_EQ(self->getSize(), 1);
  const Outcome one = solve(self, n, dim);
  ASSERT_TRUE(all.result.converged);
  ASSERT_TRUE(one.result.converged);
  EXPECT_EQ(all.result.newton_iterations, one.result.newton_iterations);
  ASSERT_EQ(all.residual_norms.size(), one.residual_norms.size());
  const double r0 = one.residual_norms.front();
  EXPECT_NEAR(all.residual_norms.front(), r0, 1e-13 * r0);
  // Newton steps agree up to the linear solver's tolerance (1e-10 relative).
  for (size_t k = 1; k < one.residual_norms.size(); ++k)
    EXPECT_NEAR(all.residual_norms[k], one.residual_norms[k], 1e-8 * r0) << "k = " << k;
  EXPECT_LT(all.error, 1e-9);
  EXPECT_LT(one.error, 1e-9);
}

TEST_F(NewtonSolverTest, AlreadyConvergedNeedsNoIteration)
{
  auto problem = Teuchos::rcp(new NonlinearDiffusion(comm, 21, 1));
  NewtonSolver solver(solver_parameters(), problem, quiet());
  NonlinearProblem::Vector x = problem->exact_solution();
  const NewtonSolver::Result result = solver.solve(x);
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(result.newton_iterations, 0);
  EXPECT_EQ(result.linear_iterations, 0);
  EXPECT_LT(result.final_residual_norm, 1e-10);
  // The solver can be used again, from another initial guess.
  x.putScalar(0.0);
  const NewtonSolver::Result again = solver.solve(x);
  EXPECT_TRUE(again.converged);
  EXPECT_GE(again.newton_iterations, 3);
}

TEST_F(NewtonSolverTest, BelosOptionsFromTheInputTakeEffect)
{
  const Outcome reference = solve(comm, 12, 3);
  ASSERT_TRUE(reference.result.converged);
  Teuchos::ParameterList p = solver_parameters();
  Teuchos::ParameterList &gmres = p.sublist("Linear Solver")
                                      .sublist("Linear Solver Types")
                                      .sublist("Belos")
                                      .sublist("Solver Types")
                                      .sublist("Block GMRES");
  gmres.set("Maximum Iterations", 1);
  gmres.set("Convergence Tolerance", 1e-14);
  // A multigrid, whose Krylov solves take more than one iteration (this small problem would
  // get Direct's exact factors).
  p.sublist("Linear Solver").set("Preconditioner Type", "MueLu");
  p.set("Maximum Iterations", 6);
  const Outcome limited = solve(comm, 12, 3, p);
  // A failed linear solve does not throw: Newton goes on with the inexact step
  // and, with one Krylov iteration per step, stops at its iteration limit.
  EXPECT_FALSE(limited.result.converged);
  EXPECT_EQ(limited.result.newton_iterations, 6);
  EXPECT_EQ(limited.result.linear_iterations, limited.result.newton_iterations);
  EXPECT_LT(limited.result.final_residual_norm, limited.result.initial_residual_norm);
}

/// On a linear problem one Newton iteration solves the step; with the adaptive tolerance its
/// Krylov solve stops at Safety times the Newton target instead of Belos' 1e-10 (the default
/// Safety, 0.001, and 0.1).
TEST_F(NewtonSolverTest, AdaptiveLinearToleranceStopsAtTheNewtonTarget)
{
  const auto run = [&](const bool adaptive, const double safety)
  {
    auto problem = Teuchos::rcp(new NonlinearDiffusion(comm, 12, 3, true));
    Teuchos::ParameterList p = solver_parameters();
    p.set("Absolute Tolerance", 1e-3);
    p.set("Adaptive Linear Tolerance", adaptive);
    p.sublist("Linear Solver").set("Preconditioner Type", "MueLu"); // iterations to stop
    if (safety > 0.0)
      p.set("Adaptive Linear Tolerance Safety", safety);
    NewtonSolver solver(p, problem, quiet());
    NonlinearProblem::Vector x(problem->solution_map());
    return solver.solve(x);
  };
  const NewtonSolver::Result tight = run(false, 0.0);
  ASSERT_TRUE(tight.converged);
  ASSERT_GT(tight.initial_residual_norm, 1e4 * tight.tolerance);
  EXPECT_EQ(tight.newton_iterations, 1);
  // Belos' 1e-10 of ||F(x0)||.
  EXPECT_LT(tight.final_residual_norm, 1e-9 * tight.initial_residual_norm);
  int previous_iterations = 0;
  for (const double safety : {0.001, 0.1})
  {
    const NewtonSolver::Result adapted = run(true, safety == 0.001 ? 0.0 : safety);
    ASSERT_TRUE(adapted.converged);
    EXPECT_EQ(adapted.newton_iterations, 1);
    EXPECT_LT(adapted.final_residual_norm, safety * adapted.tolerance * 1.01) << safety;
    EXPECT_GT(adapted.final_residual_norm, 1e-9 * adapted.initial_residual_norm) << safety;
    EXPECT_LT(adapted.linear_iterations, tight.linear_iterations) << safety;
    // A looser safety, fewer iterations.
    if (previous_iterations > 0)
    {
      EXPECT_LT(adapted.linear_iterations, previous_iterations);
    }
    previous_iterations = adapted.linear_iterations;
  }
}

/// Adaptive Linear Tolerance Rate: on the nonlinear problem (its Jacobian varies) the Krylov
/// solves after the first stop at rate times the square of the last reduction: fewer Krylov
/// iterations, the same Newton iterations and tolerance, the same solution to it.
TEST_F(NewtonSolverTest, AdaptiveLinearToleranceRateSavesKrylovIterationsOfANonlinearSolve)
{
  const auto run = [&](const double rate, NonlinearProblem::Vector &x)
  {
    auto problem = Teuchos::rcp(new NonlinearDiffusion(comm, 12, 3));
    Teuchos::ParameterList p = solver_parameters();
    p.set("Absolute Tolerance", 1e-8);
    p.set("Relative Tolerance", 1e-8);
    p.set("Adaptive Linear Tolerance Rate", rate);
    p.sublist("Linear Solver").set("Preconditioner Type", "MueLu");
    NewtonSolver solver(p, problem, quiet());
    x = NonlinearProblem::Vector(problem->solution_map());
    const NewtonSolver::Result r = solver.solve(x);
    x.update(-1.0, problem->exact_solution(), 1.0);
    return r;
  };
  NonlinearProblem::Vector error_off, error_on;
  const NewtonSolver::Result off = run(0.0, error_off);
  const NewtonSolver::Result on = run(0.01, error_on);
  ASSERT_TRUE(off.converged);
  ASSERT_TRUE(on.converged);
  ASSERT_GE(off.newton_iterations, 3);
  EXPECT_EQ(on.newton_iterations, off.newton_iterations);
  EXPECT_LE(on.final_residual_norm, on.tolerance);
  EXPECT_LT(on.linear_iterations, off.linear_iterations);
  EXPECT_LT(error_on.normInf(), 1e-7);
  EXPECT_LT(error_off.normInf(), 1e-7);
}

// Adaptive Linear Tolerance First (default 1e-3) loosens the first Krylov solve of a varying
// Jacobian's solve from the last state (fewer Krylov iterations, the same answer to the Newton
// tolerance), but not of a solve that starts at a predictor (Extrapolated Newton Start), whose
// first iteration may be its last: that one is the same with and without it.
TEST_F(NewtonSolverTest, FirstForcingTermOnlyWhereNewtonStartsFromTheLastState)
{
  const auto run = [&](const double first, const bool predictor, NonlinearProblem::Vector &x)
  {
    auto problem = Teuchos::rcp(new NonlinearDiffusion(comm, 12, 3));
    Teuchos::ParameterList p = solver_parameters();
    p.set("Absolute Tolerance", 1e-8);
    p.set("Relative Tolerance", 1e-8);
    p.set("Adaptive Linear Tolerance First", first);
    p.sublist("Linear Solver").set("Preconditioner Type", "MueLu");
    EXPECT_EQ(Teuchos::ParameterList(NewtonSolver::valid_parameters())
                  .get<double>("Adaptive Linear Tolerance First"),
              1e-3); // the default
    NewtonSolver solver(p, problem, quiet());
    x = NonlinearProblem::Vector(problem->solution_map());
    // The predictor: half the way to the solution.
    NonlinearProblem::Vector half = problem->exact_solution();
    half.scale(0.5);
    const NewtonSolver::Result r = solver.solve(x, predictor ? &half : nullptr, predictor);
    x.update(-1.0, problem->exact_solution(), 1.0);
    return r;
  };
  for (const bool predictor : {false, true})
  {
    NonlinearProblem::Vector error_off, error_on;
    const NewtonSolver::Result off = run(0.0, predictor, error_off);
    const NewtonSolver::Result on = run(1e-3, predictor, error_on);
    ASSERT_TRUE(off.converged) << predictor;
    ASSERT_TRUE(on.converged) << predictor;
    ASSERT_GE(off.newton_iterations, 3) << predictor;
    EXPECT_LT(error_on.normInf(), 1e-7) << predictor;
    EXPECT_LT(error_off.normInf(), 1e-7) << predictor;
    if (predictor)
    {
      EXPECT_EQ(on.linear_iterations, off.linear_iterations);
      EXPECT_EQ(on.final_residual_norm, off.final_residual_norm);
    }
    else
    {
      EXPECT_LT(on.linear_iterations, off.linear_iterations);
      EXPECT_LE(on.newton_iterations, off.newton_iterations + 1);
    }
  }
}

TEST_F(NewtonSolverTest, Ifpack2PreconditionerCanBeChosen)
{
  Teuchos::ParameterList p = solver_parameters();
  Teuchos::ParameterList &linear = p.sublist("Linear Solver");
  linear.set("Preconditioner Type", "Ifpack2");
  linear.sublist("Preconditioner Types").sublist("Ifpack2").set("Prec Type", "RELAXATION");
  linear.sublist("Preconditioner Types")
      .sublist("Ifpack2")
      .sublist("Ifpack2 Settings")
      .set("relaxation: type", "Symmetric Gauss-Seidel");
  const Outcome run = solve(comm, 8, 3, p);
  EXPECT_TRUE(run.result.converged);
  EXPECT_LT(run.error, 1e-9);
  EXPECT_GT(run.result.linear_iterations, run.result.newton_iterations);
}

TEST_F(NewtonSolverTest, NanResidualIsNotConverged)
{
  const Outcome run =
      solve(comm, 21, 1, solver_parameters(), std::numeric_limits<double>::quiet_NaN());
  EXPECT_FALSE(run.result.converged);
  EXPECT_EQ(run.result.newton_iterations, 0);
  EXPECT_TRUE(std::isnan(run.result.initial_residual_norm));
}

TEST_F(NewtonSolverTest, MaximumIterationsIsNotConverged)
{
  Teuchos::ParameterList p = solver_parameters();
  p.set("Maximum Iterations", 2);
  const Outcome run = solve(comm, 12, 3, p);
  EXPECT_FALSE(run.result.converged);
  EXPECT_EQ(run.result.newton_iterations, 2);
  EXPECT_GT(run.error, 1e-6);
}

/// The message of the InputError that constructing a solver with `p` throws.
std::string input_error(const RCP<const Teuchos::Comm<int>> &comm, const Teuchos::ParameterList &p)
{
  auto problem = Teuchos::rcp(new NonlinearDiffusion(comm, 11, 1));
  const std::string message =
      kiln_test::input_error_message([&] { NewtonSolver solver(p, problem, quiet()); });
  return message.empty() ? "no InputError" : message;
}

TEST_F(NewtonSolverTest, InvalidOptionsAreInputErrors)
{
  using testing::HasSubstr;
  using testing::StartsWith;
  {
    Teuchos::ParameterList p = solver_parameters();
    p.sublist("Linear Solver")
        .sublist("Linear Solver Types")
        .sublist("Belos")
        .set("Solver Type", "No Such Solver");
    const std::string message = input_error(comm, p);
    EXPECT_THAT(message, StartsWith("Solver/Linear Solver/Linear Solver Types/Belos/\"Solver "
                                    "Type\" = No Such Solver: not one of the choices of Belos."));
    EXPECT_THAT(message, HasSubstr("\"Pseudo Block GMRES\"")); // the choices listed
  }
  {
    Teuchos::ParameterList p = solver_parameters();
    p.sublist("Linear Solver").set("Preconditioner Type", "No Such Preconditioner");
    const std::string message = input_error(comm, p);
    EXPECT_THAT(message, StartsWith("Solver/Linear Solver/\"Preconditioner Type\" = No Such "
                                    "Preconditioner: not one of the choices of Stratimikos."));
    EXPECT_THAT(message, HasSubstr("\"Ifpack2\"")); // listed among the valid values
  }
  {
    Teuchos::ParameterList p = solver_parameters();
    p.sublist("Linear Solver")
        .sublist("Preconditioner Types")
        .sublist("MueLu")
        .set("smoother: tpye", "CHEBYSHEV");
    const std::string message = input_error(comm, p);
    EXPECT_THAT(message, StartsWith("Solver/Linear Solver/Preconditioner Types/MueLu: "));
    EXPECT_THAT(message, HasSubstr("Did you mean \"smoother: type\"?"));
    EXPECT_THAT(message, testing::Not(HasSubstr("Throw number")));
  }
  {
    Teuchos::ParameterList p = solver_parameters();
    p.sublist("Nonlinear Solver").sublist("Direction").set("Method", "No Such Direction");
    const std::string message = input_error(comm, p);
    EXPECT_THAT(message, StartsWith("Solver/Nonlinear Solver/Direction/\"Method\" = No Such "
                                    "Direction: not one of the choices of NOX. Choices: "
                                    "\"Newton\", \"Steepest Descent\""));
  }
  {
    // Belos reads the names it knows from its solver's list and ignores the others.
    Teuchos::ParameterList p = solver_parameters();
    p.sublist("Linear Solver")
        .sublist("Linear Solver Types")
        .sublist("Belos")
        .sublist("Solver Types")
        .sublist("Block GMRES")
        .set("Convergence Tolerence", 1e-9);
    const std::string message = input_error(comm, p);
    EXPECT_THAT(message, StartsWith("Solver/Linear Solver/Linear Solver Types/Belos/Solver "
                                    "Types/Block GMRES/\"Convergence Tolerence\": unknown "
                                    "parameter of Belos. Did you mean \"Convergence "
                                    "Tolerance\"? Valid names here: \"Convergence Tolerance\""));
    EXPECT_THAT(message, HasSubstr("correct it or remove it"));
    EXPECT_THAT(message, testing::Not(HasSubstr("Output Stream"))); // not from an input
  }
  {
    Teuchos::ParameterList p = solver_parameters();
    p.sublist("Linear Solver")
        .sublist("Linear Solver Types")
        .sublist("Belos")
        .sublist("Solver Types")
        .sublist("Block CG")
        .set("Maximum Iterations", 10.0);
    EXPECT_THAT(input_error(comm, p),
                HasSubstr("Solver Types/Block CG/\"Maximum Iterations\": expected type "
                          "\"int\", got type \"double\""));
  }
  {
    Teuchos::ParameterList p = solver_parameters();
    p.sublist("Linear Solver").sublist("Linear Solver Types").sublist("Bellos");
    EXPECT_THAT(input_error(comm, p),
                StartsWith("Solver/Linear Solver/Linear Solver Types/\"Bellos\": unknown "
                           "sublist of Stratimikos. Did you mean \"Belos\"?"));
  }
  {
    // Belos reads only the chosen solver's sublist: one filled for another is an error.
    Teuchos::ParameterList p; // as read from an input: Kiln's defaults are added
    Teuchos::ParameterList &belos =
        p.sublist("Linear Solver").sublist("Linear Solver Types").sublist("Belos");
    belos.sublist("Solver Types").sublist("Pseudo Block GMRES").set("Num Blocks", 50);
    EXPECT_EQ(input_error(comm, p),
              "Solver/Linear Solver/Linear Solver Types/Belos/Solver Types/Pseudo Block GMRES: "
              "parameters for \"Pseudo Block GMRES\", but the \"Solver Type\" beside \"Solver "
              "Types\" is \"Block GMRES\" (Kiln's default), so Belos would ignore them; set "
              "\"Solver Type\" to \"Pseudo Block GMRES\" or move them to Solver Types/\"Block "
              "GMRES\"");
    belos.set("Solver Type", "Pseudo Block GMRES");
    EXPECT_EQ(input_error(comm, p), "no InputError");
    belos.set("Solver Type", "Block CG");
    EXPECT_THAT(input_error(comm, p), HasSubstr("is \"Block CG\", so Belos would ignore them"));
    // Kiln's defaults for the solver it would have used do not count as the input's.
    belos.sublist("Solver Types").remove("Pseudo Block GMRES");
    EXPECT_EQ(input_error(comm, p), "no InputError");
  }
  {
    // So does NOX, for its line search: Kiln's default method is named as such.
    Teuchos::ParameterList p;
    p.sublist("Nonlinear Solver").sublist("Line Search").sublist("Polynomial").set("Max Iters", 5);
    EXPECT_THAT(input_error(comm, p),
                StartsWith("Solver/Nonlinear Solver/Line Search/Polynomial: parameters for "
                           "\"Polynomial\", but the \"Method\" beside them is \"Full Step\" "
                           "(Kiln's default), so NOX would ignore them"));
  }
  {
    // Stratimikos reads only the chosen solver's and preconditioner's sublists.
    Teuchos::ParameterList p;
    Teuchos::ParameterList &linear = p.sublist("Linear Solver");
    linear.sublist("Linear Solver Types").sublist("Amesos2").set("Solver Type", "KLU2");
    EXPECT_THAT(input_error(comm, p),
                StartsWith("Solver/Linear Solver/Linear Solver Types/Amesos2: parameters for "
                           "\"Amesos2\", but the \"Linear Solver Type\" beside \"Linear Solver "
                           "Types\" is \"Belos\" (Kiln's default), so Stratimikos would ignore "
                           "them"));
    linear.set("Linear Solver Type", "Amesos2");
    EXPECT_EQ(input_error(comm, p), "no InputError");
  }
  {
    Teuchos::ParameterList p;
    Teuchos::ParameterList &linear = p.sublist("Linear Solver");
    Teuchos::ParameterList &types = linear.sublist("Preconditioner Types");
    types.sublist("Ifpack2").set("Prec Type", "ILUT");
    EXPECT_THAT(input_error(comm, p),
                StartsWith("Solver/Linear Solver/Preconditioner Types/Ifpack2: parameters for "
                           "\"Ifpack2\", but the \"Preconditioner Type\" beside \"Preconditioner "
                           "Types\" is \"Direct\" (Kiln's default)"));
    types.remove("Ifpack2");
    // Kiln picks MueLu, Block Triangular or Direct by the problem: any of their lists may be
    // read.
    types.sublist("Block Triangular").sublist("Displacement").set("smoother: type", "CHEBYSHEV");
    types.sublist("MueLu").set("coarse: max size", 100);
    EXPECT_EQ(input_error(comm, p), "no InputError");
    linear.set("Preconditioner Type", "MueLu"); // named: Block Triangular's list is not read
    EXPECT_THAT(input_error(comm, p),
                StartsWith("Solver/Linear Solver/Preconditioner Types/Block Triangular: "
                           "parameters for \"Block Triangular\", but the \"Preconditioner "
                           "Type\" beside \"Preconditioner Types\" is \"MueLu\", so"));
    linear.set("Preconditioner Type", "Ifpack2");
    EXPECT_THAT(input_error(comm, p), StartsWith("Solver/Linear Solver/Preconditioner Types/"));
  }
  {
    // The block's name in messages is the caller's.
    Teuchos::ParameterList p = solver_parameters();
    p.sublist("Nonlinear Solver").sublist("Line Search").set("Methd", "Backtrack");
    auto problem = Teuchos::rcp(new NonlinearDiffusion(comm, 11, 1));
    EXPECT_THAT(kiln_test::input_error_message(
                    [&] { NewtonSolver solver(p, problem, quiet(), "in.xml: Kiln/Solver"); }),
                StartsWith("in.xml: Kiln/Solver/Nonlinear Solver/Line Search/\"Methd\": unknown "
                           "parameter of NOX. Did you mean \"Method\"?"));
  }
  {
    Teuchos::ParameterList p; // as read from an input: no validators
    p.set("Absolute Tolerance", -1.0);
    EXPECT_THAT(input_error(comm, p), HasSubstr("\"Absolute Tolerance\""));
  }
}

/// Not a test: Belos + MueLu iterations per linear solve with the default
/// parameters (or those of the "Solver" block in the file KILN_BENCH_XML) on
/// the 3D problem, n^3 nodes (KILN_BENCH_N, default 20), e.g.
///   mpirun -np 2 unit_newton_solver --gtest_also_run_disabled_tests
///     --gtest_filter='*Iterations*'
TEST_F(NewtonSolverTest, DISABLED_IterationsPerLinearSolve)
{
  const char *env = std::getenv("KILN_BENCH_N");
  const int n = env != nullptr ? std::atoi(env) : 20;
  auto problem = Teuchos::rcp(new NonlinearDiffusion(comm, n, 3));
  Teuchos::ParameterList p = NewtonSolver::valid_parameters();
  if (const char *xml = std::getenv("KILN_BENCH_XML"); xml != nullptr) // a "Solver" block
    Teuchos::updateParametersFromXmlFileAndBroadcast(xml, Teuchos::ptrFromRef(p), *comm);
  NewtonSolver solver(p, problem, quiet());
  NonlinearProblem::Vector x(problem->solution_map());
  const auto start = std::chrono::steady_clock::now();
  const NewtonSolver::Result r = solver.solve(x);
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  if (comm->getRank() == 0)
    std::cout << "n = " << n << "^3, np = " << comm->getSize() << ": converged " << r.converged
              << ", Newton " << r.newton_iterations << ", linear " << r.linear_iterations << " ("
              << static_cast<double>(r.linear_iterations) / r.newton_iterations
              << " per solve), ||F|| " << r.initial_residual_norm << " -> " << r.final_residual_norm
              << ", " << seconds.count() << " s\n";
  EXPECT_TRUE(r.converged);
}
} // namespace

/// Solve/"Reuse": the Jacobian and the preconditioner are kept while the problem's
/// dependencies are unchanged on every rank, and built anew otherwise.
class JacobianReuseTest : public NewtonSolverTest
{
protected:
  RCP<NonlinearDiffusion> problem = Teuchos::rcp(new NonlinearDiffusion(comm, 9, 3, true));
  /// Solves from x = 0; checks the solution.
  NewtonSolver::Result solve_once(NewtonSolver &solver)
  {
    NonlinearProblem::Vector x(problem->solution_map());
    const NewtonSolver::Result result = solver.solve(x);
    NonlinearProblem::Vector error = problem->exact_solution();
    error.update(1.0, x, -1.0);
    EXPECT_TRUE(result.converged);
    EXPECT_LT(error.normInf(), 1e-8);
    return result;
  }
};

TEST_F(JacobianReuseTest, KeptWhileTheDependenciesAreUnchanged)
{
  problem->dependencies = {1.0, 2.0};
  NewtonSolver solver(solver_parameters(), problem, quiet());
  const NewtonSolver::Result first = solve_once(solver);
  // One Jacobian per Newton iteration, the first evaluated, the others kept.
  ASSERT_GE(first.newton_iterations, 1);
  EXPECT_EQ(first.jacobians_evaluated, 1);
  EXPECT_EQ(first.preconditioners_built, 1);
  EXPECT_EQ(first.jacobians_kept, first.newton_iterations - 1);
  EXPECT_EQ(first.preconditioners_kept, first.newton_iterations - 1);
  const NewtonSolver::Result second = solve_once(solver);
  EXPECT_EQ(second.jacobians_evaluated, 0);
  EXPECT_EQ(second.jacobians_kept, second.newton_iterations);
  EXPECT_EQ(second.preconditioners_built, 0);
  EXPECT_EQ(second.preconditioners_kept, second.newton_iterations);
  EXPECT_EQ(second.linear_iterations, first.linear_iterations);
  EXPECT_EQ(problem->jacobian_evaluations, 1);
  EXPECT_EQ(problem->jacobians_kept, first.newton_iterations + second.newton_iterations - 1);

  problem->dependencies = {1.0, 3.0};
  const NewtonSolver::Result changed = solve_once(solver);
  EXPECT_EQ(changed.jacobians_evaluated, 1);
  EXPECT_EQ(changed.preconditioners_built, 1);
}

TEST_F(JacobianReuseTest, NeverKeptWithoutDependencies)
{
  NewtonSolver solver(solver_parameters(), problem, quiet());
  solve_once(solver);
  const NewtonSolver::Result second = solve_once(solver);
  EXPECT_EQ(second.jacobians_evaluated, second.newton_iterations);
  EXPECT_EQ(second.jacobians_kept, 0);
  EXPECT_EQ(second.preconditioners_built, second.newton_iterations);
}

TEST_F(JacobianReuseTest, NeverKeptWithReuseOff)
{
  problem->dependencies = {1.0};
  Teuchos::ParameterList p = solver_parameters();
  p.set("Reuse", false);
  NewtonSolver solver(p, problem, quiet());
  solve_once(solver);
  const NewtonSolver::Result second = solve_once(solver);
  EXPECT_EQ(second.jacobians_evaluated, second.newton_iterations);
  EXPECT_EQ(second.preconditioners_built, second.newton_iterations);
  EXPECT_EQ(problem->jacobians_kept, 0);
}

/// With Reuse off, a Jacobian is never kept on any rank: the problem's dependencies are asked
/// (and reduced over the ranks) only when Adaptive Linear Tolerance Rate needs to know
/// whether the Jacobian varies.
TEST_F(JacobianReuseTest, ReuseOffAsksNoDependenciesUnlessTheToleranceRateNeedsThem)
{
  problem->dependencies = {1.0};
  Teuchos::ParameterList p = solver_parameters();
  p.set("Reuse", false);
  p.set("Adaptive Linear Tolerance Rate", 0.0);
  {
    NewtonSolver solver(p, problem, quiet());
    const NewtonSolver::Result r = solve_once(solver);
    EXPECT_EQ(r.jacobians_evaluated, r.newton_iterations);
    EXPECT_EQ(problem->jacobian_dependency_calls, 0);
  }
  p.set("Adaptive Linear Tolerance Rate", 0.01);
  problem->jacobian_dependency_calls = 0;
  NewtonSolver solver(p, problem, quiet());
  const NewtonSolver::Result r = solve_once(solver);
  EXPECT_EQ(r.jacobians_evaluated, r.newton_iterations);
  EXPECT_EQ(r.jacobians_kept, 0);
  EXPECT_EQ(problem->jacobian_dependency_calls, r.jacobians_evaluated);
}

/// Solver/"Preconditioner Reuse Tolerance": a Jacobian whose smooth coefficient changed is
/// evaluated anew, but keeps the preconditioner while the coefficient stays within a factor
/// 1 + tolerance of the one it was built for and the other dependencies are equal; the
/// solution is that of the new Jacobian.
TEST_F(JacobianReuseTest, PreconditionerKeptWhileTheCoefficientStaysNear)
{
  problem->smooth = 1;
  problem->shift = 4.0;
  problem->dependencies = {4.0, 2.0};
  Teuchos::ParameterList p = solver_parameters();
  p.set("Preconditioner Reuse Tolerance", 1.0);
  NewtonSolver solver(p, problem, quiet());
  EXPECT_EQ(solve_once(solver).preconditioners_built, 1);

  const auto solve_with = [&](const double shift, const double discrete)
  {
    problem->shift = shift;
    problem->dependencies = {shift, discrete};
    return solve_once(solver);
  };
  // Within a factor 2 of 4 (tolerance 1): evaluated, preconditioner kept.
  const NewtonSolver::Result near = solve_with(7.0, 2.0);
  EXPECT_EQ(near.jacobians_evaluated, 1);
  EXPECT_EQ(near.preconditioners_built, 0);
  EXPECT_EQ(near.preconditioners_kept, near.newton_iterations);
  EXPECT_EQ(solve_with(2.5, 2.0).preconditioners_built, 0);
  // Measured against the coefficient it was built for (4), not the last one (2.5).
  EXPECT_EQ(solve_with(8.5, 2.0).preconditioners_built, 1);
  EXPECT_EQ(solve_with(5.0, 2.0).preconditioners_built, 0);
  // Another discrete dependency: built anew.
  EXPECT_EQ(solve_with(5.5, 3.0).preconditioners_built, 1);
  // The same dependencies: the Jacobian is kept too.
  const NewtonSolver::Result same = solve_with(5.5, 3.0);
  EXPECT_EQ(same.jacobians_evaluated, 0);
  EXPECT_EQ(same.preconditioners_built, 0);
}

/// The default, 1, keeps the preconditioner for a coefficient 12% larger; 0 builds one for
/// every new Jacobian.
TEST_F(JacobianReuseTest, PreconditionerKeptForANearCoefficientByDefault)
{
  for (const bool by_default : {true, false})
  {
    problem->smooth = 1;
    problem->shift = 4.0;
    problem->dependencies = {4.0};
    Teuchos::ParameterList p = solver_parameters();
    if (!by_default)
      p.set("Preconditioner Reuse Tolerance", 0.0);
    NewtonSolver solver(p, problem, quiet());
    solve_once(solver);
    problem->shift = 4.5;
    problem->dependencies = {4.5};
    const NewtonSolver::Result changed = solve_once(solver);
    EXPECT_EQ(changed.jacobians_evaluated, 1);
    EXPECT_EQ(changed.preconditioners_built, by_default ? 0 : 1);
  }
}

/// A restarted run given the record a checkpoint keeps (preconditioner_origin()) builds its
/// first preconditioner from the Jacobian the uninterrupted run built the one it keeps from,
/// so it solves to the same bits; without the record, or with a record whose discrete
/// dependencies differ, it builds one from its own Jacobian.
TEST_F(JacobianReuseTest, RestartBuildsThePreconditionerTheRunKept)
{
  problem->smooth = 1;
  const auto set = [&](const double shift, const double discrete)
  {
    problem->shift = shift;
    problem->dependencies = {shift, discrete};
  };
  set(4.0, 2.0);
  NewtonSolver run(solver_parameters(), problem, quiet());
  solve_once(run);
  const std::vector<double> record = run.preconditioner_origin();
  ASSERT_FALSE(record.empty());
  set(6.0, 2.0);
  NonlinearProblem::Vector x_run(problem->solution_map());
  const NewtonSolver::Result kept = run.solve(x_run);
  ASSERT_EQ(kept.preconditioners_built, 0);
  EXPECT_EQ(problem->jacobians_with, 0);

  // max |x - x_run| of a new solver given `given`, and its counts.
  const auto restarted = [&](const std::vector<double> &given, NewtonSolver::Result &r)
  {
    NewtonSolver solver(solver_parameters(), problem, quiet());
    solver.restore_preconditioner_origin(given);
    NonlinearProblem::Vector x(problem->solution_map());
    r = solver.solve(x);
    x.update(-1.0, x_run, 1.0);
    return x.normInf();
  };
  NewtonSolver::Result r;
  EXPECT_EQ(restarted(record, r), 0.0);
  EXPECT_EQ(r.linear_iterations, kept.linear_iterations);
  EXPECT_EQ(r.preconditioners_built, 1);
  EXPECT_EQ(problem->jacobians_with, 2); // at 4, then back at 6
  // Built at 6: the same solution to the solver's tolerance, not to the bit.
  EXPECT_GT(restarted({}, r), 0.0);
  EXPECT_EQ(problem->jacobians_with, 2);
  // The record of a run whose discrete dependency differed (on one rank).
  if (comm->getRank() == comm->getSize() - 1)
    problem->dependencies = {6.0, 3.0};
  EXPECT_GT(restarted(record, r), 0.0);
  EXPECT_EQ(problem->jacobians_with, 2);
  // Nothing kept, nothing recorded; a record is not used without reuse.
  for (const char *off : {"Preconditioner Reuse Tolerance", "Reuse"})
  {
    Teuchos::ParameterList p = solver_parameters();
    if (std::string(off) == "Reuse")
      p.set(off, false);
    else
      p.set(off, 0.0);
    NewtonSolver without(p, problem, quiet());
    without.restore_preconditioner_origin(record);
    solve_once(without);
    EXPECT_TRUE(without.preconditioner_origin().empty()) << off;
    EXPECT_EQ(problem->jacobians_with, 2) << off;
  }
}

/// Keep Preconditioner Within Solve: a Jacobian that varies with x (no jacobian
/// dependencies) is evaluated at every Newton iteration, and keeps the preconditioner of the
/// solve's first while the preconditioner dependencies are unchanged; a new solve builds one.
class KeepPreconditionerWithinSolveTest : public NewtonSolverTest
{
protected:
  RCP<NonlinearDiffusion> problem = Teuchos::rcp(new NonlinearDiffusion(comm, 9, 3));
  NewtonSolver::Result solve_with(NewtonSolver &solver)
  {
    NonlinearProblem::Vector x(problem->solution_map());
    const NewtonSolver::Result r = solver.solve(x);
    x.update(-1.0, problem->exact_solution(), 1.0);
    EXPECT_TRUE(r.converged);
    EXPECT_LT(x.normInf(), 1e-8);
    return r;
  }
  Teuchos::ParameterList parameters(const bool keep, const char *preconditioner = "MueLu")
  {
    Teuchos::ParameterList p = solver_parameters();
    p.set("Keep Preconditioner Within Solve", keep);
    // Each solve on its own (KeepPreconditionerAcrossStepsTest keeps one across solves).
    p.set("Keep Preconditioner Across Steps", false);
    p.sublist("Linear Solver").set("Preconditioner Type", preconditioner);
    return p;
  }
};

TEST_F(KeepPreconditionerWithinSolveTest, OnePreconditionerPerSolveOnceNewtonConverges)
{
  problem->preconditioner_deps = {2.0};
  for (const char *preconditioner : {"MueLu", "Direct"})
  {
    NewtonSolver solver(parameters(true, preconditioner), problem, quiet());
    for (int solve = 0; solve < 2; ++solve)
    {
      problem->residual_norms.clear();
      const NewtonSolver::Result r = solve_with(solver);
      ASSERT_GE(r.newton_iterations, 4) << preconditioner;
      EXPECT_EQ(r.jacobians_evaluated, r.newton_iterations) << preconditioner;
      EXPECT_EQ(r.jacobians_kept, 0) << preconditioner;
      // From u = 0 the first Newton step raises ||F|| (43 -> 131): the second iteration
      // builds anew (the guard: ||F|| not halved); from then on ||F|| falls fast and the
      // second iteration's preconditioner serves the rest of the solve.
      ASSERT_GT(problem->residual_norms.at(1), problem->residual_norms.at(0));
      EXPECT_EQ(r.preconditioners_built, 2) << preconditioner;
      EXPECT_EQ(r.preconditioners_kept, r.newton_iterations - 2) << preconditioner;
    }
  }
}

TEST_F(KeepPreconditionerWithinSolveTest, OnePerIterationWhenOffOrWithoutDependencies)
{
  problem->preconditioner_deps = {2.0};
  NewtonSolver off(parameters(false), problem, quiet());
  NewtonSolver::Result r = solve_with(off);
  EXPECT_EQ(r.preconditioners_built, r.newton_iterations);
  EXPECT_EQ(r.preconditioners_kept, 0);
  // Reuse false turns it off too.
  Teuchos::ParameterList no_reuse = parameters(true);
  no_reuse.set("Reuse", false);
  NewtonSolver without_reuse(no_reuse, problem, quiet());
  r = solve_with(without_reuse);
  EXPECT_EQ(r.preconditioners_built, r.newton_iterations);
  // A problem that names no preconditioner dependencies (the default): never kept.
  problem->preconditioner_deps.clear();
  NewtonSolver none(parameters(true), problem, quiet());
  r = solve_with(none);
  EXPECT_EQ(r.preconditioners_built, r.newton_iterations);
}

TEST_F(KeepPreconditionerWithinSolveTest, BuiltAnewWhenTheDependenciesChangeWithinTheSolve)
{
  problem->preconditioner_deps = {2.0};
  problem->change_at = 4; // at the fourth Jacobian of the solve
  NewtonSolver solver(parameters(true), problem, quiet());
  const NewtonSolver::Result r = solve_with(solver);
  ASSERT_GE(r.newton_iterations, 5);
  // Built at the first, the second (||F|| rose: OnePreconditionerPerSolveOnceNewtonConverges)
  // and the fourth Jacobian.
  EXPECT_EQ(r.preconditioners_built, 3);
  EXPECT_EQ(r.preconditioners_kept, r.newton_iterations - 3);
}

TEST_F(KeepPreconditionerWithinSolveTest, BuiltAnewAfterALinearSolveFellShort)
{
  problem->preconditioner_deps = {2.0};
  Teuchos::ParameterList p = parameters(true);
  // Two GMRES iterations: every solve falls short of 1e-10, so no kept preconditioner
  // survives one; Newton still converges (more slowly), each iteration building anew.
  Teuchos::ParameterList &gmres = p.sublist("Linear Solver")
                                      .sublist("Linear Solver Types")
                                      .sublist("Belos")
                                      .sublist("Solver Types")
                                      .sublist("Block GMRES");
  gmres.set("Maximum Iterations", 2);
  p.set("Maximum Iterations", 60);
  NewtonSolver solver(p, problem, quiet());
  NonlinearProblem::Vector x(problem->solution_map());
  const NewtonSolver::Result r = solver.solve(x);
  ASSERT_GT(r.linear_failures, 1);
  // Built at the first iteration and after each failed solve but the last one's.
  EXPECT_GE(r.preconditioners_built, r.linear_failures);
  EXPECT_LE(r.preconditioners_built, r.linear_failures + 1);
}

/// Keep Preconditioner Across Steps: the first Jacobian of a solve also keeps the
/// preconditioner of the solve before, unless the dependencies changed, the solve before did
/// not converge, or its Krylov iterations per Newton iteration grew past the staleness
/// factor times those of the solve that built it.
class KeepPreconditionerAcrossStepsTest : public KeepPreconditionerWithinSolveTest
{
protected:
  Teuchos::ParameterList across(const bool keep, const double staleness = 2.0,
                                const char *preconditioner = "MueLu")
  {
    Teuchos::ParameterList p = parameters(true, preconditioner);
    p.set("Keep Preconditioner Across Steps", keep);
    p.set("Preconditioner Staleness Factor", staleness);
    return p;
  }
  /// A solve from 1% off the solution (Newton converges fast; no iteration builds anew
  /// within the solve): its preconditioners built, 1 if its first Jacobian built one.
  NewtonSolver::Result solve_near(NewtonSolver &solver, const double off = 0.01)
  {
    NonlinearProblem::Vector x = problem->exact_solution();
    x.scale(1.0 + off);
    const NewtonSolver::Result r = solver.solve(x);
    x.update(-1.0, problem->exact_solution(), 1.0);
    EXPECT_TRUE(r.converged);
    EXPECT_LT(x.normInf(), 1e-8);
    EXPECT_GE(r.newton_iterations, 2);
    EXPECT_LE(r.preconditioners_built, 1);
    return r;
  }
};

TEST_F(KeepPreconditionerAcrossStepsTest, TheNextSolveKeepsThePreconditioner)
{
  problem->preconditioner_deps = {2.0};
  for (const char *preconditioner : {"MueLu", "Direct"})
  {
    NewtonSolver on(across(true, 1000.0, preconditioner), problem, quiet());
    NewtonSolver off(across(false, 1000.0, preconditioner), problem, quiet());
    EXPECT_EQ(solve_near(on).preconditioners_built, 1) << preconditioner;
    EXPECT_EQ(solve_near(off).preconditioners_built, 1) << preconditioner;
    for (int solve = 0; solve < 2; ++solve)
    {
      const NewtonSolver::Result r = solve_near(on);
      EXPECT_EQ(r.preconditioners_built, 0) << preconditioner;
      EXPECT_EQ(r.preconditioners_kept, r.newton_iterations) << preconditioner;
      EXPECT_EQ(r.jacobians_evaluated, r.newton_iterations) << preconditioner;
      EXPECT_EQ(solve_near(off).preconditioners_built, 1) << preconditioner;
    }
    // From u = 0 ||F|| rises in the first iteration: the second builds anew, as within a
    // solve; the first keeps the last one.
    const NewtonSolver::Result from_zero = solve_with(on);
    EXPECT_EQ(from_zero.preconditioners_built, 1) << preconditioner;
  }
}

TEST_F(KeepPreconditionerAcrossStepsTest, BuiltAnewWhenTheDependenciesChangeBetweenSolves)
{
  problem->preconditioner_deps = {2.0};
  NewtonSolver solver(across(true, 1000.0), problem, quiet());
  solve_near(solver);
  EXPECT_EQ(solve_near(solver).preconditioners_built, 0);
  problem->preconditioner_deps = {3.0};
  EXPECT_EQ(solve_near(solver).preconditioners_built, 1);
  EXPECT_EQ(solve_near(solver).preconditioners_built, 0);
  // A problem that names no preconditioner dependencies: never kept.
  problem->preconditioner_deps.clear();
  for (int solve = 0; solve < 2; ++solve)
  {
    NonlinearProblem::Vector x = problem->exact_solution();
    x.scale(1.01);
    const NewtonSolver::Result r = solver.solve(x);
    EXPECT_TRUE(r.converged);
    EXPECT_EQ(r.preconditioners_built, r.newton_iterations);
  }
}

TEST_F(KeepPreconditionerAcrossStepsTest, BuiltAnewAfterANewtonSolveFailed)
{
  problem->preconditioner_deps = {2.0};
  Teuchos::ParameterList p = across(true, 1000.0);
  p.set("Maximum Iterations", 3); // too few from u = 0 (at least 4)
  NewtonSolver solver(p, problem, quiet());
  solve_near(solver);
  EXPECT_EQ(solve_near(solver).preconditioners_built, 0);
  NonlinearProblem::Vector x(problem->solution_map());
  ASSERT_FALSE(solver.solve(x).converged);
  EXPECT_EQ(solve_near(solver).preconditioners_built, 1);
  EXPECT_EQ(solve_near(solver).preconditioners_built, 0);
}

TEST_F(KeepPreconditionerAcrossStepsTest, BuiltAnewWhenTheKrylovIterationsGrewPastTheFactor)
{
  problem->preconditioner_deps = {2.0};
  // Solves with a growing diagonal term (shift): the Krylov iterations per Newton iteration
  // with the first solve's preconditioner change. Factor 1 (any growth): the solve after one
  // that took more than the solve that built the preconditioner builds anew; factor 1000:
  // never.
  const std::array<double, 6> shifts{0.0, 1.0, 10.0, 10.0, 3.0, 3.0};
  for (const double factor : {1.0, 1000.0})
  {
    NewtonSolver solver(across(true, factor), problem, quiet());
    double fresh = 0.0;
    bool stale = true;
    int rebuilt = 0;
    for (int solve = 0; solve < 6; ++solve)
    {
      problem->shift = shifts[solve];
      const NewtonSolver::Result r = solve_near(solver);
      EXPECT_EQ(r.preconditioners_built, stale ? 1 : 0) << factor << " " << solve;
      const double per_iteration = static_cast<double>(r.linear_iterations) / r.newton_iterations;
      if (r.preconditioners_built == 1)
      {
        fresh = per_iteration;
        stale = false;
        rebuilt += solve > 0 ? 1 : 0;
      }
      else
      {
        ASSERT_EQ(r.linear_failures, 0) << factor << " " << solve;
        stale = per_iteration > factor * std::max(fresh, 1.0);
      }
    }
    if (factor == 1.0)
      EXPECT_GE(rebuilt, 1);
    else
      EXPECT_EQ(rebuilt, 0);
  }
}

TEST_F(JacobianReuseTest, PreconditionerBuiltAnewWhenOneRanksDiscreteDependencyChanges)
{
  problem->smooth = 1;
  problem->dependencies = {1.0, 2.0};
  Teuchos::ParameterList p = solver_parameters();
  p.set("Preconditioner Reuse Tolerance", 1.0);
  NewtonSolver solver(p, problem, quiet());
  solve_once(solver);
  problem->dependencies = {1.2, 2.0};
  if (comm->getRank() == comm->getSize() - 1)
    problem->dependencies = {1.2, 5.0};
  const NewtonSolver::Result second = solve_once(solver);
  EXPECT_EQ(second.jacobians_evaluated, 1);
  EXPECT_EQ(second.preconditioners_built, 1);
}

TEST_F(JacobianReuseTest, BuiltAnewWhenOneRanksDependenciesChange)
{
  problem->dependencies = {1.0};
  NewtonSolver solver(solver_parameters(), problem, quiet());
  solve_once(solver);
  if (comm->getRank() == comm->getSize() - 1)
    problem->dependencies = {4.0};
  const NewtonSolver::Result second = solve_once(solver);
  EXPECT_EQ(second.jacobians_evaluated, 1);
  EXPECT_EQ(second.preconditioners_built, 1);
  EXPECT_EQ(second.jacobians_kept, second.newton_iterations - 1);
}
