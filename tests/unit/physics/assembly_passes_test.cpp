// Tests that CoupledProblem assembles the residual once per Newton iteration with contact: the
// contact decision (and F) is kept for the state it was taken at, so the Jacobian of the same
// state is assembled alone. Counted by the assembly timers over the Newton solve of the step in
// which the closing contact box closes (the active set changes), and over an equilibrium solve
// with the temperature frozen.
// KILN_TEST_NP: 1 2
#include "app/simulation.hpp"
#include "io/input_reader.hpp"
#include "physics/coupled_problem.hpp"
#include "solvers/newton_solver.hpp"
#include "support/simulation_runs.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Teuchos_Tuple.hpp>
#include <gtest/gtest.h>

#include <string>

namespace
{
int calls(const std::string &name)
{
  return Teuchos::TimeMonitor::getNewTimer(name)->numCalls();
}
} // namespace

TEST(AssemblyPasses, OneResidualPerNewtonIterationWithContact)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string deck = kiln_test::inputs + "contact-box-close.xml";
  Teuchos::ParameterList input = kiln::read_input(deck, *comm);
  input.sublist("Output").set("Times", Teuchos::Array<double>(Teuchos::tuple(0.0, 50.0)));
  input.sublist("Output").set("File Base",
                              "assembly_passes_np" + std::to_string(comm->getSize()) + "/close");
  kiln::Simulation sim(input, deck, comm);
  sim.run(); // to 50 s: the gap is open, and closes by 55 s
  kiln::CoupledProblem &problem = sim.problem();
  ASSERT_TRUE(problem.has_contact());
  kiln::NonlinearProblem::Vector x(sim.solution(), Teuchos::Copy), b(problem.solution_map());
  ASSERT_EQ(problem.n_active_pairs(x), 0);

  // A backward Euler step of 5 s.
  b.update(-1.0 / 5.0, x, 0.0);
  problem.set_time_derivative(55.0, 1.0 / 5.0, b);
  int residuals = calls("Kiln: 5 assembly (residual)");
  int jacobians = calls("Kiln: 5 assembly (Jacobian)");
  kiln::NewtonSolver::Result r = sim.newton_solver().solve(x);
  ASSERT_TRUE(r.converged);
  EXPECT_EQ(problem.n_active_pairs(x), problem.n_pairs());
  EXPECT_GE(r.newton_iterations, 2); // the active set changed
  EXPECT_EQ(calls("Kiln: 5 assembly (residual)") - residuals, r.newton_iterations + 1);
  EXPECT_EQ(calls("Kiln: 5 assembly (Jacobian)") - jacobians, r.newton_iterations);

  // Asking for the state's contact output or active set costs no assembly: it is decided.
  residuals = calls("Kiln: 5 assembly (residual)");
  problem.contact_output(x);
  problem.n_active_pairs(x);
  EXPECT_EQ(calls("Kiln: 5 assembly (residual)"), residuals);

  // The equilibrium at this temperature, held: the held rows change F, so the state is decided
  // anew, once per Newton iteration again.
  problem.freeze_temperature(&x);
  residuals = calls("Kiln: 5 assembly (residual)");
  jacobians = calls("Kiln: 5 assembly (Jacobian)");
  r = sim.newton_solver().solve(x);
  ASSERT_TRUE(r.converged);
  EXPECT_EQ(calls("Kiln: 5 assembly (residual)") - residuals, r.newton_iterations + 1);
  EXPECT_EQ(calls("Kiln: 5 assembly (Jacobian)") - jacobians, r.newton_iterations);
  problem.freeze_temperature(nullptr);
}
