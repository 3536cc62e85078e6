#pragma once
/// The time history of a run: one row of figures per accepted step (doc/output-format.md).
#include <mpi.h>

#include <string>
#include <vector>

namespace kiln
{
/// One column of the history: its name (the HDF5 dataset /history/NAME and the Exodus global
/// variable; the CSV header is "NAME [UNIT]"), unit and meaning.
struct HistoryColumn
{
  std::string name;
  std::string unit;
  std::string meaning;
};

/// The columns, in order; a row holds one value per column (NaN where the run has no such
/// quantity, e.g. temperatures without a temperature).
const std::vector<HistoryColumn> &history_columns();
/// The columns of a run on a mesh split at `gap_side_sets` (Mesh::gap_side_sets): those of
/// history_columns(), and with several gaps a block per gap after them, named after the
/// gap's side set ID: min_gap_gapID, max_gap_gapID, active_pairs_gapID, contact_area_gapID,
/// normal_force_gapID, gap_heat_flow_gapID (the columns without suffix are over every gap);
/// then a block per contact pair of Mechanics/Contact/Pairs (`pairs`: their names, the
/// input's order, Mesh::contact_pairs): normal_force_NAME, contact_area_NAME. The columns
/// without suffix are over the split gaps only.
std::vector<HistoryColumn> history_columns(const std::vector<int> &gap_side_sets,
                                           const std::vector<std::string> &pairs = {});
/// The names of the columns of contact pair NAME's block.
std::vector<std::string> pair_history_columns(const std::string &pair);
/// The names of the columns of gap ID's block (history_columns(gap_side_sets) order).
std::vector<std::string> gap_history_columns(int id);

/// `value` as the CSV writes it: the shortest text that reads back as the same double
/// ("0.04", "53", "1e-06"), "nan" for NaN.
std::string history_number(double value);

/// BASE.history.csv: a header line with the column names and units ("time [s]"), then one
/// line per row, each
/// flushed as it is written (a run cut off keeps its rows). Rank 0 writes; every member
/// function is collective and throws InputError on every rank when the file cannot be
/// written.
class HistoryCsv
{
public:
  /// A new file (an earlier one is replaced) at `path`, with `columns`.
  HistoryCsv(MPI_Comm comm, const std::string &path,
             std::vector<HistoryColumn> columns = history_columns());
  /// Continues the file of an earlier run at `path` after its step `step` (a restart): its
  /// rows of steps up to `step` are kept (the rest, written after the checkpoint, are
  /// dropped) and returned on every rank by kept_rows(). A missing file, or one with other
  /// columns (moved aside to PATH.old), starts anew, and warning() says so.
  /// With a `running_path`, no row of the file at `path` is dropped: when it holds rows after
  /// `step`, it stays whole (kept_end() gives the time of its last row) and this history is
  /// written at `running_path` until finish() names it. A file at `running_path` (a restart
  /// cut off before its finish()) is the one continued, `path` again kept whole.
  HistoryCsv(MPI_Comm comm, const std::string &path, int step,
             std::vector<HistoryColumn> columns = history_columns(),
             const std::string &running_path = "");

  /// The file being written.
  const std::string &path() const { return path_; }
  /// The time [s] of the last row of the earlier file kept whole beside the one written, or
  /// -infinity when the history is written in place (every rank).
  double kept_end() const { return kept_end_; }
  /// Renames the history written at the running path to `final_path` (rank 0; collective);
  /// nothing for a history written in place.
  void finish(const std::string &final_path);
  /// The rows kept from the earlier run (every rank).
  const std::vector<std::vector<double>> &kept_rows() const { return kept_; }
  /// Why the earlier rows could not be kept (all or some), or "" (every rank).
  const std::string &warning() const { return warning_; }
  const std::vector<HistoryColumn> &columns() const { return columns_; }
  /// Appends a row (columns() order; rank 0's values are written).
  void append(const std::vector<double> &row);

private:
  /// Writes the header and `rows` under PATH.tmp and renames it PATH (rank 0).
  void start(const std::vector<std::vector<double>> &rows);

  MPI_Comm comm_;
  std::string path_;
  std::vector<HistoryColumn> columns_;
  std::vector<std::vector<double>> kept_;
  std::string warning_;
  double kept_end_;
  bool running_ = false;
};
} // namespace kiln
