#pragma once
/// The "Output" block: where the results go, in which format, and when a state is written.
#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace kiln
{
namespace internal
{
/// The index of the first byte of `text` that does not begin a well-formed UTF-8 sequence (an
/// overlong 2-byte lead, a missing continuation byte, a Latin-1 letter), or npos.
std::size_t first_non_utf8_byte(const std::string &text);
} // namespace internal

/// Reads and checks Kiln/Output and answers "is an output due here?". A state is written
/// - at the start of a run (t = 0; a restarted run continues the earlier run's series);
/// - at every listed time ("Times"); the last one is the end of the run, so it is always
///   written; the time steps land on each;
/// - at every multiple of "Interval" up to the end (the steps land on them too);
/// - after every "Every Steps" accepted steps.
/// The files are FILE_BASE.h5 + FILE_BASE.xmf and/or FILE_BASE.exo ("Format"), beside them
/// FILE_BASE.history.csv (a row per step), FILE_BASE.gap-NNNNNN.csv (the gap at output step
/// NNNNNN) and, while a run writes them, the lock FILE_BASE.lock (doc/output-format.md).
class OutputSchedule
{
public:
  static Teuchos::ParameterList valid_parameters();
  /// `p` validated against valid_parameters(); `input_path` is the input file, named in
  /// messages and giving the default File Base results/<its name without .xml>. A File Base
  /// that is a folder is refused (checked by rank 0 of `comm`; collective).
  OutputSchedule(const Teuchos::ParameterList &p, const std::string &input_path,
                 const Teuchos::Comm<int> &comm);

  /// The path of the results without extension.
  const std::string &file_base() const { return base_; }
  bool writes_hdf5() const { return format_ != "Exodus"; }
  bool writes_exodus() const { return format_ != "HDF5"; }
  /// "BASE.h5 and BASE.xmf", "BASE.exo" or "BASE.h5 and BASE.xmf and BASE.exo" (without the
  /// .xmf unless `with_index`).
  std::string results_files(bool with_index = true) const;
  std::string history_path() const { return base_ + ".history.csv"; }
  std::string lock_path() const { return base_ + ".lock"; }

  /// The end of the run: the last listed time [s].
  double end_time() const { return times_.back(); }
  /// The times the steps must land on after `start` (and at `start` too if
  /// `include_start`), increasing: the start of a run, the listed times and the multiples of
  /// the interval, up to the end.
  std::vector<double> stop_times(double start, bool include_start) const;
  /// Whether a state at time `t` is written: t = 0, a listed time or a multiple of the
  /// interval (to 1e-12 relative).
  bool due_at_time(double t) const;
  /// Whether a state is written after `steps` accepted steps ("Every Steps").
  bool due_after_step(int steps) const { return every_steps_ > 0 && steps % every_steps_ == 0; }

private:
  /// Refuses a file name of File Base that, with the longest suffix Kiln adds, exceeds the
  /// file system's limit per name, or that is not UTF-8 when the XDMF index names it.
  void check_file_name(const std::string &base_where, const std::string &input_path) const;

  std::string base_;
  std::string format_;
  std::vector<double> times_; ///< listed, increasing, at least one
  int every_steps_ = 0;
  double interval_ = 0.0; ///< 0: none
};
} // namespace kiln
