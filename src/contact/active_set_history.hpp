#pragma once
/// The contact active sets of the Newton iterations of one step, to detect cycling.
#include <Teuchos_Comm.hpp>
#include <Teuchos_CommHelpers.hpp>

#include <vector>

namespace kiln
{
/// Each rank records its part of the active set (a flag per pair it owns) at every Newton
/// iteration. A cycle: the set of an earlier iteration, not the last one, comes back
/// (A -> B -> A), so Newton jumps between wrong sets instead of settling. Collective.
class ActiveSetHistory
{
public:
  void clear() { sets_.clear(); }
  /// Records `set` as the next iteration's; returns the (1-based) earlier iteration with the
  /// same set on every rank, not the previous one, or 0 if none.
  int record(const std::vector<char> &set, const Teuchos::Comm<int> &comm)
  {
    int repeated = 0;
    for (std::size_t j = 0; j + 1 < sets_.size() && repeated == 0; ++j)
    {
      const int local = sets_[j] == set ? 1 : 0;
      int everywhere = 0;
      Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, local, Teuchos::outArg(everywhere));
      // Not a cycle if the set has not changed since the last iteration.
      const int same_as_last = sets_.back() == set ? 1 : 0;
      int unchanged = 0;
      Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, same_as_last, Teuchos::outArg(unchanged));
      if (everywhere == 1 && unchanged == 0)
        repeated = static_cast<int>(j) + 1;
    }
    sets_.push_back(set);
    return repeated;
  }
  int size() const { return static_cast<int>(sets_.size()); }

private:
  std::vector<std::vector<char>> sets_;
};
} // namespace kiln
