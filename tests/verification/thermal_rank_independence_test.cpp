// np 1 against np 2: the contact box (inputs/contact-box-close.xml) run on both ranks
// and on each rank alone (a split communicator), with tight solver tolerances, gives the
// same temperatures at every output time to 1e-9 relative.
// KILN_TEST_NP: 2
#include "io/input_reader.hpp"
#include "support/simulation_runs.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

namespace
{
/// The temperatures (all nodes) at each output time.
std::vector<std::vector<double>> run(const Teuchos::RCP<const Teuchos::Comm<int>> &comm)
{
  const std::string path = kiln_test::inputs + "contact-box-close.xml";
  Teuchos::ParameterList input = kiln::read_input(path, *comm);
  // |F| levels off at 1e-12 to 1e-11 by rounding (T_dot = a T + b cancels more as the step
  // shortens; the same with the lumped and the consistent capacity): an absolute tolerance
  // of 1e-12 is below it, and a step retried with a shorter dt only raises it. 1e-11 changes
  // the temperatures by far less than the 1e-9 compared.
  kiln_test::set_solver_tolerances(input, 1e-11, 1e-14, 1e-13);
  kiln::Simulation sim(input, path, comm);
  sim.setup();
  kiln::CoupledProblem &problem = sim.problem();
  kiln_test::Vector x(problem.solution_map());
  problem.initial_condition(0.0, x);
  std::vector<std::vector<double>> states;
  kiln_test::run_from(sim, x, {50.0, 53.0, 150.0},
                      [&](double, int, double, const kiln_test::Vector &state)
                      { states.push_back(kiln_test::all_node_values(sim, state)); });
  return states;
}
} // namespace

TEST(ThermalRankIndependence, OneRankMatchesTwo)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  ASSERT_EQ(comm->getSize(), 2);
  const auto two = run(comm);
  const auto one = run(comm->split(comm->getRank(), 0)); // each rank alone
  ASSERT_EQ(one.size(), 3u);
  ASSERT_EQ(two.size(), 3u);
  for (std::size_t k = 0; k < one.size(); ++k)
  {
    ASSERT_EQ(one[k].size(), two[k].size());
    double worst = 0.0;
    for (std::size_t n = 0; n < one[k].size(); ++n)
      worst = std::max(worst, std::abs(one[k][n] - two[k][n]) / std::abs(one[k][n]));
    std::cout << "output " << k << ": max relative difference np 1 vs np 2 = " << worst << "\n";
    EXPECT_LE(worst, 1e-9);
  }
}
