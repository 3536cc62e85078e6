#include "app/run_results.hpp"

#include "app/output_schedule.hpp"
#include "app/restart_plan.hpp"
#include "app/run_observer.hpp"
#include "base/errors.hpp"
#include "io/exodus_results_replay.hpp"
#include "io/exodus_results_writer.hpp"
#include "io/field_output.hpp"
#include "io/gap_csv_writer.hpp"
#include "io/hdf5_xdmf_writer.hpp"
#include "io/results_replay.hpp"
#include "mesh/mesh.hpp"
#include "physics/coupled_problem.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <kiln/version.hpp>

#include <filesystem>

namespace kiln
{

void RunResults::make_output_folder(const std::string &file_base, const std::string &where,
                                    const Teuchos::Comm<int> &comm)
{
  const std::filesystem::path base(file_base);
  std::string problem;
  if (comm.getRank() == 0 && base.has_parent_path())
  {
    std::error_code error;
    std::filesystem::create_directories(base.parent_path(), error);
    if (!std::filesystem::is_directory(base.parent_path()))
      problem = "= \"" + file_base + "\": cannot create its folder \"" +
                base.parent_path().string() + "\" (" + error.message() +
                "); give a base in a folder this user can create or write";
  }
  check_collectively(comm, problem.empty(), where, problem);
}

RunResults::RunResults(Context context, const int first_gap_step) : c_(std::move(context))
{
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Kiln: 4 output"));
  const std::string base = c_.outputs.file_base();
  const MPI_Comm mpi_comm =
      *Teuchos::rcp_dynamic_cast<const Teuchos::MpiComm<int>>(c_.comm, true)->getRawMpiComm();
  // Rank 0's clock for every rank: the attribute is written collectively.
  std::string created = internal::utc_now();
  std::vector<char> text(created.begin(), created.end());
  int length = static_cast<int>(text.size());
  Teuchos::broadcast(*c_.comm, 0, Teuchos::outArg(length));
  text.resize(static_cast<std::size_t>(length));
  Teuchos::broadcast(*c_.comm, 0, length, text.data());
  const ResultsMetadata metadata{version_string, std::string(text.begin(), text.end()),
                                 c_.input_path, c_.input_xml, c_.run_digest};
  if (c_.outputs.writes_hdf5())
    writers_.push_back(
        std::make_unique<Hdf5XdmfWriter>(mpi_comm, base, c_.mesh, c_.dofs.owned_nodes(),
                                         c_.dofs.owned_cells(), c_.cell_rank, metadata));
  if (c_.outputs.writes_exodus())
    writers_.push_back(
        std::make_unique<ExodusResultsWriter>(mpi_comm, base, c_.mesh, c_.dofs.owned_nodes(),
                                              c_.dofs.owned_cells(), c_.cell_rank, metadata));
  if (!c_.mesh.gap_pairs.empty() || !c_.mesh.contact_pairs.empty())
  {
    auto gap = std::make_unique<GapCsvWriter>(mpi_comm, base, c_.mesh, c_.dofs.owned_nodes(),
                                              first_gap_step);
    gap_tables_ = gap.get();
    first_gap_step_ = first_gap_step;
    writers_.push_back(std::move(gap));
  }
  field_output_ = std::make_unique<FieldOutput>(c_.problem, c_.mesh, c_.dofs);
}

RunResults::~RunResults() = default;

int RunResults::continue_results(const std::string &source, const double time)
{
  std::vector<ResultsWriter *> writers;
  for (const auto &w : writers_)
    writers.push_back(w.get());
  ReplayRows rows{
      c_.mesh.n_nodes(), c_.mesh.n_cells(), c_.dofs.owned_nodes(), c_.dofs.owned_cells(), {}};
  for (const GapPair &pair : c_.mesh.gap_pairs)
    rows.gap_pairs.emplace_back(pair.node_a, pair.node_b);
  const int n = c_.restart_plan.exodus_results()
                    ? replay_exodus_results(source, time, c_.mesh, rows, writers, *c_.comm)
                    : replay_results(source, time, rows, writers, *c_.comm);
  *c_.out << "results: the " << n << " output steps up to t = " << time << " s of " << source
          << " continue in " << c_.outputs.results_files(false) << "\n";
  c_.restart_plan.check_replayed(n, source);
  return n;
}

HistoryCsv RunResults::open_history(const TimeStepper::State &state)
{
  const MPI_Comm mpi_comm =
      *Teuchos::rcp_dynamic_cast<const Teuchos::MpiComm<int>>(c_.comm, true)->getRawMpiComm();
  std::vector<HistoryColumn> columns =
      history_columns(c_.mesh.gap_side_sets, c_.mesh.contact_pair_names());
  // A restart writes its history beside an earlier one it would shorten (finish()).
  const std::string running = c_.outputs.file_base() + ".running.history.csv";
  if (c_.restart_plan.fresh())
  {
    // A new run: the history of a restart cut off before (of the results it replaces) goes.
    std::error_code ignored;
    if (c_.comm->getRank() == 0)
      std::filesystem::remove(running, ignored);
    return HistoryCsv(mpi_comm, c_.outputs.history_path(), std::move(columns));
  }
  HistoryCsv history(mpi_comm, c_.outputs.history_path(), state.statistics.steps,
                     std::move(columns), running);
  if (!history.warning().empty())
    *c_.out << "warning: " << history.warning() << "\n";
  for (const auto &row : history.kept_rows())
    for (const auto &writer : writers_)
      writer->write_history(row);
  return history;
}

void RunResults::finish(const std::string &status, const double time, HistoryCsv &history)
{
  const RestartPlan::Kept kept = c_.restart_plan.kept(time, history.kept_end());
  if (kept.aside)
  {
    // A restart that stopped before it passed the results (or the history) of the run it
    // continued: those stay whole under BASE, and this run's go beside them.
    const std::string aside = c_.restart_plan.aside_base();
    results_aside_ = c_.restart_plan.aside(c_.outputs.results_files());
    for (const auto &writer : writers_)
      writer->set_final_base(aside);
    const bool history_aside = history.path() != c_.outputs.history_path();
    if (history_aside)
      history.finish(aside + ".history.csv");
    // The files kept: the results if they are the continued run's, the history if this run
    // wrote beside it.
    const std::string history_kept = history_aside ? c_.outputs.history_path() : "";
    *c_.out << "results: "
            << (kept.results ? c_.outputs.results_files(false) +
                                   (history_aside ? " and " + history_kept : std::string())
                             : history_kept)
            << " of the run continued (to t = " << kept.end
            << " s) are kept whole, as this run stopped at t = " << time
            << " s, before it passed them; this run's results are in " << results_aside_
            << (history_aside ? ", its history in " + history.path() : std::string()) << "\n";
  }
  else
    history.finish(c_.outputs.history_path());
  history_file_ = history.path();
  for (const auto &writer : writers_)
    writer->finish(status);
}

std::vector<std::pair<std::string, std::string>>
RunResults::files_written(const std::string &checkpoint) const
{
  std::vector<std::pair<std::string, std::string>> files = {
      {"results", results_aside_.empty() ? c_.outputs.results_files() : results_aside_},
      {"history", history_file_.empty() ? c_.outputs.history_path() : history_file_}};
  if (gap_tables_ != nullptr && gap_tables_->next_step() > first_gap_step_)
  {
    // A line per split gap: "gap tables" (the first), "gap tables (2)" ...; then one per
    // contact pair: "pair tables (NAME)" (its tables follow the split gaps').
    const int n = gap_tables_->next_step() - first_gap_step_;
    const int n_split = static_cast<int>(c_.mesh.gap_side_sets.size());
    for (int g = 0; g < gap_tables_->n_gaps(); ++g)
      files.emplace_back(g >= n_split
                             ? "pair tables (" + c_.mesh.contact_pairs[g - n_split].name + ")"
                         : g == 0 ? std::string("gap tables")
                                  : "gap tables (" + std::to_string(g + 1) + ")",
                         n == 1 ? gap_tables_->path(first_gap_step_, g)
                                : gap_tables_->path(first_gap_step_, g) + " to " +
                                      gap_tables_->path(gap_tables_->next_step() - 1, g) + " (" +
                                      std::to_string(n) + " files)");
  }
  if (!checkpoint.empty())
    files.emplace_back("checkpoint", checkpoint);
  return files;
}
} // namespace kiln
