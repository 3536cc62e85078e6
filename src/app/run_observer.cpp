#include "app/run_observer.hpp"

#include "base/stop_request.hpp"
#include "physics/coupled_problem.hpp"

#include <Teuchos_TimeMonitor.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>

namespace kiln
{
namespace internal
{
bool same_time(const double a, const double b)
{
  return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b));
}

/// Now, UTC, ISO 8601.
std::string utc_now()
{
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return text;
}
} // namespace internal

RunObserver::RunObserver(Context context, const int output_steps)
    : c_(std::move(context)), output_steps_(output_steps)
{
}

bool RunObserver::is_output_time(const double t) const
{
  return std::any_of(c_.output_times.begin(), c_.output_times.end(),
                     [t](const double o) { return internal::same_time(o, t); });
}

void RunObserver::step_accepted(const TimeStepper::State &state, const NewtonSolver::Result &,
                                double)
{
  if (c_.checkpoints.due_after_step(state.statistics.steps))
    checkpoint(state);
}

void RunObserver::stop_time(const TimeStepper::State &state)
{
  if (is_output_time(state.time))
    output(state);
  const auto &times = c_.checkpoints.times();
  if (std::any_of(times.begin(), times.end(),
                  [&](const double t) { return internal::same_time(t, state.time); }))
    checkpoint(state);
}

bool RunObserver::stop_requested()
{
  signal_ = kiln::stop_signal(*c_.comm);
  return signal_ != 0;
}

void RunObserver::output(const TimeStepper::State &state)
{
  if (last_output_ >= 0.0 && internal::same_time(last_output_, state.time))
    return;
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Kiln: 4 output"));
  for (const auto &writer : c_.writers)
    c_.field_output.write(*writer, state.time, state.statistics.steps, state.last_step, *state.x);
  ++output_steps_;
  last_output_ = state.time;
  *c_.out << "output: t = " << state.time << " s written to " << c_.output_files << "\n";
}

std::string RunObserver::checkpoint(const TimeStepper::State &state)
{
  const std::string path = c_.checkpoints.path(state.statistics.steps);
  if (last_checkpoint_ == state.statistics.steps)
    return path;
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Kiln: 6 checkpoint"));
  CheckpointInfo info = c_.info;
  info.created = internal::utc_now();
  info.output_steps = output_steps_;
  const CoupledProblem::ContactOutput contact = c_.problem.contact_output(*state.x);
  for (const GapPair &pair : c_.mesh.gap_pairs)
  {
    info.active.push_back(contact.active[pair.node_a] == 1.0 ? 1 : 0);
    info.traction.push_back(contact.traction[pair.node_a]);
  }
  write_checkpoint(path, state, info, c_.fingerprint, *c_.comm);
  // BASE.h5 names the latest: a hard link (a copy where links are not possible), replaced
  // in one rename.
  if (c_.comm->getRank() == 0)
  {
    const std::string latest = c_.checkpoints.latest_path();
    const std::string tmp = latest + ".tmp";
    std::error_code e;
    std::filesystem::remove(tmp, e);
    std::filesystem::create_hard_link(path, tmp, e);
    if (e)
      std::filesystem::copy_file(path, tmp, std::filesystem::copy_options::overwrite_existing, e);
    if (!e)
      std::filesystem::rename(tmp, latest, e);
  }
  last_checkpoint_ = state.statistics.steps;
  *c_.out << "checkpoint: t = " << state.time << " s (step " << state.statistics.steps
          << ") written to " << path << "\n";
  return path;
}
} // namespace kiln
