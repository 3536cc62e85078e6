// Tests src/physics/mechanics/stress_measures.cpp: von Mises stress, pressure and principal
// stresses against closed forms (uniaxial, pure shear, hydrostatic) and against a rotated
// diagonal tensor (the principal values are the diagonal, whatever the rotation; the von
// Mises stress and the pressure are invariant).
#include "physics/mechanics/stress_measures.hpp"

#include "mesh/hex_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
/// A diag(d) A^T in Voigt order (xx yy zz xy xz yz).
kiln::Voigt rotated(const std::array<double, 3> &d, const double phi, const double theta)
{
  const auto A = kiln::rotation_matrix(phi, theta);
  double s[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        s[i][j] += A[i][k] * d[k] * A[j][k];
  return {s[0][0], s[1][1], s[2][2], s[0][1], s[0][2], s[1][2]};
}
} // namespace

TEST(StressMeasures, ClosedForms)
{
  const kiln::Voigt uniaxial = {100.0, 0, 0, 0, 0, 0};
  EXPECT_DOUBLE_EQ(kiln::von_mises(uniaxial), 100.0);
  EXPECT_DOUBLE_EQ(kiln::pressure(uniaxial), -100.0 / 3.0);
  const kiln::Voigt shear = {0, 0, 0, 50.0, 0, 0};
  EXPECT_NEAR(kiln::von_mises(shear), 50.0 * std::sqrt(3.0), 1e-12);
  const auto p = kiln::principal_values(shear);
  EXPECT_NEAR(p[0], 50.0, 1e-12);
  EXPECT_NEAR(p[1], 0.0, 1e-12);
  EXPECT_NEAR(p[2], -50.0, 1e-12);
  const kiln::Voigt hydrostatic = {-7.0, -7.0, -7.0, 0, 0, 0};
  EXPECT_EQ(kiln::von_mises(hydrostatic), 0.0);
  EXPECT_EQ(kiln::pressure(hydrostatic), 7.0);
  EXPECT_EQ(kiln::principal_values(hydrostatic), (std::array<double, 3>{-7.0, -7.0, -7.0}));
}

TEST(StressMeasures, InvariantUnderRotation)
{
  const std::array<double, 3> d = {-2.288e7, 3.1e6, 1.4e7};
  const kiln::Voigt s = rotated(d, 45.0, -30.0);
  const auto p = kiln::principal_values(s);
  EXPECT_NEAR(p[0], 1.4e7, 1e-7 * 2.3e7);
  EXPECT_NEAR(p[1], 3.1e6, 1e-7 * 2.3e7);
  EXPECT_NEAR(p[2], -2.288e7, 1e-7 * 2.3e7);
  const kiln::Voigt diagonal = {d[0], d[1], d[2], 0, 0, 0};
  EXPECT_NEAR(kiln::von_mises(s), kiln::von_mises(diagonal), 1e-9 * 2.3e7);
  EXPECT_NEAR(kiln::pressure(s), kiln::pressure(diagonal), 1e-9 * 2.3e7);
  // Two equal values (the contact box's closed state: sigma' xx = sigma' zz in the block frame)
  // to round-off, not to the square root of it.
  const auto q = kiln::principal_values(rotated({-5.0, -5.0, 2.0}, 30.0, 10.0));
  EXPECT_NEAR(q[0], 2.0, 1e-14);
  EXPECT_NEAR(q[1], -5.0, 1e-14);
  EXPECT_NEAR(q[2], -5.0, 1e-14);
  // A rank-one stress (the contact box at t = 0): its zero eigenvalues to 1e-15 of the other.
  const auto r = kiln::principal_values(rotated({1.5253e7, 0.0, 0.0}, 45.0, -30.0));
  EXPECT_NEAR(r[0], 1.5253e7, 1e-8);
  EXPECT_NEAR(r[1], 0.0, 1e-7);
  EXPECT_NEAR(r[2], 0.0, 1e-7);
}
