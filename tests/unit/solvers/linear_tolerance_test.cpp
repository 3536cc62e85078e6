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

/// Adaptive Linear Tolerance Rate: with the last ||F||, eta_k is at least rate times the
/// square of the last reduction (the residual quadratic convergence predicts), clamped.
TEST(LinearTolerance, RateFollowsTheLastReductionSquared)
{
  LinearTolerance rule;
  rule.safety = 0.001;
  rule.rate = 0.01;
  // ||F|| 1.2e5 -> 1.4e4: 0.01 (1.4e4 / 1.2e5)^2 = 1.36e-4, above 0.001 1e-3 / 1.4e4.
  EXPECT_DOUBLE_EQ(rule(1e-3, 1.4e4, 1.2e5), 0.01 * (1.4e4 / 1.2e5) * (1.4e4 / 1.2e5));
  // Without a last norm (the first iteration, a constant Jacobian): the safety rule, here
  // the floor.
  EXPECT_DOUBLE_EQ(rule(1e-3, 1.4e4), 1e-10);
  // Near the end the safety rule is the looser one.
  EXPECT_DOUBLE_EQ(rule(1e-3, 1e-2, 1e2), 0.001 * 1e-3 / 1e-2);
  // A residual that did not fall: the safety rule.
  EXPECT_DOUBLE_EQ(rule(1e-3, 10.0, 1.0), 0.001 * 1e-3 / 10.0);
  EXPECT_DOUBLE_EQ(rule(1e-2, 1.0, 1.0), 1e-5);
  // rate 0: the safety rule whatever the last norm.
  rule.rate = 0.0;
  EXPECT_DOUBLE_EQ(rule(1e-3, 1.4e4, 1.2e5), 1e-10);
  EXPECT_DOUBLE_EQ(rule(1e-3, 1e-2, 1e2), 0.001 * 1e-3 / 1e-2);
}

/// Adaptive Linear Tolerance First: the first iteration of a solve whose Jacobian varies
/// stops at `first` (within the ceiling); a constant Jacobian's, and the later iterations, do
/// not.
TEST(LinearTolerance, FirstForcingOnlyAtTheFirstIterationOfAVaryingJacobian)
{
  LinearTolerance rule{1e-10, 0.1, 0.001, 0.01, 1e-3};
  // Target 2.8e-3 from ||F_0|| 2.7e3: the safety alone asks 1e-9.
  EXPECT_DOUBLE_EQ(rule(2.8e-3, 2.7e3, 0.0, true), 1e-3);
  EXPECT_DOUBLE_EQ(rule(2.8e-3, 2.7e3, 0.0, false), 0.001 * 2.8e-3 / 2.7e3);
  // Near the target the safety's own tolerance is looser: kept.
  EXPECT_DOUBLE_EQ(rule(1.0, 0.5, 0.0, true), 0.001 * 1.0 / 0.5);
  rule.first = 0.0; // not used
  EXPECT_DOUBLE_EQ(rule(2.8e-3, 2.7e3, 0.0, true), 0.001 * 2.8e-3 / 2.7e3);
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
