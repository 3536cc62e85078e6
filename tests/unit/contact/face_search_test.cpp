// Tests src/contact/face_search.cpp: the bucket search of the primary faces finds, for every
// secondary face, exactly the primary faces whose boxes meet its box grown by the reach (all
// pairs tested by brute force), on non-matching flat surfaces (4x4 against 5x3), perturbed
// and rotated surfaces and a curved (cylindrical) pair; the faces it finds by hand.
// KILN_TEST_NP: 1
#include "contact/face_search.hpp"

#include "mesh/contact_surface.hpp"
#include "support/two_body_mesh.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace
{
using kiln::ContactSurface;
using kiln::FaceSearch;
using kiln::Mesh;
using testing::ElementsAre;

/// Every primary face whose box meets the secondary face's box grown by `reach`.
std::vector<int> brute_force(const ContactSurface &primary, const kiln::BoundingBox &box,
                             const double reach)
{
  std::vector<int> found;
  for (int p = 0; p < primary.n_faces(); ++p)
    if (primary.face_box(p).overlaps(box.grown(reach)))
      found.push_back(p);
  return found;
}

/// Checks the search against all pairs for every secondary face and each reach; returns the
/// number of (secondary, primary) candidates found.
int expect_as_brute_force(const Mesh &mesh, const std::vector<double> &reaches)
{
  const ContactSurface primary(mesh, 1, "test: primary");
  const ContactSurface secondary(mesh, 2, "test: secondary");
  const FaceSearch search(primary);
  int found = 0;
  for (const double reach : reaches)
    for (int s = 0; s < secondary.n_faces(); ++s)
    {
      const std::vector<int> candidates = search.candidates(secondary.face_box(s), reach);
      EXPECT_EQ(candidates, brute_force(primary, secondary.face_box(s), reach))
          << "secondary face " << s << ", reach " << reach;
      found += static_cast<int>(candidates.size());
    }
  return found;
}
} // namespace

TEST(FaceSearch, NonMatchingFlatSurfacesByHand)
{
  // Primary 4x4 faces of 0.25, secondary 5x3 of 0.2 x 1/3, 0.01 apart. Faces are numbered
  // x-fastest: primary (i, j) is i + 4 j.
  const Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {5, 3}, 0.01);
  const ContactSurface primary(mesh, 1, "test: primary");
  const ContactSurface secondary(mesh, 2, "test: secondary");
  const FaceSearch search(primary);
  // Secondary (0, 0): x in [0, 0.2], y in [0, 1/3], z = 0.01. Reach 0.01 takes z = 0 in;
  // in x it reaches 0.21 (primary column 0), in y 0.343 (rows 0 and 1).
  EXPECT_THAT(search.candidates(secondary.face_box(0), 0.01), ElementsAre(0, 4));
  // Reach 0.005 does not take the plane z = 0 in.
  EXPECT_TRUE(search.candidates(secondary.face_box(0), 0.005).empty());
  // Secondary (2, 1): x in [0.4, 0.6], y in [1/3, 2/3], grown by 0.06: x in [0.34, 0.66]
  // (columns 1 and 2), y in [0.273, 0.727] (rows 1 and 2).
  EXPECT_THAT(search.candidates(secondary.face_box(2 + 5), 0.06), ElementsAre(5, 6, 9, 10));
  // Far away nothing, with a huge reach everything.
  const kiln::BoundingBox far{{5.0, 5.0, 5.0}, {5.1, 5.1, 5.1}};
  EXPECT_TRUE(search.candidates(far, 1.0).empty());
  EXPECT_EQ(search.candidates(far, 100.0).size(), 16u);
}

TEST(FaceSearch, InTheMovedConfiguration)
{
  // The primary surface moved along x by u (ContactSurface::set_displacement): secondary face
  // (0, 0), x in [0, 0.2] grown by 0.01, meets columns 0 and 1 for u = -0.125 and none for
  // u = +0.25.
  const Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {5, 3}, 0.01);
  ContactSurface primary(mesh, 1, "test: primary");
  const ContactSurface secondary(mesh, 2, "test: secondary");
  primary.set_displacement(std::vector<kiln::Point>(primary.n_nodes(), {-0.125, 0.0, 0.0}));
  EXPECT_THAT(FaceSearch(primary).candidates(secondary.face_box(0), 0.01), ElementsAre(0, 1, 4, 5));
  primary.set_displacement(std::vector<kiln::Point>(primary.n_nodes(), {0.25, 0.0, 0.0}));
  EXPECT_TRUE(FaceSearch(primary).candidates(secondary.face_box(0), 0.01).empty());
}

