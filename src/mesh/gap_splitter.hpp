#pragma once
/// Splits a mesh at an interior side set into a gap of zero initial width.
#include "mesh/mesh.hpp"

#include <string>

namespace kiln
{
/// Every interior face listed in side set `side_set_id` (from one side or both)
/// is cut. The cells then fall into parts connected through the remaining
/// faces; the parts are ranked by their lowest block id, then their lowest
/// cell id. At each node of the cut faces, the cells of the lowest-ranked part
/// around it keep the node (side a); the cells of each other part get a new
/// coincident twin (side b), appended after the existing nodes. One GapPair per
/// twin, with the area-weighted outward normal of side a's cut faces.
/// Throws InputError (naming `where`) if the side set is absent, has no
/// interior face, or does not separate the cells on its two sides.
void split_gap(Mesh &mesh, int side_set_id, const std::string &where);
} // namespace kiln
