#include "physics/heat/pair_heat_state.hpp"

#include "base/errors.hpp"

namespace kiln
{
std::vector<double> pair_heat_state(const std::vector<std::shared_ptr<PairGapHeat>> &terms)
{
  std::vector<double> state;
  for (const auto &heat : terms)
  {
    const std::vector<Point> &u = heat->searched_displacement();
    state.push_back(static_cast<double>(3 * u.size()));
    for (const Point &v : u)
      state.insert(state.end(), v.begin(), v.end());
  }
  return state;
}

void restore_pair_heat(const std::vector<std::shared_ptr<PairGapHeat>> &terms,
                       const std::vector<std::unique_ptr<ContactInterface>> &pairings,
                       const std::vector<std::shared_ptr<PairGapHeat>> &pairing_heat,
                       const std::vector<double> &state, const std::string &where)
{
  if (state.empty())
  {
    // A checkpoint of a Kiln whose heat cells were fixed at set-up: right only without a search.
    for (std::size_t p = 0; p < pairing_heat.size(); ++p)
      KILN_CHECK_INPUT(pairing_heat[p] == nullptr || pairings[p]->searches() <= 1, where,
                       "has no heat cells of the contact pairs (contact/pair_heat_u) but "
                           << pairings[p]->name()
                           << ", which carries heat across its gap, was searched again before "
                              "it: a checkpoint of a Kiln older than its rebuilt heat cells; "
                              "restart from a checkpoint of this Kiln, or run from the start");
    return;
  }
  std::size_t at = 0;
  for (const auto &heat : terms)
  {
    const std::size_t n = at < state.size() ? static_cast<std::size_t>(state[at]) : 0;
    KILN_CHECK_INPUT(at < state.size() && at + 1 + n <= state.size() &&
                         (n == 0 || n == 3 * heat->surface_nodes().size()),
                     where,
                     "its heat cells of the contact pairs (contact/pair_heat_u) do not fit this "
                     "run's pairs: a checkpoint of another run or a damaged one");
    std::vector<Point> u(n / 3);
    for (std::size_t i = 0; i < u.size(); ++i)
      u[i] = {state[at + 1 + 3 * i], state[at + 2 + 3 * i], state[at + 3 + 3 * i]};
    at += 1 + n;
    if (!u.empty())
      heat->rebuild(u, 0.0, where);
  }
  KILN_CHECK_INPUT(at == state.size(), where,
                   "its heat cells of the contact pairs (contact/pair_heat_u) are longer than "
                   "this run's pairs need: a checkpoint of another run or a damaged one");
}
} // namespace kiln
