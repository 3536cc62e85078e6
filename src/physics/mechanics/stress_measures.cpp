#include "physics/mechanics/stress_measures.hpp"

#include <algorithm>
#include <cmath>

namespace kiln
{
double von_mises(const Voigt &s)
{
  const double d01 = s[0] - s[1], d12 = s[1] - s[2], d20 = s[2] - s[0];
  return std::sqrt(0.5 * (d01 * d01 + d12 * d12 + d20 * d20) +
                   3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

double pressure(const Voigt &s)
{
  return -(s[0] + s[1] + s[2]) / 3.0;
}

std::array<double, 3> principal_values(const Voigt &s)
{
  // The trigonometric solution of the characteristic cubic of the deviator (Smith 1961):
  // eig = m + 2 sqrt(J2/3) cos(theta + 2 pi k/3), cos(3 theta) = (J3/2) (3/J2)^(3/2).
  const double m = (s[0] + s[1] + s[2]) / 3.0;
  const double a = s[0] - m, b = s[1] - m, c = s[2] - m;
  const double xy = s[3], xz = s[4], yz = s[5];
  const double J2 = 0.5 * (a * a + b * b + c * c) + xy * xy + xz * xz + yz * yz;
  if (J2 <= 1e-30 * (m * m + 1e-300))
    return {m, m, m};
  const double J3 = a * (b * c - yz * yz) - xy * (xy * c - yz * xz) + xz * (xy * yz - b * xz);
  const double r = std::clamp(0.5 * J3 * std::pow(3.0 / J2, 1.5), -1.0, 1.0);
  const double theta = std::acos(r) / 3.0;
  const double radius = 2.0 * std::sqrt(J2 / 3.0);
  const double pi = std::acos(-1.0);
  std::array<double, 3> e = {m + radius * std::cos(theta),
                             m + radius * std::cos(theta - 2.0 * pi / 3.0),
                             m + radius * std::cos(theta + 2.0 * pi / 3.0)};
  std::sort(e.begin(), e.end(), std::greater<>());
  return e;
}
} // namespace kiln
