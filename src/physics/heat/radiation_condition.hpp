#pragma once
/// Thermal radiation to the surroundings through side sets.
#include "physics/boundary_condition.hpp"

namespace kiln
{
/// Radiation from a grey surface to surroundings at T_amb(t): the outward flux is
/// eps sigma (T^4 - T_amb^4) with eps = "Emissivity" and sigma the Stefan-Boltzmann
/// constant. On each face, with T interpolated from its 4 nodes at the 2x2 Gauss points:
///
///   R_i       = ∫ eps sigma (T^4 - T_amb^4) φ_i dΓ
///   dR_i/dT_j = ∫ 4 eps sigma T^3 φ_j φ_i dΓ
///
/// Touches the temperature rows and columns of a 4-node local system (face-node order).
class RadiationCondition final : public BoundaryCondition
{
public:
  /// sigma [W/(m^2 K^4)] (CODATA 2018, exact).
  static constexpr double stefan_boltzmann = 5.670374419e-8;

  static std::string description();
  static Teuchos::ParameterList valid_parameters();
  explicit RadiationCondition(const BoundaryConditionInput &input);

  bool is_constraint() const override { return false; }
  void evaluate(const FaceState &state, LocalSystem &local) const override;
  /// eps [-].
  double emissivity() const { return emissivity_; }
  /// T_amb(t) [K].
  double ambient_temperature(const double t) const { return ambient_.value(t); }

private:
  double emissivity_;
  TimeFunction ambient_;
};
} // namespace kiln
