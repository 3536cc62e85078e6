#pragma once
/// Convective heat loss through side sets.
#include "physics/boundary_condition.hpp"

namespace kiln
{
/// Outward flux h (T - T_ambient(t)) on the faces (ConvectionKernel): h = "Coefficient"
/// [W/(m^2 K)], T_ambient = "Ambient Temperature" [K].
class ConvectionCondition final : public BoundaryCondition
{
public:
  static std::string description();
  static Teuchos::ParameterList valid_parameters();
  explicit ConvectionCondition(const BoundaryConditionInput &input);

  bool is_constraint() const override { return false; }
  void evaluate(const FaceState &state, LocalSystem &local) const override;
  /// H constant (the ambient temperature only moves the residual).
  bool constant_jacobian() const override { return true; }
  /// h [W/(m^2 K)].
  double coefficient() const { return coefficient_; }
  /// T_ambient(t) [K].
  double ambient_temperature(const double t) const { return ambient_.value(t); }

private:
  double coefficient_;
  TimeFunction ambient_;
};
} // namespace kiln
