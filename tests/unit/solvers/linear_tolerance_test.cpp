// Tests src/solvers/linear_tolerance.cpp: the Krylov tolerance of a Newton iteration, and
// which Belos tolerance bounds it.
#include "solvers/linear_tolerance.hpp"

#include <gtest/gtest.h>

namespace
{
using kiln::internal::belos_convergence_tolerance;
using kiln::internal::LinearTolerance;

TEST(LinearTolerance, LeavesTheSafetyFactorOfTheNewtonTarget)
{
  LinearTolerance rule; // floor 1e-10, ceiling 0.1
  rule.safety = 0.1;
  // ||F_k|| = 100, the Newton test wants 1e-6: the Krylov residual must reach 1e-7.
  EXPECT_DOUBLE_EQ(rule(1e-6, 100.0), 1e-9);
  EXPECT_DOUBLE_EQ(rule(1e-8, 1e-4), 1e-5);
}

TEST(LinearTolerance, NeverTighterThanTheFloorNorLooserThanTheCeiling)
{
  LinearTolerance rule;
  rule.safety = 0.1;
  rule.floor = 1e-8;
  EXPECT_DOUBLE_EQ(rule(1e-12, 1.0), 1e-8);
  EXPECT_DOUBLE_EQ(rule(0.5, 1.0), 0.05);
  EXPECT_DOUBLE_EQ(rule(5.0, 1.0), 0.1);   // F_k below the target: the ceiling
  EXPECT_DOUBLE_EQ(rule(1e-8, 0.0), 1e-8); // nothing to solve: the floor
  EXPECT_DOUBLE_EQ(rule(0.0, 1.0), 1e-8);  // no target: the floor
}

TEST(LinearTolerance, SafetyZeroIsAlwaysTheFloor)
{
  const LinearTolerance rule;
  EXPECT_DOUBLE_EQ(rule(1e-6, 100.0), 1e-10);
  EXPECT_DOUBLE_EQ(rule(1e-8, 1e-9), 1e-10);
}

TEST(LinearTolerance, FloorIsTheChosenBelosSolversTolerance)
{
  Teuchos::ParameterList p;
  p.set("Linear Solver Type", "Belos");
  Teuchos::ParameterList &belos = p.sublist("Linear Solver Types").sublist("Belos");
  belos.set("Solver Type", "Pseudo Block GMRES");
  belos.sublist("Solver Types").sublist("Pseudo Block GMRES").set("Convergence Tolerance", 1e-11);
  belos.sublist("Solver Types").sublist("Block CG").set("Convergence Tolerance", 1e-5);
  EXPECT_DOUBLE_EQ(belos_convergence_tolerance(p), 1e-11);
  belos.set("Solver Type", "Block CG");
  EXPECT_DOUBLE_EQ(belos_convergence_tolerance(p), 1e-5);
  belos.set("Solver Type", "TFQMR"); // not set: Belos' default
  EXPECT_DOUBLE_EQ(belos_convergence_tolerance(p), 1e-8);
  p.set("Linear Solver Type", "Amesos2"); // a direct solver: not adapted
  EXPECT_DOUBLE_EQ(belos_convergence_tolerance(p), 0.0);
}
} // namespace
