#pragma once
/// Watches the contact active set through the Newton iterations and the steps: log lines,
/// cycles, and the fallback to Fischer-Burmeister after a cycle.
#include "contact/active_set_history.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_FancyOStream.hpp>
#include <Teuchos_RCP.hpp>

#include <string>
#include <vector>

namespace kiln
{
/// Each rank passes the flags of the pairs it owns (1: in contact). Collective.
class ActiveSetMonitor
{
public:
  /// `n_pairs`: all pairs; `n_owned`: this rank's.
  ActiveSetMonitor(Teuchos::RCP<const Teuchos::Comm<int>> comm, int n_pairs, int n_owned);

  /// Log lines go to `out` (nothing is logged without one).
  void set_log(Teuchos::RCP<Teuchos::FancyOStream> out) { out_ = std::move(out); }
  /// Names the gap in the log lines ("contact (gap side set 12)"), where there are several or
  /// contact pairs beside it.
  void set_gap_name(std::string name) { gap_name_ = std::move(name); }
  /// Names a contact pair between bodies meshed apart instead ("contact (pair "cut")"): its
  /// rows are counted as its secondary nodes, not as gap pairs.
  void set_pair_name(std::string name)
  {
    gap_name_ = std::move(name);
    pair_ = true;
  }
  /// A new step's Newton solve begins: no history, no fallback.
  void start_step();
  /// The active set at a Jacobian evaluation: logs what changed since the last one; a set of
  /// an earlier iteration coming back (a cycle) switches the rest of the step to the
  /// fallback.
  void jacobian_evaluated(const std::vector<char> &active);
  /// Whether this step has fallen back to Fischer-Burmeister after a cycle.
  bool fallback() const { return fallback_; }
  /// A step ending at `time` is accepted with this active set, `loaded` the pairs in contact
  /// whose pressure is above round-off (carries_load): logs the gap closing or opening (none
  /// in contact after some; if none of those carried a load, the line says so instead of
  /// "has opened": they touched at a pressure of round-off, as with "Minimum Norm").
  void step_accepted(double time, const std::vector<char> &active, const std::vector<char> &loaded);
  /// A run continued from a saved state with this active set (and loaded pairs): no log line,
  /// and the next changes are counted from it.
  void resume(const std::vector<char> &active, const std::vector<char> &loaded);
  /// Pairs in contact, over all ranks.
  int count(const std::vector<char> &active) const;

private:
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  Teuchos::RCP<Teuchos::FancyOStream> out_;
  std::string gap_name_; ///< "" with one gap
  bool pair_ = false;    ///< a contact pair's rows (secondary nodes), not a split gap's pairs
  int n_pairs_;
  ActiveSetHistory history_; ///< the sets at this step's Jacobians
  std::vector<char> last_;   ///< the set at the last Jacobian (or accepted step)
  int jacobians_ = 0;        ///< Jacobian evaluations in this step
  int accepted_active_ = 0;  ///< pairs in contact after the last accepted step
  int accepted_loaded_ = 0;  ///< of which loaded
  bool fallback_ = false;
};
} // namespace kiln
