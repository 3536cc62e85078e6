// Tests src/solvers/collective_evaluation.cpp: an exception of the problem on one rank is the
// same RunError on every rank (no rank waits for the others), naming the rank for an
// exception that is not a RunError; a RunError's message passes as it is.
// KILN_TEST_NP: 1 2
#include "solvers/collective_evaluation.hpp"

#include "base/errors.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace
{
using kiln::NonlinearProblem;
using Teuchos::RCP;

/// F(x) = x on two unknowns per rank, throwing `what` on rank `rank` (-1: none).
class Throwing final : public NonlinearProblem
{
public:
  Throwing(const int rank, const bool run_error) : rank_(rank), run_error_(run_error)
  {
    const auto comm = Teuchos::DefaultComm<int>::getComm();
    map_ = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(2 * comm->getSize()), 0, comm));
  }
  RCP<const Map> solution_map() const override { return map_; }
  RCP<const Graph> jacobian_graph() const override { return Teuchos::null; }
  void evaluate(const Vector &x, Vector *f, Matrix *) override
  {
    if (f != nullptr)
      Tpetra::deep_copy(*f, x);
    if (map_->getComm()->getRank() != rank_)
      return;
    if (run_error_)
      throw kiln::RunError("the problem cannot go on");
    throw std::runtime_error("boom\nsecond line");
  }

private:
  int rank_;
  bool run_error_;
  RCP<const Map> map_;
};

std::string message_of(NonlinearProblem &problem)
{
  NonlinearProblem::Vector x(problem.solution_map()), f(problem.solution_map());
  try
  {
    kiln::internal::evaluate_collectively(problem, x, &f, nullptr);
  }
  catch (const kiln::RunError &e)
  {
    return e.what();
  }
  return "";
}

TEST(EvaluateCollectively, NoExceptionNoError)
{
  Throwing problem(-1, false);
  EXPECT_EQ(message_of(problem), "");
}

TEST(EvaluateCollectively, AnExceptionOnTheLastRankIsARunErrorOnEveryRank)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const int last = comm->getSize() - 1;
  Throwing problem(last, false);
  EXPECT_EQ(message_of(problem),
            "rank " + std::to_string(last) + " of " + std::to_string(comm->getSize()) +
                " failed in the evaluation of the residual: boom; second line; every rank "
                "stopped. This is a bug in Kiln or a library it uses: please report it with "
                "the input");
}

TEST(EvaluateCollectively, ARunErrorKeepsItsMessage)
{
  Throwing problem(0, true);
  EXPECT_EQ(message_of(problem), "the problem cannot go on");
}
} // namespace
