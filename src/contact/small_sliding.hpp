#pragma once
/// The small-sliding limit of a mortar pairing (issue 30; doc/contact.md, "Small sliding"): the
/// rows are built once, in the reference configuration, so they stay right only while each
/// secondary node j stays near its twin point on the primary surface.
#include "contact/contact_interface.hpp"

#include <Teuchos_Comm.hpp>

#include <functional>
#include <string>

namespace kiln
{
/// The tangential slip of row `row` since its rows were built, s_j = |(I - n n)(u_j - sum_k
/// w_jk u_k)| [m], with u(node) the displacement of a node at the state.
double row_slip(const ContactRow &row, const std::function<Point(int node)> &u);

/// Throws the same RunError on every rank if a row of `interface` (those with a slip_limit,
/// this rank's owned ones) has slid further than its limit at the accepted state at `time`
/// [s]: the message names the pair, the node, its position, the time, the slip and the
/// limit and what to change (a rank's row of largest slip / limit; the lowest such rank's).
/// u(node): the displacement of an overlap node at that state. Collective.
void check_small_sliding(const ContactInterface &interface, const std::function<Point(int node)> &u,
                         double time, const Teuchos::Comm<int> &comm);
} // namespace kiln
