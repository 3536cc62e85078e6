#pragma once
/// A prescribed heat flux into the body through side sets.
#include "physics/boundary_condition.hpp"

namespace kiln
{
/// Flux q = Heat Flux(t) [W/m^2] into the body on the faces (HeatFluxKernel).
class HeatFluxCondition final : public BoundaryCondition
{
public:
  static std::string description();
  static Teuchos::ParameterList valid_parameters();
  explicit HeatFluxCondition(const BoundaryConditionInput &input);

  bool is_constraint() const override { return false; }
  void evaluate(const FaceState &state, LocalSystem &local) const override;
  /// No Jacobian.
  bool constant_jacobian() const override { return true; }
  /// q(t) [W/m^2].
  double flux(const double t) const { return flux_.value(t); }

private:
  TimeFunction flux_;
};
} // namespace kiln
