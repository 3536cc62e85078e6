#pragma once
/// The input errors of a contact pair between separately meshed bodies (issue 30) that its
/// surfaces show: one side set on both sides, surfaces that do not face each other. (A side
/// set that is not in the mesh, empty, inside the mesh or quadratic: ContactSurface.) Each
/// message names `where`, the pair ("in.xml: Mechanics/Contact/Pairs/\"Pellet\""), and says
/// what to change. The mesh is replicated: every rank throws alike.
#include <string>

namespace kiln
{
class ContactSurface;

/// Throws unless the primary and secondary side sets differ.
void check_distinct_side_sets(int primary_side_set, int secondary_side_set,
                              const std::string &where);

/// Throws unless some secondary face faces a primary face: their boxes meet once grown by
/// `reach` [m] (FaceSearch) and their normals point against each other. Names the distance
/// between the nearest face boxes when none is within reach, and says that the surfaces
/// look the same way when faces are within reach but none faces the other.
void check_surfaces_face_each_other(const ContactSurface &primary, const ContactSurface &secondary,
                                    double reach, const std::string &where);
} // namespace kiln
