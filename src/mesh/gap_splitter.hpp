#pragma once
/// Splits a mesh at interior side sets into gaps of zero initial width.
#include "mesh/mesh.hpp"

#include <string>
#include <vector>

namespace kiln
{
/// Every interior face listed in the side sets `side_set_ids` (from one side or both) is cut.
/// The cells then fall into parts connected through the remaining faces; the parts are
/// ranked by their lowest block id, then their lowest cell id. At each node of the cut
/// faces, the cells of the lowest-ranked part around it keep the node; the cells of each
/// other part get a new coincident copy, appended after the existing nodes (where k parts
/// meet, k copies). One GapPair per two parts that a cut face separates at a node: side a
/// the lower-ranked part, with the area-weighted normal of side a's cut faces between the
/// two, and the gap (side set) of those faces. Throws InputError (naming `where`) if a side
/// set is absent, listed twice, has no interior face, does not separate the cells on its
/// two sides, or if two gap side sets share a face.
void split_gaps(Mesh &mesh, const std::vector<int> &side_set_ids, const std::string &where);
/// split_gaps with one side set.
void split_gap(Mesh &mesh, int side_set_id, const std::string &where);
} // namespace kiln
