#pragma once
/// A prescribed traction vector on side sets.
#include "physics/boundary_condition.hpp"

namespace kiln
{
/// A load t = "Traction" [Pa] (3 components, a fixed direction) on the faces, or t(x, t) by
/// "Traction Expressions" (three formulas in x, y, z, t) (TractionKernel).
class TractionCondition final : public BoundaryCondition
{
public:
  static std::string description();
  static Teuchos::ParameterList valid_parameters();
  explicit TractionCondition(const BoundaryConditionInput &input);

  bool is_constraint() const override { return false; }
  void evaluate(const FaceState &state, LocalSystem &local) const override;
  /// No Jacobian (the load does not follow the face).
  bool constant_jacobian() const override { return true; }
  /// t [Pa] (without Traction Expressions).
  const Point &traction() const { return traction_; }

private:
  Point traction_{};
  std::vector<TimeFunction> formulas_; ///< Traction Expressions: tx, ty, tz, or none
};
} // namespace kiln
