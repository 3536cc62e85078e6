#pragma once
/// A contact pair's search redone during a run (issue 30; doc/contact.md, "Small sliding"): the
/// surfaces' displacement gathered on every rank, the new rows, and the check that they stay
/// off the other pairs and gaps.
#include "contact/contact_interface.hpp"
#include "contact/pair_research.hpp"
#include "mesh/mesh.hpp"

#include <Teuchos_Comm.hpp>

#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace kiln
{
/// The rows of `pairings[p]` searched again by `research` at the accepted state of `time` [s]:
/// `u` gives the displacement of the nodes this rank owns (`node_owner`, per mesh node), of
/// which the surfaces' are gathered on every rank (gather_displacement,
/// contact/surface_displacement.hpp) so that every rank searches the same surfaces
/// (PairResearch::rows_at). Throws RunError (the same on every rank) as rows_at does, and naming
/// both if a new partner is a node of another pair or gap of `pairings` (the rows of one would
/// overwrite the other's), as the set-up refuses it. Collective.
std::vector<ContactRow>
search_pair_again(const std::vector<std::unique_ptr<ContactInterface>> &pairings, std::size_t p,
                  const PairResearch &research, const Mesh &mesh,
                  const std::function<Point(int node)> &u, const std::vector<int> &node_owner,
                  const Teuchos::Comm<int> &comm, double time);
} // namespace kiln
