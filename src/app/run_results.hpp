#pragma once
/// The results files of a run: opened, continued after a restart, finished.
#include "io/history_csv.hpp"
#include "solvers/time_stepper.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_FancyOStream.hpp>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace kiln
{
class CoupledProblem;
class DofManager;
class FieldOutput;
class GapCsvWriter;
class OutputSchedule;
class RestartPlan;
class ResultsWriter;
struct Mesh;

/// The files a run writes its results to: the results writers of Output/"Format" (HDF5 +
/// XDMF, Exodus), the gap tables (a mesh with a gap or contact pairs), the field output that
/// fills them, and BASE.history.csv. A restart's results start with the earlier run's output
/// steps and its history with the earlier rows (RestartPlan decides which); at the end the
/// files get their final names and status, beside the continued run's if those stay whole
/// (RestartPlan::kept), and the summary lists them.
class RunResults
{
public:
  /// What the results are of: the run's pieces (set up by Simulation::setup()), its schedule
  /// and restart plan, and the metadata the results files record.
  struct Context
  {
    const Mesh &mesh;
    const DofManager &dofs;
    const std::vector<int> &cell_rank; ///< the rank of every cell
    CoupledProblem &problem;
    const OutputSchedule &outputs;
    const RestartPlan &restart_plan;
    std::string input_path; ///< the input file
    std::string input_xml;  ///< the input as given
    std::string run_digest; ///< RunFingerprint::digest() of the run
    Teuchos::RCP<const Teuchos::Comm<int>> comm;
    Teuchos::RCP<Teuchos::FancyOStream> out; ///< rank 0's log
  };

  /// Rank 0 creates the folder of `file_base` (the results, the checkpoints), or every rank
  /// throws an InputError naming `where` (collective).
  static void make_output_folder(const std::string &file_base, const std::string &where,
                                 const Teuchos::Comm<int> &comm);

  /// Opens the results writers of Output/"Format", the gap tables (their first output step
  /// `first_gap_step`) and the field output. Collective.
  RunResults(Context context, int first_gap_step);
  ~RunResults();
  RunResults(const RunResults &) = delete;
  RunResults &operator=(const RunResults &) = delete;

  /// The results writers (RunObserver writes the states and history rows into them).
  std::vector<std::unique_ptr<ResultsWriter>> &writers() { return writers_; }
  FieldOutput &field_output() { return *field_output_; }

  /// The earlier run's output steps in `source` up to `time` into this run's results;
  /// returns their number.
  int continue_results(const std::string &source, double time);
  /// BASE.history.csv, new or (a restart) continued; the rows kept go to every results writer.
  HistoryCsv open_history(const TimeStepper::State &state);
  /// Gives the results files and the `history` their final names, recording `status`. The
  /// earlier run's results and history are kept if this run, at `time` [s], has not passed
  /// them both (the new ones then get the base BASE.restarted: RestartPlan::kept).
  void finish(const std::string &status, double time, HistoryCsv &history);
  /// The "key: value" lines of the files written, for the summary.
  std::vector<std::pair<std::string, std::string>>
  files_written(const std::string &checkpoint) const;

private:
  Context c_;
  std::string results_aside_; ///< this run's results files, if not under BASE
  std::string history_file_;  ///< this run's history as finished, or "" before
  std::vector<std::unique_ptr<ResultsWriter>> writers_;
  GapCsvWriter *gap_tables_ = nullptr; ///< one of writers_, if the mesh has a gap
  int first_gap_step_ = 0;             ///< the output step of its first table
  std::unique_ptr<FieldOutput> field_output_;
};
} // namespace kiln
