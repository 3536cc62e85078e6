#pragma once
/// When a gap or a contact pair closed and opened, for the run's summary.
#include <vector>

namespace kiln
{
/// The times at which a set of rows (the split gaps' node pairs, or one contact pair's rows)
/// closed and opened, from its state after each accepted step:
/// - closed: every row in contact, after a state with a row out of contact;
/// - opened: no row carries a pressure above round-off (StateSummary::n_loaded), after a state
///   with one that does.
/// A row that only touches with a pressure of round-off (with "Free Motions" = "Minimum Norm"
/// the bodies touch at one node before they close) and flips in and out of contact from step to
/// step makes no event: it carries nothing, so the rows have not opened.
class ContactEvents
{
public:
  /// The state the run starts from: `n_active` rows in contact, `n_loaded` of them loaded.
  void start(int n_active, int n_loaded);
  /// The state after the step to `time` [s] of `n_rows` rows.
  void step(double time, int n_rows, int n_active, int n_loaded);

  /// Whether start() was called.
  bool started() const { return last_active_ >= 0; }
  const std::vector<double> &closed() const { return closed_; }
  const std::vector<double> &opened() const { return opened_; }

private:
  int last_active_ = -1; ///< rows in contact at the last state (-1: none yet)
  int last_loaded_ = 0;  ///< of which loaded
  std::vector<double> closed_, opened_;
};
} // namespace kiln