TEST(FaceSearch, NonMatchingFlatSurfacesAsAllPairs)
{
  const Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {5, 3}, 0.01);
  EXPECT_GT(expect_as_brute_force(mesh, {0.0, 0.01, 0.2, 0.25, 0.5, 3.0}), 0);
}

TEST(FaceSearch, PerturbedAndRotatedSurfacesAsAllPairs)
{
  for (const auto &angles : {std::array<double, 2>{0.0, 0.0}, {30.0, -20.0}, {45.0, 60.0}})
  {
    Mesh mesh = kiln_test::two_flat_bodies({8, 8}, {7, 9}, 0.005);
    kiln_test::perturb(mesh, 0.02);
    kiln_test::rotate(mesh, angles[0], angles[1]);
    SCOPED_TRACE("phi " + std::to_string(angles[0]) + ", theta " + std::to_string(angles[1]));
    EXPECT_GT(expect_as_brute_force(mesh, {0.0, 0.003, 0.03, 0.15, 1.0}), 0);
  }
}

TEST(FaceSearch, CurvedPairAsAllPairs)
{
  Mesh mesh = kiln_test::two_cylinder_shells({12, 4}, {9, 5}, 0.01);
  kiln_test::rotate(mesh, 30.0, -20.0);
  EXPECT_GT(expect_as_brute_force(mesh, {0.0, 0.01, 0.1, 0.4}), 0);
}

TEST(FaceSearch, CurvedPairFindsThePrimaryFaceAcross)
{
  // The centre of each secondary face, moved 0.01 radially inwards, lies on the primary face
  // of the same angle and height: it is among the candidates with the reach of one face.
  const Mesh mesh = kiln_test::two_cylinder_shells({12, 4}, {9, 5}, 0.01);
  const ContactSurface primary(mesh, 1, "test: primary");
  const ContactSurface secondary(mesh, 2, "test: secondary");
  const FaceSearch search(primary);
  for (int s = 0; s < secondary.n_faces(); ++s)
  {
    const int i = s % 9, k = s / 9;
    const double angle = (i + 0.5) / 9.0, z = (k + 0.5) / 5.0;
    const int across = static_cast<int>(angle * 12.0) + 12 * static_cast<int>(z * 4.0);
    const std::vector<int> candidates =
        search.candidates(secondary.face_box(s), secondary.face_diameter(s));
    EXPECT_THAT(candidates, testing::Contains(across)) << "secondary face " << s;
  }
}

TEST(FaceSearch, BucketsSmallerThanTheFaces)
{
  // Buckets of a tenth of a face: a box reaches ten buckets beyond its lower corner's.
  Mesh mesh = kiln_test::two_flat_bodies({6, 5}, {4, 7}, 0.01);
  kiln_test::perturb(mesh, 0.03);
  kiln_test::rotate(mesh, 10.0, 50.0);
  const ContactSurface primary(mesh, 1, "test: primary");
  const ContactSurface secondary(mesh, 2, "test: secondary");
  std::vector<kiln::BoundingBox> boxes;
  for (int p = 0; p < primary.n_faces(); ++p)
    boxes.push_back(primary.face_box(p));
  const FaceSearch search(boxes, 0.1 * primary.max_face_diameter());
  for (const double reach : {0.0, 0.02, 0.3})
    for (int s = 0; s < secondary.n_faces(); ++s)
      EXPECT_EQ(search.candidates(secondary.face_box(s), reach),
                brute_force(primary, secondary.face_box(s), reach))
          << "secondary face " << s << ", reach " << reach;
}

TEST(FaceSearch, NoPrimaryFaces)
{
  const FaceSearch search({}, 0.0);
  EXPECT_EQ(search.n_faces(), 0);
  EXPECT_TRUE(search.candidates({{0, 0, 0}, {1, 1, 1}}, 1.0).empty());
}
