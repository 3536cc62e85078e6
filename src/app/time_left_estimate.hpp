#pragma once
/// The wall-clock time a run has left, from the pace of its recent steps.

#include <cstddef>
#include <deque>
#include <utility>

namespace kiln
{
/// Estimates the wall time left to reach `end_time` from the simulated time the steps cover
/// per wall second. The first `warm_up` steps are left out (the first Jacobian, the first
/// preconditioner and the short first steps of an adaptive stepper make them slow and
/// unrepresentative), and the pace is that of the last `window` steps after them (an adaptive
/// step grows as the solution settles, so the early pace would overestimate the rest). No
/// estimate until `min_steps` steps after the warm-up are in.
class TimeLeftEstimate
{
public:
  TimeLeftEstimate(double end_time, int warm_up = 2, int min_steps = 3, int window = 10);
  /// An accepted step that ended at simulated `time` [s], `wall` [s] after any fixed origin.
  void step(double wall, double time);
  /// The wall time left [s], or -1 while no estimate is meaningful (the warm-up, too few
  /// steps, no simulated time covered) or at the end.
  double seconds_left() const;

private:
  double end_time_;
  int warm_up_;
  int min_steps_;
  std::size_t window_;
  int steps_ = 0;
  std::deque<std::pair<double, double>> samples_; ///< (wall, time): the warm-up's end, then steps
};
} // namespace kiln
