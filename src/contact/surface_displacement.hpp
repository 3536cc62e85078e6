#pragma once
/// The displacement of a contact pair's surface nodes on every rank (issue 30; doc/contact.md,
/// "Small sliding"): what a search redone during a run reads, the same on every rank.
#include "mesh/mesh.hpp"

#include <Teuchos_Comm.hpp>

#include <functional>
#include <vector>

namespace kiln
{
/// u of each of `nodes` (mesh nodes, e.g. a pair's PairResearch::surface_nodes()), in their
/// order [m]: `u` gives the displacement of the nodes this rank owns (`node_owner`, per mesh
/// node) and is asked at those alone; summed over `comm` (each node from its owner alone, so
/// exactly its value on every rank: 3 doubles per node of memory and traffic on every rank,
/// never per mesh node). Collective.
std::vector<Point> gather_displacement(const std::vector<int> &nodes,
                                       const std::function<Point(int node)> &u,
                                       const std::vector<int> &node_owner,
                                       const Teuchos::Comm<int> &comm);
} // namespace kiln
