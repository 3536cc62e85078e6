#include "physics/materials/enthalpy.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace kiln
{
namespace
{
/// The temperatures where rho c may have a kink (a table's points), and a formula's sample
/// range cut into panels of at most Enthalpy::panel.
void add_anchors(const TemperatureFunction &f, std::vector<double> &anchors)
{
  const std::vector<double> &T = f.checked_temperatures();
  if (f.is_constant() || T.empty())
    return;
  if (!f.is_expression())
  {
    anchors.insert(anchors.end(), T.begin(), T.end());
    return;
  }
  const double low = *std::min_element(T.begin(), T.end());
  const double high = *std::max_element(T.begin(), T.end());
  const int n = std::max(1, static_cast<int>(std::ceil((high - low) / Enthalpy::panel)));
  for (int i = 0; i <= n; ++i)
    anchors.push_back(low + (high - low) * i / n);
}
} // namespace

Enthalpy::Enthalpy(TemperatureFunction density, TemperatureFunction specific_heat)
    : density_(std::move(density)), specific_heat_(std::move(specific_heat))
{
  if (is_linear())
    return;
  formula_ = (!density_.is_constant() && density_.is_expression()) ||
             (!specific_heat_.is_constant() && specific_heat_.is_expression());
  add_anchors(density_, anchor_T_);
  add_anchors(specific_heat_, anchor_T_);
  std::sort(anchor_T_.begin(), anchor_T_.end());
  anchor_T_.erase(std::unique(anchor_T_.begin(), anchor_T_.end()), anchor_T_.end());
  if (anchor_T_.empty()) // a formula that names T without sample temperatures
    anchor_T_.push_back(298.0);
  anchor_H_.resize(anchor_T_.size());
  anchor_H_[0] = heat_capacity(anchor_T_[0]) * anchor_T_[0];
  for (std::size_t k = 1; k < anchor_T_.size(); ++k)
    anchor_H_[k] = anchor_H_[k - 1] + integral(anchor_T_[k - 1], anchor_T_[k]);
}

Enthalpy Enthalpy::constant(const double rho_c)
{
  return Enthalpy(TemperatureFunction::constant(rho_c), TemperatureFunction::constant(1.0));
}

double Enthalpy::integral(const double from, const double to) const
{
  // 5-point Gauss-Legendre on [-1, 1]: exact for polynomials of degree 9.
  static constexpr double x[5] = {0.0, 0.5384693101056831, -0.5384693101056831, 0.9061798459386640,
                                  -0.9061798459386640};
  static constexpr double w[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                  0.2369268850561891, 0.2369268850561891};
  if (!formula_)
  {
    // Tables: rho c is a quadratic (or a constant) on [from, to], which 2-point
    // Gauss-Legendre integrates exactly.
    const double middle = 0.5 * (from + to), half = 0.5 * (to - from);
    const double offset = half / std::sqrt(3.0);
    return half * (heat_capacity(middle - offset) + heat_capacity(middle + offset));
  }
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(to - from) / panel)));
  const double h = (to - from) / n;
  double sum = 0.0;
  for (int p = 0; p < n; ++p)
  {
    const double middle = from + (p + 0.5) * h;
    for (int q = 0; q < 5; ++q)
      sum += w[q] * heat_capacity(middle + 0.5 * h * x[q]);
  }
  return 0.5 * h * sum;
}

double Enthalpy::value(const double T) const
{
  if (anchor_T_.empty())
    return heat_capacity(T) * T;
  // The anchor at or below T (the lowest one for T below all of them).
  const auto above = std::upper_bound(anchor_T_.begin(), anchor_T_.end(), T);
  const std::size_t k = above == anchor_T_.begin() ? 0 : (above - anchor_T_.begin()) - 1;
  return anchor_H_[k] + integral(anchor_T_[k], T);
}
} // namespace kiln
