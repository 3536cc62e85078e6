#pragma once
/// What a run that continues from a checkpoint (kiln --restart) does with the files of the run
/// it continues.
#include "io/checkpoint.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_FancyOStream.hpp>

#include <limits>
#include <string>
#include <vector>

namespace kiln
{
class CheckpointSchedule;
class CoupledProblem;
class NewtonSolver;
class OutputSchedule;

/// The restart's decisions: the checkpoint it reads (its output steps) and the state it resumes
/// from, whether its time leaves anything to compute, which results it continues (BASE.h5;
/// BASE.running.h5 of a run that was cut off, kept as BASE.interrupted.h5; BASE.exo with Exodus
/// output only) and that they are its own run's, where the gap tables start, which checkpoint
/// times are still ahead (the times the steps land on), and, at the end, whether the results
/// and history of the run it continued stay whole (this run stopped before it passed them: its
/// own go beside them, under BASE.restarted). A new run (no checkpoint) continues nothing.
class RestartPlan
{
public:
  /// `checkpoint`: the checkpoint to continue from, "" for a new run; `results_base`:
  /// Kiln/Output/"File Base"; `extension`: of the results a restart continues, ".h5" (or
  /// ".exo" with Exodus output only); `run_digest`: this run's RunFingerprint::digest();
  /// `out`: rank 0's log.
  RestartPlan(std::string checkpoint, std::string results_base, std::string extension,
              std::string run_digest, Teuchos::RCP<const Teuchos::Comm<int>> comm,
              Teuchos::RCP<Teuchos::FancyOStream> out);

  bool fresh() const { return checkpoint_.empty(); }
  const std::string &checkpoint() const { return checkpoint_; }

  /// The checkpoint, read for the run `run` (read_checkpoint: unknowns on `map`, the state at
  /// quadrature points into `quadrature_state`); keeps its output steps. Collective.
  Checkpoint read(const RunFingerprint &run, const Teuchos::RCP<const Map> &map,
                  QuadratureState *quadrature_state);
  /// The state of the checkpoint, read for the run `run` and checked against it, into
  /// `problem` (its contact pairs' rows, which pairs are in contact) and `newton` (what its
  /// kept preconditioner was built from); logs what was read. Collective.
  TimeStepper::State resume(const RunFingerprint &run, CoupledProblem &problem,
                            NewtonSolver &newton);
  /// The output steps written before the checkpoint (0 before read()).
  int output_steps() const { return output_steps_; }

  /// An InputError naming the checkpoint unless its `time` [s] is before `end_time`, the last
  /// output time of the input `input_path`: otherwise nothing is left to compute.
  void check_time_left(double time, double end_time, const std::string &input_path) const;

  /// The results of the run continued, which this run's results start with, or "" (a new run,
  /// or none: a warning). An InputError naming them if they are another run's (their
  /// run_fingerprint is not `run_digest`); BASE.running.EXT of a run that was cut off is moved
  /// to BASE.interrupted.EXT (rank 0), and the end of BASE.EXT of this run noted: it is kept
  /// until this run passes it. Collective.
  std::string earlier_results();
  /// Whether the results continued are Exodus (else HDF5).
  bool exodus_results() const { return extension_ == ".exo"; }
  /// The first output step of the gap tables: the checkpoint's output steps when a restart has
  /// no results to continue (its tables go on numbering), else 0 (the continued results
  /// rewrite them).
  int first_gap_step(const std::string &earlier_results) const;
  /// A warning if the `replayed` output steps of `source` are not the checkpoint's.
  void check_replayed(int replayed, const std::string &source) const;

  /// Whether a checkpoint time `t` [s] is still to come for a run at `time`: for a new run
  /// one at `time` too, for a restart only a later one (the checkpoint's own is written).
  bool ahead(double t, double time) const;
  /// The times the steps land on from `time` [s] on: the output times of `outputs` (and
  /// `time` itself for a new run) and the checkpoint times of `checkpoints` still ahead.
  std::vector<double> stop_times(double time, const OutputSchedule &outputs,
                                 const CheckpointSchedule &checkpoints) const;

  /// What stays of the run continued when this run ends at `time` [s].
  struct Kept
  {
    bool aside = false;   ///< this run's results and history go under aside_base()
    bool results = false; ///< the continued results stay whole (this run did not pass them)
    double end = 0.0;     ///< the end of what is kept [s]
  };
  /// `history_end`: the end of the continued history (HistoryCsv::kept_end()).
  Kept kept(double time, double history_end) const;
  /// BASE.restarted: this run's files when the run continued keeps its own.
  std::string aside_base() const { return base_ + ".restarted"; }
  /// `files` (a list of paths) with every "BASE." made "BASE.restarted.".
  std::string aside(std::string files) const;

private:
  /// Refuses (InputError naming both files) the earlier `results` unless they are this run's.
  void check_same_run(const std::string &results) const;

  std::string checkpoint_;
  std::string base_;
  std::string extension_;
  std::string run_digest_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  Teuchos::RCP<Teuchos::FancyOStream> out_;
  int output_steps_ = 0;
  /// The last output time of the continued run's BASE.EXT, kept until this run passes it [s].
  double kept_results_end_ = -std::numeric_limits<double>::infinity();
};
} // namespace kiln
