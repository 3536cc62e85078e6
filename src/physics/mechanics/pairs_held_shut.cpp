#include "physics/mechanics/pairs_held_shut.hpp"

#include "physics/mechanics/least_norm_shift.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

namespace kiln
{
namespace
{
/// An extra motion moves a pair's sides apart along its direction by more than this (relative
/// to the motion's largest body displacement): the pair would hold it. The free motions are
/// found to 1e-11 of the largest eigenvalue (FreeMotionFinder), so a row that misses them
/// gives round-off only.
constexpr double holds_motion = 1e-6;
/// A pair whose multiplier is at most this times the largest of any pair carries round-off
/// only (Newton stops at 1e-8 of the initial residual or below; the converged multipliers
/// of the decks are zero to 1e-15 of the largest).
constexpr double zero_pressure = 1e-9;
} // namespace

int hold_pairs_shut(const FreeMotions &free,
                    const std::vector<std::unique_ptr<InterfaceStrategy>> &interfaces,
                    const std::function<void(InterfaceStrategy &)> &decide_again,
                    const Teuchos::Comm<int> &comm)
{
  const double none = std::numeric_limits<double>::infinity();
  std::vector<std::vector<char>> shut(interfaces.size());
  // A pair's id over every interface: its interface's offset plus its index.
  std::vector<double> offset(interfaces.size() + 1, 0.0);
  for (std::size_t s = 0; s < interfaces.size(); ++s)
    offset[s + 1] = offset[s] + interfaces[s]->interface().n_rows();
  int count = 0;
  for (;;)
  {
    std::vector<FreeMotions::HeldDirection> held;
    for (const auto &strategy : interfaces)
    {
      const auto h = strategy->held_directions(false);
      held.insert(held.end(), h.begin(), h.end());
    }
    const std::vector<RigidMotion> motions = free.motions_with(held);
    if (static_cast<int>(motions.size()) <= free.size())
      return count;
    // This rank's candidate: the least open pair that an extra motion moves.
    double opening = none, id = none;
    for (std::size_t s = 0; s < interfaces.size(); ++s)
    {
      for (const InterfaceStrategy::OpenPair &open :
           interfaces[s]->open_pairs(-std::numeric_limits<double>::infinity()))
      {
        if (open.holds)
          continue;
        double rate = 0.0;
        for (const RigidMotion &m : motions)
          rate = std::max(rate, free.opening_rate(m, open.held));
        const double pair_id = offset[s] + open.pair;
        if (rate > holds_motion &&
            (open.opening < opening || (open.opening == opening && pair_id < id)))
        {
          opening = open.opening;
          id = pair_id;
        }
      }
    }
    double least = none;
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, opening, Teuchos::outArg(least));
    if (least == none)
      return count; // nothing open can hold them: the solver meets the singular Jacobian
    double first = none;
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, opening == least ? id : none,
                       Teuchos::outArg(first));
    // Back from the id to the interface and the pair.
    std::size_t s = 0;
    while (first >= offset[s + 1])
      ++s;
    const int pair = static_cast<int>(first - offset[s]);
    if (shut[s].empty())
      shut[s].assign(static_cast<std::size_t>(interfaces[s]->interface().n_rows()), 0);
    shut[s][static_cast<std::size_t>(pair)] = 1;
    interfaces[s]->hold_shut(shut[s]);
    decide_again(*interfaces[s]);
    ++count;
  }
}

