#pragma once
/// A prescribed temperature on side sets.
#include "physics/boundary_condition.hpp"

namespace kiln
{
/// T = Temperature(t) [K] at the nodes of the faces, exactly (NodalConstraints).
class TemperatureCondition final : public BoundaryCondition
{
public:
  static std::string description();
  static Teuchos::ParameterList valid_parameters();
  explicit TemperatureCondition(const BoundaryConditionInput &input);

  bool is_constraint() const override { return true; }
  void add_constraints(const Mesh &mesh, NodalConstraints &constraints) const override;

private:
  TimeFunction temperature_;
};
} // namespace kiln
