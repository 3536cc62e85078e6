#pragma once
/// A prescribed pressure on side sets.
#include "physics/boundary_condition.hpp"

namespace kiln
{
/// A load t = -Pressure(t) n [Pa] on the faces, n the outward normal (p > 0 pushes;
/// TractionKernel::evaluate_pressure).
class PressureCondition final : public BoundaryCondition
{
public:
  static std::string description();
  static Teuchos::ParameterList valid_parameters();
  explicit PressureCondition(const BoundaryConditionInput &input);

  bool is_constraint() const override { return false; }
  void evaluate(const FaceState &state, LocalSystem &local) const override;
  /// No Jacobian (the load does not follow the face).
  bool constant_jacobian() const override { return true; }
  /// p(t) [Pa].
  double pressure(const double t) const { return pressure_.value(t); }

private:
  TimeFunction pressure_;
};
} // namespace kiln
