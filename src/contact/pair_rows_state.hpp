#pragma once
/// The rows of the contact pairs in a checkpoint (issue 30; doc/contact.md, "Small sliding"):
/// a pair searched again during a run has rows of its own, which a restart must rebuild.
#include "contact/contact_interface.hpp"

#include <memory>
#include <string>
#include <vector>

namespace kiln
{
/// The rows of the pairings of `pairings` (the split gaps are skipped), flattened for a
/// checkpoint (the same on every rank): per pairing, its count of searches and its rows'
/// partners, weights, areas, g0 and slip0. Empty without pairings.
std::vector<double> pair_rows_state(const std::vector<std::unique_ptr<ContactInterface>> &pairings);

/// Gives the pairings of `pairings` the rows of `state` (pair_rows_state() of a checkpoint): a
/// pairing searched once keeps its set-up rows. Throws InputError naming `where` (the
/// checkpoint) if they do not fit these pairings. Returns whether any rows were replaced.
bool restore_pair_rows(std::vector<std::unique_ptr<ContactInterface>> &pairings,
                       const std::vector<double> &state, const std::string &where);
} // namespace kiln
