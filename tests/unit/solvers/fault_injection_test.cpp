// Tests src/solvers/fault_injection.cpp (Kiln/Debug, a testing aid): no wrapper without a
// fault; the evaluations it corrupts (from "Time", "Evaluations" of them, residual
// evaluations only, on "Rank" only); an exception on one rank that evaluate_collectively turns
// into the same RunError on every rank; the input errors of its parameters.
// KILN_TEST_NP: 1 2
#include "solvers/fault_injection.hpp"

#include "base/errors.hpp"
#include "solvers/collective_evaluation.hpp"
#include "support/parameter_lists.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_oblackholestream.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace
{
using kiln::FaultInjection;
using kiln::NonlinearProblem;
using kiln::TransientProblem;
using testing::HasSubstr;
using Teuchos::RCP;

/// F(x) = x on three unknowns per rank; J = I.
class Identity final : public TransientProblem
{
public:
  Identity()
  {
    const auto comm = Teuchos::DefaultComm<int>::getComm();
    map_ = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(3 * comm->getSize()), 0, comm));
    auto graph = Teuchos::rcp(new Graph(map_, 1));
    for (std::size_t i = 0; i < map_->getNodeNumElements(); ++i)
    {
      const auto gid = map_->getGlobalElement(static_cast<int>(i));
      graph->insertGlobalIndices(gid, Teuchos::tuple(gid));
    }
    graph->fillComplete();
    graph_ = graph;
  }
  RCP<const Map> solution_map() const override { return map_; }
  RCP<const Graph> jacobian_graph() const override { return graph_; }
  void set_time_derivative(const double time, double, const Vector &) override { time_ = time; }
  void evaluate(const Vector &x, Vector *f, Matrix *) override
  {
    if (f != nullptr)
      Tpetra::deep_copy(*f, x);
    ++evaluations_;
  }
  void step_accepted(double, const Vector &) override { ++accepted_; }
  void step_rejected() override { ++rejected_; }
  double time_ = -1.0;
  int evaluations_ = 0;
  int accepted_ = 0;
  int rejected_ = 0;

private:
  RCP<const Map> map_;
  RCP<const Graph> graph_;
};

Teuchos::ParameterList debug(const std::string &fault, const int rank, const double time,
                             const int evaluations)
{
  Teuchos::ParameterList p = FaultInjection::valid_parameters();
  p.set("Fault", fault);
  p.set("Rank", rank);
  p.set("Time", time);
  p.set("Evaluations", evaluations);
  return p;
}

class FaultInjectionTest : public testing::Test
{
protected:
  RCP<const Teuchos::Comm<int>> comm = Teuchos::DefaultComm<int>::getComm();
  int last = comm->getSize() - 1;
  Teuchos::FancyOStream quiet{Teuchos::rcp(new Teuchos::oblackholestream)};
  RCP<Identity> problem = Teuchos::rcp(new Identity);
  NonlinearProblem::Vector x{problem->solution_map()};
  NonlinearProblem::Vector f{problem->solution_map()};
  NonlinearProblem::Vector b{problem->solution_map()};

  FaultInjectionTest() { x.putScalar(1.0); }
  /// Whether this rank's residual of one evaluation at `time` has a NaN.
  bool nan_at(TransientProblem &p, const double time)
  {
    p.set_time_derivative(time, 0.0, b);
    p.evaluate(x, &f, nullptr);
    bool nan = false;
    for (const double v : f.getData())
      nan = nan || std::isnan(v);
    return nan;
  }
};

TEST_F(FaultInjectionTest, NoFaultNoWrapper)
{
  const RCP<TransientProblem> solved = FaultInjection::wrap(
      problem, FaultInjection::valid_parameters(), "in.xml: Kiln/Debug", quiet);
  EXPECT_EQ(solved.get(), problem.get());
}

TEST_F(FaultInjectionTest, NanInTheChosenEvaluationsOnTheChosenRankOnly)
{
  FaultInjection faulty(problem, debug("NaN In Residual", last, 1.0, 2), "in.xml: Kiln/Debug");
  const bool mine = comm->getRank() == last;
  EXPECT_FALSE(nan_at(faulty, 0.5)); // before "Time"
  EXPECT_EQ(problem->time_, 0.5);    // forwarded
  // A Jacobian alone does not count.
  faulty.evaluate(x, nullptr, nullptr);
  EXPECT_EQ(nan_at(faulty, 1.0), mine);
  EXPECT_EQ(nan_at(faulty, 1.5), mine);
  EXPECT_FALSE(nan_at(faulty, 2.0)); // two evaluations only
  EXPECT_EQ(faulty.n_faults(), 2);
  EXPECT_EQ(problem->evaluations_, 5);
}

TEST_F(FaultInjectionTest, StepsAcceptedAndRejectedAreForwarded)
{
  // The wrapped problem commits or restores its state at quadrature points there.
  FaultInjection faulty(problem, debug("NaN In Residual", 0, 0.0, 1), "in.xml: Kiln/Debug");
  faulty.step_rejected();
  faulty.step_accepted(1.0, x);
  faulty.step_rejected();
  EXPECT_EQ(problem->rejected_, 2);
  EXPECT_EQ(problem->accepted_, 1);
}

TEST_F(FaultInjectionTest, MinusOneEvaluationsIsAll)
{
  FaultInjection faulty(problem, debug("NaN In Residual", 0, 0.0, -1), "in.xml: Kiln/Debug");
  for (int i = 0; i < 10; ++i)
    EXPECT_EQ(nan_at(faulty, 0.1 * i), comm->getRank() == 0);
}

TEST_F(FaultInjectionTest, AnExceptionOnOneRankIsTheSameRunErrorOnEveryRank)
{
  FaultInjection faulty(problem, debug("Exception In Assembly", last, 0.0, 1),
                        "in.xml: Kiln/Debug");
  faulty.set_time_derivative(0.25, 0.0, b);
  std::string message;
  try
  {
    kiln::internal::evaluate_collectively(faulty, x, &f, nullptr);
  }
  catch (const kiln::RunError &e)
  {
    message = e.what();
  }
  EXPECT_EQ(message, "in.xml: Kiln/Debug/\"Fault\" = \"Exception In Assembly\": the exception "
                     "injected on rank " +
                         std::to_string(last) + " of " + std::to_string(comm->getSize()) +
                         " in the residual evaluation at t = 0.25 s; every rank stopped (a "
                         "testing aid: remove Kiln/Debug for real runs)");
  // The next evaluation is a good one.
  EXPECT_NO_THROW(kiln::internal::evaluate_collectively(faulty, x, &f, nullptr));
}

TEST_F(FaultInjectionTest, ItsParametersAreChecked)
{
  const int n = comm->getSize();
  EXPECT_THAT(kiln_test::input_error_message(
                  [&]
                  { FaultInjection(problem, debug("NaN In Residual", n, 0.0, 1), "d.xml: K"); }),
              HasSubstr("d.xml: K/\"Rank\": is " + std::to_string(n) + " but the run has " +
                        std::to_string(n) + " rank"));
  EXPECT_THAT(kiln_test::input_error_message(
                  [&]
                  { FaultInjection(problem, debug("NaN In Residual", 0, 0.0, 0), "d.xml: K"); }),
              HasSubstr("d.xml: K/\"Evaluations\": is 0; give a count >= 1, or -1 for all"));
}
} // namespace
