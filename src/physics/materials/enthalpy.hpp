#pragma once
/// The enthalpy per volume of a material, H(T) = ∫ rho(s) c(s) ds [J/m^3].
#include "physics/materials/temperature_function.hpp"

#include <vector>

namespace kiln
{
/// H(T) = H(T_0) + ∫_{T_0}^{T} rho(s) c(s) ds [J/m^3], dH/dT = rho(T) c(T) [J/(m^3 K)]
/// (doc/heat.md, "Conservative capacity"). Only differences of H enter the heat equation; the
/// constant is fixed by H(T_0) = rho(T_0) c(T_0) T_0 at the lowest anchor T_0, so that a
/// constant rho c gives H = rho c T (the thermal energy of the time history).
///
/// The integral is kept at anchor temperatures T_k and completed from the anchor below T by
/// Gauss-Legendre quadrature:
/// - both constant: no anchors, H = rho c T exactly (is_linear());
/// - tables: the anchors are the union of both tables' temperatures; between two of them
///   rho c is a product of linear functions, a quadratic, which the 2-point rule integrates
///   exactly (to rounding), and beyond the ends rho c is constant;
/// - a formula: anchors every at most `panel` K over its sample temperatures ("Temperatures",
///   which the user sets to the run's range) and panels of at most `panel` K beyond them, the
///   5-point rule on each; a smooth rho c is integrated to about 1e-12 relative.
class Enthalpy
{
public:
  /// The widest panel of the quadrature for a formula [K].
  static constexpr double panel = 10.0;
  /// rho [kg/m^3] and c [J/(kg K)], each of T [K].
  Enthalpy(TemperatureFunction density, TemperatureFunction specific_heat);
  /// A constant rho c [J/(m^3 K)].
  static Enthalpy constant(double rho_c);

  /// H(T) [J/m^3], T [K].
  double value(double T) const;
  /// dH/dT = rho(T) c(T) [J/(m^3 K)].
  double heat_capacity(double T) const { return density_.value(T) * specific_heat_.value(T); }
  /// Whether rho c does not depend on T (H = rho c T).
  bool is_linear() const { return density_.is_constant() && specific_heat_.is_constant(); }

private:
  /// ∫_{from}^{to} rho c dT: 2-point Gauss-Legendre on one panel (tables: between two
  /// anchors, or beyond the ends, rho c is a quadratic or a constant) or, with a formula,
  /// 5-point on panels of at most `panel` K.
  double integral(double from, double to) const;

  TemperatureFunction density_;
  TemperatureFunction specific_heat_;
  std::vector<double> anchor_T_; ///< T_k, increasing (empty if is_linear())
  std::vector<double> anchor_H_; ///< H(T_k)
  bool formula_ = false;         ///< a formula among rho and c: panels of at most `panel`
};
} // namespace kiln
