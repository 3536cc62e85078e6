#pragma once
/// The slip of a mortar pairing's rows since their last search (issue 30; doc/contact.md,
/// "Small sliding"): the rows stay right only while each secondary node j stays near its twin
/// point on the primary surface; beyond `Search Update Fraction` of a face the search is redone
/// (PairResearch, and the pair's heat cells with it: PairGapHeat::rebuild).
#include "contact/contact_interface.hpp"

#include <Teuchos_Comm.hpp>

#include <functional>

namespace kiln
{
/// The tangential slip of row `row` since its last search, s_j = |(I - n n)(u_j - sum_k w_jk
/// u_k - slip0)| [m], with u(node) the displacement of a node at the state.
double row_slip(const ContactRow &row, const std::function<Point(int node)> &u);

/// Whether a row of `interface` (those with a slip_limit) has slid beyond its limit since its
/// last search, on any rank (this rank's owned rows; a slip that is not finite counts).
/// Collective.
bool slid_beyond_limit(const ContactInterface &interface, const std::function<Point(int node)> &u,
                       const Teuchos::Comm<int> &comm);
} // namespace kiln
