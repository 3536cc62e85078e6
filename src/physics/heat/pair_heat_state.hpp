#pragma once
/// The heat cells of the contact pairs in a checkpoint (issue 30; doc/heat.md, "Heat across
/// the gap of a mortar pairing"): a pair with a heat term searched again during a run has cells
/// of its own, which a restart must rebuild (as contact/pair_rows_state does for its rows).
#include "contact/contact_interface.hpp"
#include "physics/heat/pair_gap_heat.hpp"

#include <memory>
#include <string>
#include <vector>

namespace kiln
{
/// The displacement of the surfaces of each term of `terms` at its last search
/// (PairGapHeat::searched_displacement), flattened for a checkpoint (the same on every rank):
/// per term, its count of values, then u. Empty without terms.
std::vector<double> pair_heat_state(const std::vector<std::shared_ptr<PairGapHeat>> &terms);

/// Rebuilds the cells of the terms of `terms` from `state` (pair_heat_state() of a checkpoint;
/// a term of no search keeps its set-up cells): the cells in force at the checkpoint.
/// `pairing_heat` gives per entry of `pairings` (whose searches are restored already) its term
/// or null. A `state` that is empty (a checkpoint of a Kiln older than rebuilt heat cells) is
/// taken as the set-up cells if no pairing with a term was searched again, else an InputError
/// naming `where` (the checkpoint), as for a state that does not fit these terms.
void restore_pair_heat(const std::vector<std::shared_ptr<PairGapHeat>> &terms,
                       const std::vector<std::unique_ptr<ContactInterface>> &pairings,
                       const std::vector<std::shared_ptr<PairGapHeat>> &pairing_heat,
                       const std::vector<double> &state, const std::string &where);
} // namespace kiln
