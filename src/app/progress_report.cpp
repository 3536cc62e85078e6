#include "app/progress_report.hpp"

#include "app/memory_estimate.hpp"
#include "base/log.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <numeric>
#include <sstream>
#include <sys/resource.h>

namespace kiln
{
namespace internal
{
namespace
{
std::string seconds(const double t)
{
  std::ostringstream s;
  s << std::setprecision(6) << t << " s";
  return s.str();
}

std::string times_list(const std::vector<double> &times)
{
  if (times.empty())
    return "never";
  std::string text;
  for (const double t : times)
    text += (text.empty() ? "" : ", ") + seconds(t);
  return text;
}

} // namespace

std::string duration_text(const double seconds)
{
  char text[64];
  if (seconds < 60.0)
    std::snprintf(text, sizeof text, "%.3g s", seconds);
  else if (seconds < 3600.0)
    std::snprintf(text, sizeof text, "%d min %02d s", static_cast<int>(seconds / 60.0),
                  static_cast<int>(std::fmod(seconds, 60.0)));
  else
    std::snprintf(text, sizeof text, "%d h %02d min", static_cast<int>(seconds / 3600.0),
                  static_cast<int>(std::fmod(seconds, 3600.0) / 60.0));
  return text;
}

double peak_rss_bytes()
{
  struct rusage usage = {};
  getrusage(RUSAGE_SELF, &usage);
  return 1024.0 * static_cast<double>(usage.ru_maxrss); // Linux: KiB
}
} // namespace internal

ProgressReport::ProgressReport(Teuchos::RCP<Teuchos::FancyOStream> out, Run run)
    : out_(std::move(out)), run_(std::move(run)), started_(std::chrono::steady_clock::now()),
      time_left_(run_.end_time)
{
}

double ProgressReport::wall_time() const
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - run_.started).count();
}

void ProgressReport::start(const StateSummary &summary)
{
  gaps_ = ContactEvents();
  if (summary.n_pairs > 0)
    gaps_.start(summary.n_active, summary.n_loaded);
  pairs_.clear();
  for (const PairFigures &pair : summary.pairs)
  {
    pairs_.push_back({pair.name, ContactEvents()});
    pairs_.back().events.start(pair.n_active, pair.n_loaded);
  }
}

std::vector<StatusField> ProgressReport::figures(const double time,
                                                 const StateSummary &summary) const
{
  std::vector<StatusField> fields;
  if (run_.end_time > 0.0)
  {
    std::ostringstream percent;
    percent << std::fixed << std::setprecision(0) << 100.0 * time / run_.end_time << "%";
    fields.push_back(
        {percent.str() + " of " + internal::seconds(run_.end_time), percent.str(), 60});
  }
  if (summary.n_pairs > 0)
  {
    const std::string pairs =
        std::to_string(summary.n_active) + "/" + std::to_string(summary.n_pairs);
    fields.push_back({pairs + " pairs in contact", pairs + " in contact", 20});
  }
  int pair_active = 0, pair_rows = 0;
  for (const PairFigures &pair : summary.pairs)
  {
    pair_active += pair.n_active;
    pair_rows += pair.n_rows;
  }
  if (pair_rows > 0)
  {
    const std::string nodes = std::to_string(pair_active) + "/" + std::to_string(pair_rows);
    fields.push_back({nodes + " contact-pair nodes in contact", nodes + " pair nodes", 20});
  }
  fields.push_back({"wall " + internal::duration_text(wall_time()), "", 10});
  const double left = time_left_.seconds_left();
  if (left >= 0.0 && time < run_.end_time)
    fields.push_back({internal::duration_text(left) + " left", "", 50});
  return fields;
}

std::vector<StatusField> ProgressReport::status_fields(const TimeStepper::State &state,
                                                       const NewtonSolver::Result &newton,
                                                       const StateSummary &summary) const
{
  const bool steady = run_.method == "Steady";
  std::vector<StatusField> fields;
  fields.push_back({(steady ? "steady solve " : "step ") + std::to_string(state.statistics.steps) +
                        ": t = " + internal::seconds(state.time),
                    "", 100});
  if (!steady)
    fields.push_back({"dt = " + internal::seconds(state.last_step), "", 30});
  const std::string newton_its = std::to_string(newton.newton_iterations);
  const std::string linear_its = std::to_string(newton.linear_iterations);
  const std::string short_of_tolerance =
      newton.linear_failures > 0
          ? ", " + std::to_string(newton.linear_failures) + " short of tolerance"
          : std::string();
  fields.push_back(
      {"Newton " + newton_its + " (" + linear_its + " linear" + short_of_tolerance + ")",
       "N " + newton_its + "/" + linear_its +
           (newton.linear_failures > 0 ? "!" + std::to_string(newton.linear_failures)
                                       : std::string()),
       40});
  for (StatusField &f : figures(state.time, summary))
    fields.push_back(std::move(f));
  return fields;
}