double shift_to_minimum_norm(const FreeMotions &free,
                             const std::vector<std::unique_ptr<InterfaceStrategy>> &interfaces,
                             Tpetra::Vector<> &x)
{
  const auto &comm = *x.getMap()->getComm();
  // A pressure of round-off, relative to the largest: such a pair may open or stay shut.
  double largest_pressure = 0.0, largest_everywhere = 0.0;
  for (const auto &strategy : interfaces)
    for (const double P : strategy->pressure())
      largest_pressure = std::max(largest_pressure, std::abs(P));
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, largest_pressure,
                     Teuchos::outArg(largest_everywhere));
  const double zero = zero_pressure * largest_everywhere;
  std::vector<InterfaceStrategy::OpenPair> open;
  std::vector<FreeMotions::HeldDirection> held;
  for (const auto &strategy : interfaces)
  {
    const auto o = strategy->open_pairs(zero);
    open.insert(open.end(), o.begin(), o.end());
    const auto h = strategy->held_directions(false);
    held.insert(held.end(), h.begin(), h.end());
  }
  // Pairs held shut or at zero pressure hold nothing here: they are constraints g >= 0 like
  // the open ones.
  std::set<std::pair<int, int>> shut;
  for (const auto &o : open)
    if (o.holds)
      shut.insert({o.held.a, o.held.b});
  held.erase(std::remove_if(held.begin(), held.end(),
                            [&](const FreeMotions::HeldDirection &h) {
                              return shut.count({h.a, h.b}) > 0;
                            }),
             held.end());
  const std::vector<RigidMotion> motions = free.motions_with(held);
  const int k = static_cast<int>(motions.size());
  if (k <= free.size())
    return 0.0;
  const auto B = free.basis(motions);
  // M = B^T B and b = B^T x, summed over the ranks in one reduction.
  const auto columns = B->get2dView();
  const auto values = x.getData();
  const std::size_t rows = x.getLocalLength();
  std::vector<double> local(static_cast<std::size_t>(k) * k + k, 0.0), sums(local.size());
  for (int i = 0; i < k; ++i)
    for (std::size_t r = 0; r < rows; ++r)
    {
      for (int j = 0; j < k; ++j)
        local[i + k * j] += columns[i][r] * columns[j][r];
      local[static_cast<std::size_t>(k) * k + i] += columns[i][r] * values[r];
    }
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(),
                     sums.data());
  // Unknowns scaled so that M's diagonal is 1.
  std::vector<double> scale(k), M(static_cast<std::size_t>(k) * k), b(k);
  for (int i = 0; i < k; ++i)
    scale[i] = sums[i + k * i] > 0.0 ? 1.0 / std::sqrt(sums[i + k * i]) : 1.0;
  for (int i = 0; i < k; ++i)
  {
    for (int j = 0; j < k; ++j)
      M[i + k * j] = scale[i] * sums[i + k * j] * scale[j];
    b[i] = scale[i] * sums[static_cast<std::size_t>(k) * k + i];
  }
  // One row per open or held-shut pair that a motion moves (row-major: A_i, then h_i).
  std::vector<double> mine;
  for (const auto &o : open)
  {
    std::vector<double> row(k + 1);
    double largest = 0.0;
    for (int j = 0; j < k; ++j)
    {
      row[j] = free.opening_along(motions[j], o.held) * scale[j];
      largest = std::max(largest, std::abs(row[j]));
    }
    if (largest <= 1e-12)
      continue;
    row[k] = std::min(o.opening, 0.0) - o.opening;
    mine.insert(mine.end(), row.begin(), row.end());
  }
  const int my_rows = static_cast<int>(mine.size()) / (k + 1);
  const int n_ranks = comm.getSize();
  std::vector<int> counts(n_ranks, 0);
  Teuchos::gatherAll(comm, 1, &my_rows, n_ranks, counts.data());
  int before = 0, m = 0;
  for (int r = 0; r < n_ranks; ++r)
  {
    if (r < comm.getRank())
      before += counts[r];
    m += counts[r];
  }
  std::vector<double> all(static_cast<std::size_t>(m) * (k + 1), 0.0), gathered(all.size());
  std::copy(mine.begin(), mine.end(), all.begin() + static_cast<long>(before) * (k + 1));
  if (!all.empty())
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(all.size()), all.data(),
                       gathered.data());
  std::vector<double> A(static_cast<std::size_t>(m) * k), h(m);
  for (int i = 0; i < m; ++i)
  {
    for (int j = 0; j < k; ++j)
      A[static_cast<std::size_t>(i) * k + j] = gathered[static_cast<std::size_t>(i) * (k + 1) + j];
    h[i] = gathered[static_cast<std::size_t>(i) * (k + 1) + k];
  }
  const std::vector<double> c = least_norm_shift(k, M, b, m, A, h);
  Tpetra::Vector<> shift(x.getMap());
  for (int j = 0; j < k; ++j)
    shift.update(c[j] * scale[j], *B->getVector(j), 1.0);
  x.update(1.0, shift, 1.0);
  return shift.normInf();
}
} // namespace kiln
