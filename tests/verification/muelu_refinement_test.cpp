// MueLu on the Jacobian of the contact box (rotated, split at the gap, the variant-A end
// temperatures), heat conduction alone and thermo-elastic (4 unknowns per node, rigid-body
// near-null space, scaled): the Belos iterations per linear solve stay within 20% when the
// mesh is refined twice by 2 (8^3, 16^3, 32^3 cells; more in doc/solvers.md and
// doc/mechanics.md), a range check on the mean over the first steps, never a fixed count.
// The same for the thermo-elastic default, the Block Triangular preconditioner (a hierarchy
// per field), whose iterations do not grow.
// KILN_TEST_NP: 2
#include "io/input_reader.hpp"
#include "support/simulation_runs.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <string>

namespace
{
/// `preconditioner`: the Preconditioner Type (the thermo-elastic default is "Block
/// Triangular", a hierarchy per field; "MueLu" one for the whole system).
double iterations_per_solve(const int n, const bool mechanics,
                            const std::string &preconditioner = "MueLu")
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string path = kiln_test::inputs + "contact-box-close.xml";
  Teuchos::ParameterList input = kiln::read_input(path, *comm);
  input.sublist("Mesh").sublist("Box").set("Cells", Teuchos::Array<int>(3, n));
  input.sublist("Solver").sublist("Linear Solver").set("Preconditioner Type", preconditioner);
  if (!mechanics)
  {
    input.set("Physics", "Heat Conduction");
    input.remove("Mechanics");
  }
  kiln::Simulation sim(input, path, comm);
  sim.setup();
  kiln::CoupledProblem &problem = sim.problem();
  kiln_test::Vector x(problem.solution_map());
  problem.initial_condition(0.0, x);
  // Steps of 1 s then 5 s: the first three solves of the real run.
  const auto stats = kiln_test::run_from(sim, x, {11.0});
  const double mean = double(stats.linear_iterations) / stats.newton_iterations;
  std::cout << (mechanics ? "thermo-elastic, " : "heat conduction, ") << preconditioner << ", " << n
            << "^3 cells: " << stats.newton_iterations << " Newton iterations, "
            << stats.linear_iterations << " linear, " << mean << " per solve\n";
  return mean;
}

void expect_flat(const bool mechanics)
{
  const double coarse = iterations_per_solve(8, mechanics);
  for (const int n : {16, 32})
  {
    const double fine = iterations_per_solve(n, mechanics);
    EXPECT_LE(fine, 1.2 * coarse) << n << "^3";
    EXPECT_GE(fine, coarse / 1.2) << n << "^3";
  }
}
} // namespace

TEST(MueLuRefinement, HeatConductionIterationsWithinTwentyPercent)
{
  expect_flat(false);
}

TEST(MueLuRefinement, ThermoElasticIterationsWithinTwentyPercent)
{
  expect_flat(true);
}

TEST(MueLuRefinement, BlockTriangularIterationsDoNotGrow)
{
  // A hierarchy per field: at 8^3 on 2 ranks it takes more iterations than at 16^3 (19
  // against 15.7 per solve, 11-27; MueLu on the whole system 18.7 and 16), just beyond 20%,
  // so the check is that refinement adds none beyond 20%.
  const double coarse = iterations_per_solve(8, true, "Block Triangular");
  const double middle = iterations_per_solve(16, true, "Block Triangular");
  const double fine = iterations_per_solve(32, true, "Block Triangular");
  EXPECT_LE(middle, 1.2 * coarse);
  EXPECT_LE(fine, 1.2 * coarse);
  EXPECT_LE(fine, 1.2 * middle);
  EXPECT_GE(fine, middle / 1.2);
}
