#include "app/restart_plan.hpp"

#include "app/checkpoint_schedule.hpp"
#include "app/output_schedule.hpp"
#include "base/errors.hpp"
#include "io/exodus_results_replay.hpp"
#include "io/results_replay.hpp"
#include "physics/coupled_problem.hpp"
#include "solvers/newton_solver.hpp"

#include <algorithm>
#include <filesystem>
#include <utility>

namespace kiln
{
namespace
{
/// The summary of the HDF5 or Exodus results file `path`.
ResultsSummary summary_of_results(const std::string &path, const bool exodus)
{
  return exodus ? exodus_results_summary(path) : results_summary(path);
}
} // namespace

RestartPlan::RestartPlan(std::string checkpoint, std::string results_base, std::string extension,
                         std::string run_digest, Teuchos::RCP<const Teuchos::Comm<int>> comm,
                         Teuchos::RCP<Teuchos::FancyOStream> out)
    : checkpoint_(std::move(checkpoint)), base_(std::move(results_base)),
      extension_(std::move(extension)), run_digest_(std::move(run_digest)), comm_(std::move(comm)),
      out_(std::move(out))
{
}

Checkpoint RestartPlan::read(const RunFingerprint &run, const Teuchos::RCP<const Map> &map,
                             QuadratureState *quadrature_state)
{
  Checkpoint c = read_checkpoint(checkpoint_, run, map, *comm_, quadrature_state);
  output_steps_ = c.info.output_steps;
  return c;
}

TimeStepper::State RestartPlan::resume(const RunFingerprint &run, CoupledProblem &problem,
                                       NewtonSolver &newton)
{
  Checkpoint c = read(run, problem.solution_map(), problem.quadrature_state());
  problem.restore_pair_rows(c.info.pair_rows, checkpoint_);
  problem.restore_pair_heat(c.info.pair_heat_u, checkpoint_);
  const int active = problem.resume(c.state.time, *c.state.x);
  int saved_active = 0;
  for (const int a : c.info.active)
    saved_active += a;
  *out_ << "restart from " << checkpoint_ << ": t = " << c.state.time << " s after step "
        << c.state.statistics.steps << " (written " << c.info.created << " by Kiln "
        << c.info.kiln_version << " from " << c.info.input_path << ")";
  // The checkpoint counts the split gaps' pairs (Mesh::gap_pairs); the rows of the contact
  // pairs between bodies meshed apart (a secondary node each) are not in it.
  int split_active = active, split_rows = problem.n_pairs(), pair_active = 0, pair_rows = 0;
  if (problem.has_contact())
    for (const PairFigures &pair : problem.summary(*c.state.x).pairs)
    {
      pair_active += pair.n_active;
      pair_rows += pair.n_rows;
    }
  split_active -= pair_active;
  split_rows -= pair_rows;
  if (problem.has_contact() && split_rows + pair_rows > 0)
  {
    *out_ << "; ";
    if (split_rows > 0)
      *out_ << split_active << " of " << split_rows << " gap pairs"
            << (pair_rows > 0 ? " and " : "");
    if (pair_rows > 0)
      *out_ << pair_active << " of " << pair_rows << " contact-pair nodes";
    *out_ << " in contact";
  }
  *out_ << "\n";
  if (split_active != saved_active)
    *out_ << "warning: the checkpoint says " << saved_active
          << " gap pairs were in contact; its state gives " << split_active << "\n";
  newton.restore_preconditioner_origin(std::move(c.info.preconditioner_origin));
  return c.state;
}

void RestartPlan::check_time_left(const double time, const double end_time,
                                  const std::string &input_path) const
{
  KILN_CHECK_INPUT(fresh() || time < end_time * (1.0 - 1e-12), checkpoint_,
                   "the checkpoint's time, t = "
                       << time << " s, is at or past the end of this run, the last output "
                       << "time " << end_time
                       << " s: there is nothing left to compute, and nothing was written. To go "
                          "on, add later times to Kiln/Output/\"Times\" of "
                       << input_path);
}

std::string RestartPlan::earlier_results()
{
  if (fresh())
    return "";
  // BASE.running.h5 if the earlier run was cut off (moved aside, as the new run writes that
  // name), else BASE.h5; with Exodus output only, the same of BASE.exo.
  const std::string &base = base_;
  const std::string &extension = extension_;
  const std::string complete = base + extension;
  const bool cut_off = std::filesystem::exists(base + ".running" + extension);
  if (cut_off || std::filesystem::exists(complete))
    check_same_run(cut_off ? base + ".running" + extension : complete);
  // The complete results of the run continued stay until this run has passed them.
  if (std::filesystem::exists(complete))
  {
    const ResultsSummary earlier = summary_of_results(complete, exodus_results());
    if (earlier.run_fingerprint == run_digest_)
      kept_results_end_ = earlier.end_time;
  }
  if (cut_off)
  {
    const std::string moved = base + ".interrupted" + extension;
    // Every rank has looked for the files before rank 0 moves one: a rank that looked after
    // would find neither and go on alone (the ranks then wait in different collectives).
    comm_->barrier();
    if (comm_->getRank() == 0)
      std::filesystem::rename(base + ".running" + extension, moved);
    comm_->barrier();
    *out_ << "results: " << base << ".running" << extension
          << " of a run that was cut off is kept as " << moved << "\n";
    return moved;
  }
  if (std::filesystem::exists(base + extension))
    return base + extension;
  *out_ << "warning: " << base << extension
        << " (the earlier run's results) is missing; the results start at the restart\n";
  return "";
}

void RestartPlan::check_same_run(const std::string &results) const
{
  // Every rank reads the attribute of the same file: the check gives one answer.
  const std::string theirs = summary_of_results(results, exodus_results()).run_fingerprint;
  const std::string &ours = run_digest_;
  KILN_CHECK_INPUT(theirs == ours, results,
                   (theirs.empty() ? "has no run fingerprint (the attribute run_fingerprint), so "
                                     "it cannot be shown to belong to the run of the checkpoint "
                                   : "was written by another run (run fingerprint " + theirs +
                                         ") than the checkpoint ")
                       << checkpoint_ << " (run fingerprint " << ours
                       << ": its mesh, physics and initial state): the restart would append to "
                          "the results of another run, and nothing was written. Restart with "
                          "that run's checkpoint, give the checkpoint's run its own "
                          "Kiln/Output/\"File Base\", or move "
                       << results << " aside (the results then start at the restart)");
}

int RestartPlan::first_gap_step(const std::string &earlier_results) const
{
  return !fresh() && earlier_results.empty() ? output_steps_ : 0;
}

void RestartPlan::check_replayed(const int replayed, const std::string &source) const
{
  if (replayed != output_steps_)
    *out_ << "warning: the checkpoint was written after " << output_steps_ << " output steps, but "
          << source << " holds " << replayed << " up to its time\n";
}

bool RestartPlan::ahead(const double t, const double time) const
{
  return fresh() ? t >= time : t > time * (1.0 + 1e-12) + 1e-12;
}

std::vector<double> RestartPlan::stop_times(const double time, const OutputSchedule &outputs,
                                            const CheckpointSchedule &checkpoints) const
{
  std::vector<double> all = outputs.stop_times(time, fresh());
  for (const double t : checkpoints.times())
    if (ahead(t, time))
      all.push_back(t);
  std::sort(all.begin(), all.end());
  std::vector<double> stops;
  for (const double t : all)
    if (stops.empty() || t > stops.back() * (1.0 + 1e-12) + 1e-12)
      stops.push_back(t);
  return stops;
}

RestartPlan::Kept RestartPlan::kept(const double time, const double history_end) const
{
  Kept k;
  k.end = std::max(kept_results_end_, history_end);
  k.aside = time < k.end * (1.0 - 1e-12) - 1e-12;
  k.results = time < kept_results_end_ * (1.0 - 1e-12) - 1e-12;
  return k;
}

std::string RestartPlan::aside(std::string files) const
{
  const std::string &base = base_;
  const std::string moved = aside_base();
  for (std::size_t at = 0; (at = files.find(base + ".", at)) != std::string::npos;
       at += moved.size() + 1)
    files.replace(at, base.size(), moved);
  return files;
}
} // namespace kiln
