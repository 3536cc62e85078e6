#pragma once
/// What a run tells its user as it goes, and at its end.
#include "app/contact_events.hpp"
#include "app/time_left_estimate.hpp"
#include "base/log.hpp"
#include "physics/state_summary.hpp"
#include "solvers/newton_solver.hpp"
#include "solvers/time_stepper.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_FancyOStream.hpp>

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace kiln
{
namespace internal
{
/// A wall-clock duration for people: "0.613 s", "2 min 05 s", "1 h 02 min".
std::string duration_text(double seconds);
/// The peak resident memory of this process [bytes] (getrusage).
double peak_rss_bytes();
} // namespace internal

/// The progress of a run, one report per accepted step, and its summary at the end.
/// - Not on a terminal (a file, a pipe, mpirun): one line per step, flushed, that starts as
///   "step N: t = T s, dt = H s (BDF2), Newton I (L linear), |F| a -> b, error e" and goes on
///   with the share of the run done, the pairs in contact, the wall time and an estimate of
///   the time left; a steady solve's line starts "steady solve N: t = T s, Newton I ...".
/// - On a terminal: the same figures on one status line, rewritten in place at each step,
///   below the log's other lines, fitted to the terminal's width (fit_status_line): shortened
///   first ("35%", "25/25 in contact", "N 3/41"), then without, in this order, the wall time,
///   the pairs in contact (the split gaps' node pairs, then the contact pairs' secondary nodes,
///   "25/25 pairs in contact, 28/28 contact-pair nodes in contact"), the time step, the Newton
///   iterations, the time left and the share done; "step N: t = T s" stays.
/// - The time left (TimeLeftEstimate) is printed once the steps after the first two give a
///   pace.
/// - At the end: "key: value" lines (status, times, steps, iterations, the times the split gaps
///   closed and opened ("gap closed at"), those of each contact pair ("pair "NAME" closed at";
///   ContactEvents: a pair that touches with a pressure of round-off only does not open),
///   the peak memory per rank and summed, the files written).
class ProgressReport
{
public:
  struct Run
  {
    std::string method;      ///< Time Stepping/"Method"
    double start_time = 0.0; ///< [s] (a restart: the checkpoint's)
    double end_time = 0.0;   ///< [s]
    int start_steps = 0;     ///< accepted steps before this run (a restart)
    bool terminal = false;   ///< rank 0's log is a terminal
    /// When the run began (before its mesh and its initial equilibrium): the wall times of
    /// the steps, the history and the summary count from it; the time left is estimated
    /// from the steps alone.
    std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
  };
  /// Lines go to `out` (rank 0); the steps start now.
  ProgressReport(Teuchos::RCP<Teuchos::FancyOStream> out, Run run);

  /// The state the run starts from (its contact state: the gap events are changes from it).
  void start(const StateSummary &summary);
  /// After an accepted step with its solve and error estimate (-1: none), and its summary.
  void step(const TimeStepper::State &state, const NewtonSolver::Result &newton, double error,
            const StateSummary &summary);
  /// The wall-clock time since the run began (Run::started) [s].
  double wall_time() const;
  /// Ends the status line and prints the summary: `status`, the figures of `state`, then
  /// `files` ("key", "value") in order. Collective over `comm` (the memory of every rank).
  void summary(const std::string &status, const TimeStepper::State &state,
               const std::vector<std::pair<std::string, std::string>> &files,
               const Teuchos::Comm<int> &comm) const;

  /// The status line's fields of a step (`solve`: "Newton 3 (41 linear)") with their short
  /// forms and priorities, in order.
  std::vector<StatusField> status_fields(const TimeStepper::State &state,
                                         const NewtonSolver::Result &newton,
                                         const StateSummary &summary) const;

private:
  /// "35% of 150 s, 25/25 pairs in contact, wall 0.61 s, 1.1 s left" as fields.
  std::vector<StatusField> figures(double time, const StateSummary &summary) const;

  Teuchos::RCP<Teuchos::FancyOStream> out_;
  Run run_;
  std::chrono::steady_clock::time_point started_; ///< the first step's start (construction)
  TimeLeftEstimate time_left_;
  ContactEvents gaps_; ///< of the split gaps' node pairs (started only if there are some)
  /// Per contact pair (StateSummary::pairs): its name and events.
  struct PairEvents
  {
    std::string name;
    ContactEvents events;
  };
  std::vector<PairEvents> pairs_;
};
} // namespace kiln
