#include "contact/pair_rows_state.hpp"

#include "base/errors.hpp"

#include <cstddef>

namespace kiln
{
std::vector<double> pair_rows_state(const std::vector<std::unique_ptr<ContactInterface>> &pairings)
{
  std::vector<double> state;
  for (std::size_t p = 0; p < pairings.size(); ++p)
  {
    if (pairings[p]->split())
      continue;
    state.push_back(pairings[p]->searches());
    state.push_back(pairings[p]->n_rows());
    for (const ContactRow &row : pairings[p]->rows())
    {
      state.push_back(static_cast<double>(row.partners.size()));
      state.insert(state.end(), row.partners.begin(), row.partners.end());
      state.insert(state.end(), row.weights.begin(), row.weights.end());
      state.insert(state.end(), {row.area, row.gap0, row.slip0[0], row.slip0[1], row.slip0[2]});
    }
  }
  return state;
}

bool restore_pair_rows(std::vector<std::unique_ptr<ContactInterface>> &pairings,
                       const std::vector<double> &state, const std::string &where)
{
  if (state.empty())
    return false; // a checkpoint without pairings, or of a run without searches written
  std::size_t at = 0;
  const auto next = [&]()
  {
    KILN_CHECK_INPUT(at < state.size(), where,
                     "its rows of the contact pairs (contact/pair_rows) are shorter than this "
                     "run's pairs need: a checkpoint of another run or a damaged one");
    return state[at++];
  };
  for (std::size_t p = 0; p < pairings.size(); ++p)
  {
    if (pairings[p]->split())
      continue;
    ContactInterface &pairing = *pairings[p];
    const int searches = static_cast<int>(next());
    KILN_CHECK_INPUT(static_cast<int>(next()) == pairing.n_rows(), where,
                     "its rows of " << pairing.name()
                                    << " (contact/pair_rows) are not as many as this run's: a "
                                       "checkpoint of another run or a damaged one");
    if (searches == 1)
    {
      // The set-up's rows: skip them.
      for (int k = 0; k < pairing.n_rows(); ++k)
        at += 2 * static_cast<std::size_t>(next()) + 5;
      continue;
    }
    std::vector<ContactRow> rows(pairing.rows().begin(), pairing.rows().end());
    for (ContactRow &row : rows)
    {
      const auto n = static_cast<std::size_t>(next());
      row.partners.resize(n);
      row.weights.resize(n);
      for (int &k : row.partners)
        k = static_cast<int>(next());
      for (double &w : row.weights)
        w = next();
      row.area = next();
      row.gap0 = next();
      for (double &v : row.slip0)
        v = next();
    }
    pairing.replace_rows(std::move(rows));
    pairing.set_searches(searches);
  }
  KILN_CHECK_INPUT(at == state.size(), where,
                   "its rows of the contact pairs (contact/pair_rows) are longer than this run's "
                   "pairs need: a checkpoint of another run or a damaged one");
  return true;
}
} // namespace kiln
