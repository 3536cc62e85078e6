#include "contact/active_set_monitor.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <string>

namespace kiln
{
namespace internal
{
int sum_over_ranks(const Teuchos::Comm<int> &comm, const int local)
{
  int global = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return global;
}
} // namespace internal

ActiveSetMonitor::ActiveSetMonitor(Teuchos::RCP<const Teuchos::Comm<int>> comm, const int n_pairs,
                                   const int n_owned)
    : comm_(std::move(comm)), n_pairs_(n_pairs), last_(n_owned, 0)
{
}

void ActiveSetMonitor::start_step()
{
  history_.clear();
  jacobians_ = 0;
  fallback_ = false;
}

int ActiveSetMonitor::count(const std::vector<char> &active) const
{
  return internal::sum_over_ranks(*comm_,
                                  static_cast<int>(std::count(active.begin(), active.end(), 1)));
}

void ActiveSetMonitor::jacobian_evaluated(const std::vector<char> &active)
{
  int closed = 0, opened = 0;
  for (std::size_t i = 0; i < active.size(); ++i)
  {
    closed += active[i] && !last_[i];
    opened += !active[i] && last_[i];
  }
  closed = internal::sum_over_ranks(*comm_, closed);
  opened = internal::sum_over_ranks(*comm_, opened);
  ++jacobians_;
  if (closed + opened > 0)
  {
    const int n_active = count(active);
    if (!out_.is_null())
      *out_ << "  contact" << gap_name_ << ", Newton iteration " << jacobians_ << ": " << closed
            << (pair_ ? " nodes closed, " : " pairs closed, ") << opened << " opened; " << n_active
            << " of " << n_pairs_ << " in contact\n";
  }
  const int repeated = history_.record(active, *comm_);
  if (repeated > 0 && !fallback_)
  {
    fallback_ = true;
    if (!out_.is_null())
      *out_ << "  contact" << gap_name_ << ": the active set of Newton iteration " << repeated
            << " came back at iteration " << jacobians_
            << " (a cycle); this step goes on with the Fischer-Burmeister function\n";
  }
  last_ = active;
}

void ActiveSetMonitor::resume(const std::vector<char> &active, const std::vector<char> &loaded)
{
  last_ = active;
  accepted_active_ = count(active);
  accepted_loaded_ = count(loaded);
}

void ActiveSetMonitor::step_accepted(const double time, const std::vector<char> &active,
                                     const std::vector<char> &loaded)
{
  last_ = active;
  const int n_active = count(active);
  const int n_loaded = count(loaded);
  if (n_active != accepted_active_ && !out_.is_null())
  {
    const char *what = pair_ ? "the pair" : "the gap";
    std::string event;
    if (n_active == n_pairs_ && accepted_active_ < n_pairs_)
      event = std::string(": ") + what + " has closed";
    else if (n_active == 0 && accepted_active_ > 0)
      event = accepted_loaded_ > 0
                  ? std::string(": ") + what + " has opened"
                  : std::string(": ") + what + " carried a pressure of round-off only (not an " +
                        "opening)";
    *out_ << "contact" << gap_name_ << " at t = " << time << " s: " << n_active << " of "
          << n_pairs_ << (pair_ ? " secondary nodes" : " gap pairs") << " in contact (was "
          << accepted_active_ << ")" << event << "\n";
  }
  accepted_active_ = n_active;
  accepted_loaded_ = n_loaded;
}
} // namespace kiln
