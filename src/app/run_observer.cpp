#include "app/run_observer.hpp"

#include "base/stop_request.hpp"
#include "physics/coupled_problem.hpp"

#include <Teuchos_TimeMonitor.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <limits>

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

void RunObserver::start(const TimeStepper::State &state, const bool fresh)
{
  const StateSummary summary = c_.problem.summary(*state.x);
  c_.progress.start(summary);
  if (fresh)
    record(state, NewtonSolver::Result{}, summary);
}

void RunObserver::record(const TimeStepper::State &state, const NewtonSolver::Result &newton,
                         const StateSummary &s)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const bool temperature = c_.layout.temperature;
  const bool displacement = c_.layout.displacement;
  const bool contact = s.n_pairs > 0;
  std::vector<double> row = {static_cast<double>(state.statistics.steps),
                             state.time,
                             state.statistics.steps > 0 ? state.last_step : 0.0,
                             static_cast<double>(newton.newton_iterations),
                             static_cast<double>(newton.linear_iterations),
                             temperature ? s.T_min : nan,
                             temperature ? s.T_max : nan,
                             temperature ? s.T_mean : nan,
                             temperature ? s.thermal_energy : nan,
                             displacement ? s.max_displacement : nan,
                             contact ? s.min_opening : nan,
                             contact ? s.max_opening : nan,
                             static_cast<double>(s.n_active),
                             contact ? s.contact_area : nan,
                             contact ? s.normal_force : nan,
                             c_.progress.wall_time()};
  // With several gaps, a block of columns per gap (history_columns(gap_side_sets)).
  if (s.gaps.size() > 1)
    for (const GapFigures &gap : s.gaps)
    {
      const bool held = gap.n_pairs > 0;
      row.insert(row.end(), {held ? gap.min_opening : nan, held ? gap.max_opening : nan,
                             static_cast<double>(gap.n_active), held ? gap.contact_area : nan,
                             held ? gap.normal_force : nan, gap.heat_flow});
    }
  // A block per contact pair (history_columns(gap_side_sets, contact_pairs)).
  for (const PairFigures &pair : s.pairs)
    row.insert(row.end(), {pair.normal_force, pair.contact_area, pair.heat_flow});
  c_.history.append(row);
  for (const auto &writer : c_.writers)
    writer->write_history(row);
}

void RunObserver::step_accepted(const TimeStepper::State &state, const NewtonSolver::Result &newton,
                                const double error)
{
  const StateSummary summary = c_.problem.summary(*state.x);
  record(state, newton, summary);
  c_.progress.step(state, newton, error, summary);
  if (c_.outputs.due_after_step(state.statistics.steps))
    output(state);
  if (c_.checkpoints.due_after_step(state.statistics.steps))
    checkpoint(state);
}

void RunObserver::stop_time(const TimeStepper::State &state)
{
  if (c_.outputs.due_at_time(state.time))
    output(state);
  const auto &times = c_.checkpoints.times();
  if (std::any_of(times.begin(), times.end(),
                  [&](const double t) { return internal::same_time(t, state.time); }))
    checkpoint(state);
  // Every stop time is one a run may end at and be restarted from (its last output time).
  c_.newton.restart_point();
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
  *c_.out << "output: t = " << state.time << " s written to " << c_.outputs.results_files(false)
          << "\n";
}

std::string RunObserver::checkpoint(const TimeStepper::State &state)
{
  const std::string path = c_.checkpoints.path(state.statistics.steps);
  if (last_checkpoint_ == state.statistics.steps)
    return path;
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Kiln: 6 checkpoint"));
  CheckpointInfo info = c_.info;
  info.created = internal::utc_now();
  // An output due at this time and not written yet (a checkpoint after every N steps comes
  // before stop_time() writes it, so that a full disk there still leaves this state) is
  // counted: the restart from here finds it among the earlier results, which it continues
  // up to this time.
  const bool output_due = c_.outputs.due_at_time(state.time) &&
                          !(last_output_ >= 0.0 && internal::same_time(last_output_, state.time));
  info.output_steps = output_steps_ + (output_due ? 1 : 0);
  info.preconditioner_origin = c_.newton.preconditioner_origin();
  const CoupledProblem::ContactOutput contact = c_.problem.contact_output(*state.x);
  for (std::size_t p = 0; p < c_.mesh.gap_pairs.size(); ++p)
  {
    info.active.push_back(contact.pair_active[p] == 1.0 ? 1 : 0);
    info.traction.push_back(contact.pair_traction[p]);
  }
  info.pair_rows = c_.problem.pair_rows_state();
  info.pair_heat_u = c_.problem.pair_heat_state();
  write_checkpoint(path, state, info, c_.fingerprint, *c_.comm, c_.problem.quadrature_state());
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
  last_checkpoint_path_ = path;
  c_.newton.restart_point();
  *c_.out << "checkpoint: t = " << state.time << " s (step " << state.statistics.steps
          << ") written to " << path << "\n";
  return path;
}
} // namespace kiln
