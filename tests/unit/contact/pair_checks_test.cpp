// Tests src/contact/pair_checks.cpp: the input errors of a contact pair that its surfaces
// show, each naming the pair: one side set on both sides, surfaces too far apart for the
// search distance, surfaces within reach that look the same way; a pair that faces passes.
// KILN_TEST_NP: 1
#include "contact/pair_checks.hpp"

#include "mesh/contact_surface.hpp"
#include "support/parameter_lists.hpp"
#include "support/two_body_mesh.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace
{
using kiln::ContactSurface;
using testing::HasSubstr;

const std::string pair = "in.xml: Mechanics/Contact/Pairs/\"Pellet\"";

/// The message of check_surfaces_face_each_other for side sets `primary`, `secondary` of two
/// flat bodies `gap` apart (4x4 and 5x3 faces), or "".
std::string facing_error(const int primary, const int secondary, const double gap,
                         const double reach)
{
  const kiln::Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {5, 3}, gap);
  const ContactSurface p(mesh, primary, pair);
  const ContactSurface s(mesh, secondary, pair);
  return kiln_test::input_error_message(
      [&] { kiln::check_surfaces_face_each_other(p, s, reach, pair); });
}
} // namespace

TEST(PairChecks, OneSideSetOnBothSides)
{
  const std::string message =
      kiln_test::input_error_message([] { kiln::check_distinct_side_sets(3, 3, pair); });
  EXPECT_THAT(message, HasSubstr(pair + ": \"Primary Side Set\" and \"Secondary Side Set\" are "
                                        "both side set 3"));
  EXPECT_EQ(kiln_test::input_error_message([] { kiln::check_distinct_side_sets(3, 4, pair); }), "");
}

TEST(PairChecks, SurfacesThatFacePass)
{
  EXPECT_EQ(facing_error(1, 2, 0.01, 0.2), "");
  // Primary and secondary swapped, and touching with no reach.
  EXPECT_EQ(facing_error(2, 1, 0.0, 0.0), "");
}

TEST(PairChecks, SurfacesOutOfReach)
{
  // 0.5 m apart, a reach of 0.2 m.
  const std::string message = facing_error(1, 2, 0.5, 0.2);
  EXPECT_THAT(message, HasSubstr(pair + ": side sets 1 (primary) and 2 (secondary) do not face "
                                        "each other: no secondary face is within the search "
                                        "distance 0.2 m of a primary face (the nearest face "
                                        "boxes are 0.5 m apart)"));
  EXPECT_THAT(message, HasSubstr("raise \"Search Distance\""));
  // With a reach of 0.5 they face.
  EXPECT_EQ(facing_error(1, 2, 0.5, 0.5), "");
}

TEST(PairChecks, SurfacesThatLookTheSameWay)
{
  // Body 1's top (side set 1, +z) and body 2's top (4, +z, 0.21 above it): within a reach of
  // 1 m, but their normals do not point against each other.
  const std::string message = facing_error(1, 4, 0.01, 1.0);
  EXPECT_THAT(message, HasSubstr(pair + ": side sets 1 (primary) and 4 (secondary) do not face "
                                        "each other: the faces within the search distance 1 m"));
  EXPECT_THAT(message, HasSubstr("look the same way"));
}
