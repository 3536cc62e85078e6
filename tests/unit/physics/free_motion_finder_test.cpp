// FreeMotionFinder: the free rigid motions of known configurations, worked out by hand, with
// the constraints shared among the ranks (each rank adds every n-th one).
// KILN_TEST_NP: 1 2
#include "physics/mechanics/free_motion_finder.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace
{
using kiln::FreeMotionFinder;
using kiln::Point;

const Teuchos::Comm<int> &comm()
{
  return *Teuchos::DefaultComm<int>::getComm();
}

/// Adds the k-th constraint on the rank k mod size only: the sum over the ranks counts each once.
struct Adder
{
  FreeMotionFinder &finder;
  int k = 0;
  void direction(const int body, const Point &x, const Point &d)
  {
    if (k++ % comm().getSize() == comm().getRank())
      finder.add_direction(body, x, d);
  }
  void gap(const int a, const int b, const Point &x, const Point &n)
  {
    if (k++ % comm().getSize() == comm().getRank())
      finder.add_gap(a, b, x, n);
  }
};

std::vector<std::string> described(const FreeMotionFinder &finder)
{
  std::vector<std::string> d;
  for (const kiln::RigidMotion &m : finder.find(comm()))
    d.push_back(finder.describe(m));
  return d;
}

/// The corners of the unit square [0, 1]^2 in the plane normal to axis `normal` at `at`.
std::vector<Point> square(const int normal, const double at)
{
  std::vector<Point> points;
  for (const double s : {0.0, 1.0})
    for (const double t : {0.0, 1.0})
    {
      Point p{};
      p[normal] = at;
      p[(normal + 1) % 3] = s;
      p[(normal + 2) % 3] = t;
      points.push_back(p);
    }
  return points;
}

TEST(FreeMotionFinder, NoConstraintLeavesAllSixAboutTheCentre)
{
  FreeMotionFinder finder({{{1.0, 2.0, 3.0}, 2.0}});
  EXPECT_EQ(
      described(finder),
      (std::vector<std::string>{"translation along x", "translation along y", "translation along z",
                                "rotation about the axis (1, 0, 0) through (1, 2, 3)",
                                "rotation about the axis (0, 1, 0) through (1, 2, 3)",
                                "rotation about the axis (0, 0, 1) through (1, 2, 3)"}));
}

TEST(FreeMotionFinder, ThreeRollersAtOnePointLeaveTheThreeRotationsAboutIt)
{
  // The point p = (1, 2, 3) held in x, y and z: r(p) = 0, so r(x) = w x (x - p). The axis
  // along e_k through p is named by its point nearest the centre (0, 0, 0).
  FreeMotionFinder finder({{{0.0, 0.0, 0.0}, 4.0}});
  Adder add{finder};
  for (const Point &d : {Point{1, 0, 0}, Point{0, 1, 0}, Point{0, 0, 1}})
    add.direction(0, {1.0, 2.0, 3.0}, d);
  EXPECT_EQ(described(finder),
            (std::vector<std::string>{"rotation about the axis (1, 0, 0) through (0, 2, 3)",
                                      "rotation about the axis (0, 1, 0) through (1, 0, 3)",
                                      "rotation about the axis (0, 0, 1) through (1, 2, 0)"}));
}

TEST(FreeMotionFinder, RollersOnTwoFacesLeaveTheTranslationNormalToBoth)
{
  // compress-x: u_x = 0 on x = 0 and u_y = 0 on y = 0. u_x = a_x + w_y z - w_z y vanishing
  // for all y, z of the face: a_x = w_y = w_z = 0; u_y = a_y + w_z x - w_x z on y = 0: a_y =
  // w_x = 0. Free: a_z.
  FreeMotionFinder finder({{{0.5, 0.5, 0.5}, 1.7}});
  Adder add{finder};
  for (const Point &p : square(0, 0.0))
    add.direction(0, p, {1, 0, 0});
  for (const Point &p : square(1, 0.0))
    add.direction(0, p, {0, 1, 0});
  EXPECT_EQ(described(finder), std::vector<std::string>{"translation along z"});
}

TEST(FreeMotionFinder, ARotatedConfigurationNamesTheRotatedDirections)
{
  // Two bodies of a rotated box (the contact box's Phi = 45, Theta = -30 frame), each held
  // on its end face along the box's x' and on its y' face along y', the gap between them
  // along x': each body's translation along z' is free, alone (the round-off of the rotated
  // rows must not read as a rotation).
  const double c = std::sqrt(0.5), s3 = std::sqrt(3.0) / 2.0;
  const Point ex{c * s3, c * s3, -0.5}, ey{-c, c, 0.0}, ez{c * 0.5, c * 0.5, s3};
  const auto at = [&](const double x, const double y, const double z)
  {
    return Point{x * ex[0] + y * ey[0] + z * ez[0], x * ex[1] + y * ey[1] + z * ez[1],
                 x * ex[2] + y * ey[2] + z * ez[2]};
  };
  FreeMotionFinder finder({{at(-0.5, 0, 0), 1.7}, {at(0.5, 0, 0), 1.7}});
  Adder add{finder};
  for (const double y : {-0.5, 0.5})
    for (const double z : {-0.5, 0.5})
    {
      add.direction(0, at(-1, y, z), ex);
      add.direction(1, at(1, y, z), ex);
      add.gap(0, 1, at(0, y, z), ex);
    }
  for (const double x : {-1.0, -0.5, 0.0})
    for (const double z : {-0.5, 0.5})
    {
      add.direction(0, at(x, -0.5, z), ey);
      add.direction(1, at(-x, -0.5, z), ey);
    }
  const std::string z_prime = "translation along (0.353553, 0.353553, 0.866025)";
  EXPECT_EQ(described(finder), (std::vector<std::string>{z_prime, z_prime}));
}

TEST(FreeMotionFinder, RollersOnThreeFacesHoldEverything)
{
  FreeMotionFinder finder({{{0.5, 0.5, 0.5}, 1.7}});
  Adder add{finder};
  for (int k = 0; k < 3; ++k)
  {
    Point n{};
    n[k] = 1.0;
    for (const Point &p : square(k, 0.0))
      add.direction(0, p, n);
  }
  EXPECT_TRUE(finder.find(comm()).empty());
}

TEST(FreeMotionFinder, ABodyHeldOnlyByContactKeepsItsTangentialMotions)
{
  // Body 0 clamped on x = 0, body 1 ([1, 2] x [0, 1]^2) touching it across x = 1: the gap
  // holds n.(r_0 - r_1) = 0 at the corners of the face: a_x, w_y, w_z of body 1. Free: its
  // translations along y and z and its rotation about the x axis through its centre.
  FreeMotionFinder finder({{{0.5, 0.5, 0.5}, 1.7}, {{1.5, 0.5, 0.5}, 1.7}});
  Adder add{finder};
  for (const Point &p : square(0, 0.0))
    for (const Point &d : {Point{1, 0, 0}, Point{0, 1, 0}, Point{0, 0, 1}})
      add.direction(0, p, d);
  for (const Point &p : square(0, 1.0))
    add.gap(0, 1, p, {1, 0, 0});
  const std::vector<kiln::RigidMotion> motions = finder.find(comm());
  ASSERT_EQ(motions.size(), 3U);
  for (const kiln::RigidMotion &m : motions)
    EXPECT_EQ(finder.bodies_moved(m), std::vector<int>{1});
  EXPECT_EQ(described(finder), (std::vector<std::string>{
                                   "translation along y", "translation along z",
                                   "rotation about the axis (1, 0, 0) through (1.5, 0.5, 0.5)"}));
}

TEST(FreeMotionFinder, TwoFreeBodiesInContactMoveAloneAndTogether)
{
  // Neither body held; the gap at x = 1 holds the relative a_x, w_y, w_z: 12 - 3 = 9 free
  // motions: 3 of each body alone (y, z, rotation about x) and 3 of both together as one
  // body (x, rotations about y and z through the pair's centre).
  FreeMotionFinder finder({{{0.5, 0.5, 0.5}, 1.7}, {{1.5, 0.5, 0.5}, 1.7}});
  Adder add{finder};
  for (const Point &p : square(0, 1.0))
    add.gap(0, 1, p, {1, 0, 0});
  EXPECT_EQ(
      described(finder),
      (std::vector<std::string>{
          "translation along y", "translation along z",
          "rotation about the axis (1, 0, 0) through (0.5, 0.5, 0.5)", "translation along y",
          "translation along z", "rotation about the axis (1, 0, 0) through (1.5, 0.5, 0.5)",
          "bodies 1 and 2 together: translation along x",
          "bodies 1 and 2 together: rotation about the axis (0, 1, 0) through (1, 0.5, 0.5)",
          "bodies 1 and 2 together: rotation about the axis (0, 0, 1) through (1, 0.5, 0.5)"}));
  for (const kiln::RigidMotion &m : finder.find(comm()))
    EXPECT_EQ(finder.bodies_moved(m).size(), finder.describe(m).rfind("bodies", 0) == 0 ? 2U : 1U);
}

TEST(FreeMotionFinder, AScrewIsNamedWithItsPitch)
{
  // The screw r(x) = e_z x x + e_z (pitch 1 m per radian about the z axis) is the one motion
  // that keeps u_x = u_y = 0 at (0, 0, 0) and (0, 0, 1) (which leaves a_z and w_z) and, at
  // (1, 0, 0) where it moves by (0, 1, 1), u_x = 0 and u.(0, 1, -1) = 0.
  FreeMotionFinder finder({{{0.0, 0.0, 0.0}, 2.0}});
  Adder add{finder};
  for (const Point &p : {Point{0, 0, 0}, Point{0, 0, 1}})
    for (const Point &d : {Point{1, 0, 0}, Point{0, 1, 0}})
      add.direction(0, p, d);
  // At (1, 0, 0) the screw moves by (0, 1, 1): hold (0, 1, -1)/sqrt2 and (1, 0, 0).
  const double s = 1.0 / std::sqrt(2.0);
  add.direction(0, {1, 0, 0}, {0, s, -s});
  add.direction(0, {1, 0, 0}, {1, 0, 0});
  EXPECT_EQ(described(finder),
            std::vector<std::string>{"rotation about the axis (0, 0, 1) through (0, 0, 0) with "
                                     "a translation along the axis of 1 m per radian"});
}
} // namespace
