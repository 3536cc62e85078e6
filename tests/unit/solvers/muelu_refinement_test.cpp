// MueLu on the heat-conduction Jacobian of the contact box (rotated, split at the gap,
// the variant-A end temperatures): the Belos iterations per linear solve stay within 20%
// when the mesh is refined twice by 2 (8^3, 16^3, 32^3 cells; 64^3 in doc/solvers.md),
// a range check on the mean over the first steps, never a fixed count.
// KILN_TEST_NP: 2
#include "io/input_reader.hpp"
#include "unit/physics/heat_test_support.hpp"

#include <gtest/gtest.h>

namespace
{
double iterations_per_solve(const int n)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string path = std::string(KILN_SOURCE_DIR) + "/inputs/contact-box-close.xml";
  Teuchos::ParameterList input = kiln::read_input(path, *comm);
  input.sublist("Mesh").sublist("Box").set("Cells", Teuchos::Array<int>(3, n));
  kiln::Simulation sim(input, path, comm);
  sim.setup();
  kiln::CoupledProblem &problem = sim.problem();
  kiln_test::Vector x(problem.solution_map());
  problem.initial_condition(0.0, x);
  // Steps of 1 s then 5 s: the first three solves of the real run.
  const auto stats = sim.time_stepper().run(problem, sim.newton_solver(), x, 0.0, {11.0},
                                            [](double, int, double, const kiln_test::Vector &) {});
  const double mean = double(stats.linear_iterations) / stats.newton_iterations;
  std::cout << n << "^3 cells: " << stats.newton_iterations << " Newton iterations, "
            << stats.linear_iterations << " linear, " << mean << " per solve\n";
  return mean;
}
} // namespace

TEST(MueLuRefinement, IterationsWithinTwentyPercent)
{
  const double coarse = iterations_per_solve(8);
  for (const int n : {16, 32})
  {
    const double fine = iterations_per_solve(n);
    EXPECT_LE(fine, 1.2 * coarse) << n << "^3";
    EXPECT_GE(fine, coarse / 1.2) << n << "^3";
  }
}
