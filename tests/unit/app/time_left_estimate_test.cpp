// Tests app/time_left_estimate: no estimate during the warm-up or before enough steps, the
// exact time left for a steady pace, the slow first steps left out, a change of pace followed.
#include "app/time_left_estimate.hpp"

#include <gtest/gtest.h>

using kiln::TimeLeftEstimate;

TEST(TimeLeftEstimate, NoneUntilThePaceIsKnown)
{
  TimeLeftEstimate eta(100.0); // warm-up 2 steps, then 3 steps
  double wall = 0.0;
  for (int n = 1; n <= 4; ++n)
  {
    wall += 1.0;
    eta.step(wall, n);
    EXPECT_LT(eta.seconds_left(), 0.0) << "step " << n;
  }
  eta.step(wall + 1.0, 5.0);
  EXPECT_NEAR(eta.seconds_left(), 95.0, 1e-12);
}

TEST(TimeLeftEstimate, SlowFirstStepsAreLeftOut)
{
  // A synthetic run: the first step takes 30 s (the first Jacobian and preconditioner), the
  // second 5 s, then each takes 1 s for 1 s of simulated time, to 100 s.
  TimeLeftEstimate eta(100.0);
  const double first_steps = 35.0;
  eta.step(30.0, 1.0);
  eta.step(first_steps, 2.0);
  for (int n = 3; n <= 20; ++n)
  {
    eta.step(first_steps + (n - 2), n);
    if (n >= 5)
    {
      EXPECT_NEAR(eta.seconds_left(), 100.0 - n, 1e-9) << "step " << n;
    }
  }
  // The pace from the start would have said 2.2 times as much at step 5 (40 s for 5 s).
}

TEST(TimeLeftEstimate, FollowsTheRecentPace)
{
  // 1 s of simulated time per wall second for 20 steps, then steps of 4 s of simulated time in
  // 1 s of wall time: after the 10-step window the estimate is the new pace's.
  TimeLeftEstimate eta(200.0);
  double wall = 0.0, time = 0.0;
  for (int n = 1; n <= 20; ++n)
    eta.step(wall += 1.0, time += 1.0);
  for (int n = 1; n <= 10; ++n)
    eta.step(wall += 1.0, time += 4.0);
  EXPECT_NEAR(eta.seconds_left(), (200.0 - time) / 4.0, 1e-9);
}

TEST(TimeLeftEstimate, NoneAtTheEndOrWithoutProgress)
{
  TimeLeftEstimate eta(10.0);
  for (int n = 1; n <= 6; ++n)
    eta.step(n, 0.0); // a steady solve: no simulated time covered
  EXPECT_LT(eta.seconds_left(), 0.0);
  TimeLeftEstimate done(5.0);
  for (int n = 1; n <= 5; ++n)
    done.step(n, n);
  EXPECT_LT(done.seconds_left(), 0.0);
}
