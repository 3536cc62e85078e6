// Tests src/solvers/starting_guess.cpp on a 1D Laplacian solved by Belos GMRES through
// Stratimikos (no preconditioner), split over the ranks: a solve started from a good guess
// takes fewer iterations to the same answer; a guess that leaves a larger residual than zero
// is declined (the same iterations and answer as from zero); a guess serves one solve only.
// KILN_TEST_NP: 1 2
#include "solvers/starting_guess.hpp"

#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Thyra_DefaultLinearOpSource.hpp>
#include <Thyra_LinearOpWithSolveBase.hpp>
#include <Thyra_LinearSolverBuilderBase.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace
{
using Teuchos::RCP;
using Teuchos::rcp;
using Matrix = Tpetra::CrsMatrix<double>;
using Vector = Tpetra::Vector<double>;
using Map = Tpetra::Map<>;
using GO = Map::global_ordinal_type;
using kiln::internal::StartingGuess;
using kiln::internal::StartingGuessSolveFactory;

constexpr GO n = 400;

struct Problem
{
  RCP<Thyra::LinearOpWithSolveBase<double>> solve;
  RCP<StartingGuess> guess = rcp(new StartingGuess);
  RCP<const Thyra::VectorSpaceBase<double>> space;
  RCP<Thyra::VectorBase<double>> b, exact;
};

Problem make_problem()
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto map = rcp(new Map(n, 0, comm));
  auto A = rcp(new Matrix(map, 3));
  for (GO i = map->getMinGlobalIndex(); i <= map->getMaxGlobalIndex(); ++i)
  {
    std::vector<GO> columns{i};
    std::vector<double> values{2.0};
    for (const GO j : {i - 1, i + 1})
      if (j >= 0 && j < n)
      {
        columns.push_back(j);
        values.push_back(-1.0);
      }
    A->insertGlobalValues(i, static_cast<int>(columns.size()), values.data(), columns.data());
  }
  A->fillComplete();

  auto list = rcp(new Teuchos::ParameterList);
  list->set("Linear Solver Type", "Belos");
  list->set("Preconditioner Type", "None");
  auto &belos = list->sublist("Linear Solver Types").sublist("Belos");
  belos.set("Solver Type", "Pseudo Block GMRES");
  auto &gmres = belos.sublist("Solver Types").sublist("Pseudo Block GMRES");
  gmres.set("Maximum Iterations", 1000);
  gmres.set("Num Blocks", 1000);
  Stratimikos::DefaultLinearSolverBuilder builder;
  builder.setParameterList(list);

  Problem p;
  const auto factory =
      rcp(new StartingGuessSolveFactory(Thyra::createLinearSolveStrategy(builder), p.guess));
  const RCP<const Thyra::LinearOpBase<double>> op =
      Thyra::createConstLinearOp(Teuchos::rcp_implicit_cast<const Tpetra::Operator<double>>(A));
  p.solve = factory->createOp();
  factory->initializeOp(Thyra::defaultLinearOpSource(op), p.solve.get(),
                        Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  p.space = op->domain();
  p.exact = Thyra::createMember(p.space);
  {
    auto x = Thyra::TpetraOperatorVectorExtraction<double>::getTpetraVector(p.exact);
    auto data = x->getDataNonConst();
    for (int i = 0; i < static_cast<int>(data.size()); ++i)
    {
      const double s = static_cast<double>(map->getGlobalElement(i)) / n;
      data[i] = std::sin(3.0 * s) + s * s;
    }
  }
  p.b = Thyra::createMember(op->range());
  Thyra::apply(*op, Thyra::NOTRANS, *p.exact, p.b.ptr());
  return p;
}

struct Solved
{
  int iterations = -1;
  double error = 0.0; ///< max |x - exact|
};

/// Solves from zero (X zeroed, as NOX does) to ||r|| <= 1e-10 ||b||.
Solved solve(const Problem &p)
{
  auto x = Thyra::createMember(p.space);
  Thyra::assign(x.ptr(), 0.0);
  Thyra::SolveCriteria<double> criteria(
      Thyra::SolveMeasureType(Thyra::SOLVE_MEASURE_NORM_RESIDUAL, Thyra::SOLVE_MEASURE_NORM_RHS),
      1e-10);
  const auto status = p.solve->solve(Thyra::NOTRANS, *p.b, x.ptr(), Teuchos::ptrFromRef(criteria));
  EXPECT_EQ(status.solveStatus, Thyra::SOLVE_STATUS_CONVERGED);
  Solved s;
  s.iterations = status.extraParameters->get<int>("Belos/Iteration Count");
  Thyra::Vp_StV(x.ptr(), -1.0, *p.exact);
  s.error = Thyra::norm_inf(*x);
  return s;
}

/// The exact solution with `size` times a smooth perturbation.
RCP<Thyra::VectorBase<double>> near_exact(const Problem &p, const double size)
{
  auto g = Thyra::createMember(p.space);
  Thyra::assign(g.ptr(), size);
  Thyra::Vp_V(g.ptr(), *p.exact);
  return g;
}

TEST(StartingGuess, AGoodGuessSavesIterationsForTheSameAnswer)
{
  const Problem p = make_problem();
  const Solved zero = solve(p);
  EXPECT_LT(zero.error, 1e-6);
  ASSERT_GT(zero.iterations, 20);

  p.guess->set(near_exact(p, 1e-4));
  const Solved guessed = solve(p);
  EXPECT_EQ(p.guess->used, 1);
  EXPECT_LT(guessed.iterations, zero.iterations);
  EXPECT_LT(guessed.error, 1e-6);
}

TEST(StartingGuess, AGuessWorseThanZeroIsDeclined)
{
  const Problem p = make_problem();
  const Solved zero = solve(p);
  p.guess->set(near_exact(p, 1e3));
  const Solved declined = solve(p);
  EXPECT_EQ(p.guess->declined, 1);
  EXPECT_EQ(p.guess->used, 0);
  EXPECT_EQ(declined.iterations, zero.iterations);
  EXPECT_EQ(declined.error, zero.error);
}

TEST(StartingGuess, AGuessServesOneSolve)
{
  const Problem p = make_problem();
  const Solved zero = solve(p);
  p.guess->set(near_exact(p, 1e-4));
  solve(p);
  const Solved after = solve(p);
  EXPECT_EQ(p.guess->used, 1);
  EXPECT_EQ(after.iterations, zero.iterations);
  EXPECT_EQ(after.error, zero.error);
  // clear() forgets a guess no solve took.
  p.guess->set(near_exact(p, 1e-4));
  p.guess->clear();
  EXPECT_EQ(solve(p).iterations, zero.iterations);
  EXPECT_EQ(p.guess->used, 1);
}
} // namespace
