#pragma once
/// What a run does between its time steps.
#include "app/checkpoint_schedule.hpp"
#include "io/checkpoint.hpp"
#include "io/field_output.hpp"
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

/// Watches the time loop (TimeStepper::Observer): writes the state at every output time to
/// every results writer, writes the checkpoints the schedule asks for, and turns a SIGTERM
/// or SIGINT into a stop after the current step. Keeps count of the output steps and of
/// what was last written, so that a run that stops can write its last good state once.
class RunObserver final : public TimeStepper::Observer
{
public:
  struct Context
  {
    CoupledProblem &problem;
    const Mesh &mesh;
    FieldOutput &field_output;
    std::vector<std::unique_ptr<ResultsWriter>> &writers;
    std::vector<double> output_times;
    const CheckpointSchedule &checkpoints;
    RunFingerprint fingerprint;
    CheckpointInfo info; ///< the input, its path and the version; the rest is filled in
    Teuchos::RCP<const Teuchos::Comm<int>> comm;
    Teuchos::RCP<Teuchos::FancyOStream> out;
    std::string output_files; ///< for log lines
  };
  /// `output_steps`: output steps written before (a continued run).
  RunObserver(Context context, int output_steps);

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

private:
  bool is_output_time(double t) const;

  Context c_;
  int output_steps_;
  double last_output_ = -1.0; ///< the time of the last output step (-1: none)
  int last_checkpoint_ = -1;  ///< the accepted steps of the last checkpoint (-1: none)
  int signal_ = 0;
};
} // namespace kiln