void ProgressReport::step(const TimeStepper::State &state, const NewtonSolver::Result &newton,
                          const double error, const StateSummary &summary)
{
  if (summary.n_pairs > 0)
    gaps_.step(state.time, summary.n_pairs, summary.n_active, summary.n_loaded);
  for (std::size_t p = 0; p < pairs_.size() && p < summary.pairs.size(); ++p)
  {
    const PairFigures &pair = summary.pairs[p];
    pairs_[p].events.step(state.time, pair.n_rows, pair.n_active, pair.n_loaded);
  }
  time_left_.step(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count(),
      state.time);
  if (run_.terminal)
  {
    show_status_line(fit_status_line(status_fields(state, newton, summary), terminal_columns()));
    return;
  }
  const int n = state.statistics.steps;
  const bool steady = run_.method == "Steady";
  // The first step of BDF2 is backward Euler (TimeStepper).
  const bool bdf2 = run_.method == "BDF2" && state.accepted >= 2;
  std::ostringstream line;
  line << (steady ? "steady solve " : "step ") << n << ": t = " << internal::seconds(state.time);
  if (!steady)
    line << ", dt = " << internal::seconds(state.last_step) << (bdf2 ? " (BDF2)" : " (BE)");
  line << ", Newton " << newton.newton_iterations << " (" << newton.linear_iterations << " linear";
  if (newton.linear_failures > 0)
    line << ", " << newton.linear_failures << " short of tolerance";
  line << "), |F| " << std::scientific << std::setprecision(3) << newton.initial_residual_norm
       << " -> " << newton.final_residual_norm;
  if (error >= 0.0)
    line << ", error " << std::defaultfloat << std::setprecision(3) << error;
  std::string rest;
  for (const StatusField &f : figures(state.time, summary))
    rest += (rest.empty() ? "" : ", ") + f.text;
  line << std::defaultfloat << "; " << rest;
  *out_ << line.str() << "\n";
}

void ProgressReport::summary(const std::string &status, const TimeStepper::State &state,
                             const std::vector<std::pair<std::string, std::string>> &files,
                             const Teuchos::Comm<int> &comm) const
{
  const int n_ranks = comm.getSize();
  const double mine = internal::peak_rss_bytes();
  std::vector<double> peaks(static_cast<std::size_t>(n_ranks), 0.0);
  Teuchos::gatherAll(comm, 1, &mine, n_ranks, peaks.data());
  end_status_line();
  const TimeStepper::Statistics &stats = state.statistics;
  auto &out = *out_;
  out << "status: " << status << "\n";
  out << "simulated time: " << internal::seconds(run_.start_time) << " to "
      << internal::seconds(state.time) << " (end " << internal::seconds(run_.end_time) << ")\n";
  out << "wall time: " << internal::duration_text(wall_time()) << "\n";
  out << "steps: " << stats.steps << "\n";
  if (run_.start_steps > 0)
    out << "steps in this run: " << stats.steps - run_.start_steps << "\n";
  out << "steps repeated for the error estimate or the plastic strain increment: "
      << stats.error_rejections << "\n";
  out << "steps repeated after Newton failed: " << stats.newton_failures << "\n";
  out << "Newton iterations: " << stats.newton_iterations << "\n";
  out << "linear iterations: " << stats.linear_iterations << "\n";
  out << "linear solves short of their tolerance: " << stats.linear_failures << "\n";
  out << "Jacobians assembled in this run: " << stats.jacobians_evaluated << "\n";
  out << "Jacobians kept in this run: " << stats.jacobians_kept << "\n";
  out << "preconditioners built in this run: " << stats.preconditioners_built << "\n";
  out << "preconditioners kept in this run: " << stats.preconditioners_kept << "\n";
  if (gaps_.started())
  {
    out << "gap closed at: " << internal::times_list(gaps_.closed()) << "\n";
    out << "gap opened at: " << internal::times_list(gaps_.opened()) << "\n";
  }
  for (const PairEvents &pair : pairs_)
  {
    out << pair.name << " closed at: " << internal::times_list(pair.events.closed()) << "\n";
    out << pair.name << " opened at: " << internal::times_list(pair.events.opened()) << "\n";
  }
  std::string per_rank;
  for (const double p : peaks)
    per_rank += (per_rank.empty() ? "" : ", ") + memory_text(p);
  out << "peak RSS per rank: " << per_rank << "\n";
  out << "peak RSS summed: " << memory_text(std::accumulate(peaks.begin(), peaks.end(), 0.0))
      << "\n";
  for (const auto &[key, value] : files)
    out << key << ": " << value << "\n";
}
} // namespace kiln
