#include "app/time_left_estimate.hpp"

#include <algorithm>

namespace kiln
{
TimeLeftEstimate::TimeLeftEstimate(const double end_time, const int warm_up, const int min_steps,
                                   const int window)
    : end_time_(end_time), warm_up_(std::max(0, warm_up)), min_steps_(std::max(1, min_steps)),
      window_(static_cast<std::size_t>(std::max(1, window)))
{
}

void TimeLeftEstimate::step(const double wall, const double time)
{
  ++steps_;
  if (steps_ < warm_up_)
    return;
  // The last step of the warm-up is the origin of the pace (its end is where timing starts).
  samples_.emplace_back(wall, time);
  if (samples_.size() > window_ + 1)
    samples_.pop_front();
}

double TimeLeftEstimate::seconds_left() const
{
  if (steps_ - warm_up_ < min_steps_ || samples_.size() < 2)
    return -1.0;
  const auto &[wall0, time0] = samples_.front();
  const auto &[wall1, time1] = samples_.back();
  const double covered = time1 - time0;
  if (covered <= 0.0 || wall1 <= wall0 || time1 >= end_time_)
    return -1.0;
  return (wall1 - wall0) * (end_time_ - time1) / covered;
}
} // namespace kiln
