#pragma once
/// What a run does between its time steps.
#include "app/checkpoint_schedule.hpp"
#include "app/output_schedule.hpp"
#include "app/progress_report.hpp"
#include "io/checkpoint.hpp"
#include "io/field_output.hpp"
#include "io/history_csv.hpp"
#include "io/results_writer.hpp"
#include "solvers/time_stepper.hpp"

#include <Teuchos_FancyOStream.hpp>

#include <memory>
#include <string>
#include <vector>

namespace kiln
{
namespace internal
{
/// Now, UTC, ISO 8601.
std::string utc_now();
} // namespace internal

/// Watches the time loop (TimeStepper::Observer): after every accepted step it records the
/// history row (BASE.history.csv and every results writer) and reports the progress; it writes
/// the state when the output schedule asks (at output times, every N steps) to every results
/// writer, writes the checkpoints the checkpoint schedule asks for, and turns a SIGTERM,
/// SIGINT or SIGUSR1 into a stop after the current step. Keeps count of the output steps and
/// of what was last written, so that a run that stops can write its last good state once.
class RunObserver final : public TimeStepper::Observer
{
public:
  struct Context
  {
    CoupledProblem &problem;
    const Mesh &mesh;
    DofLayout layout;
    FieldOutput &field_output;
    std::vector<std::unique_ptr<ResultsWriter>> &writers;
    const OutputSchedule &outputs;
    const CheckpointSchedule &checkpoints;
    HistoryCsv &history;
    ProgressReport &progress;
    NewtonSolver &newton; ///< its kept preconditioner: origin into checkpoints, restart_point()
    RunFingerprint fingerprint;
    CheckpointInfo info; ///< the input, its path and the version; the rest is filled in
    Teuchos::RCP<const Teuchos::Comm<int>> comm;
    Teuchos::RCP<Teuchos::FancyOStream> out;
  };
  /// `output_steps`: output steps written before (a continued run).
  RunObserver(Context context, int output_steps);

  /// The state the run starts from; `fresh`: a new run (not a restart), whose start is the
  /// history's first row.
  void start(const TimeStepper::State &state, bool fresh);
  void step_accepted(const TimeStepper::State &state, const NewtonSolver::Result &newton,
                     double error) override;
  void stop_time(const TimeStepper::State &state) override;
  bool stop_requested() override;

  /// Writes the state as an output step, unless it was the last one written.
  void output(const TimeStepper::State &state);
  /// Writes a checkpoint of the state (BASE-NNNNNN.h5 and BASE.h5), unless it was the last
  /// one written; returns its path.
  std::string checkpoint(const TimeStepper::State &state);
  /// The signal that stopped the run, or 0.
  int stop_signal() const { return signal_; }
  int output_steps() const { return output_steps_; }
  /// The path of the last checkpoint written, or "".
  const std::string &last_checkpoint_path() const { return last_checkpoint_path_; }

private:
  /// The history row of a state (history_columns() order) into the CSV and every writer.
  void record(const TimeStepper::State &state, const NewtonSolver::Result &newton,
              const StateSummary &summary);

  Context c_;
  int output_steps_;
  double last_output_ = -1.0; ///< the time of the last output step (-1: none)
  int last_checkpoint_ = -1;  ///< the accepted steps of the last checkpoint (-1: none)
  std::string last_checkpoint_path_;
  int signal_ = 0;
};
} // namespace kiln
