#pragma once
/// Prescribed displacement components on side sets.
#include "physics/boundary_condition.hpp"

namespace kiln
{
/// u_c = Displacement(t) [m] for each listed component c of "Components" (x, y, z) at the
/// nodes of the faces.
class DisplacementCondition final : public BoundaryCondition
{
public:
  static std::string description();
  static Teuchos::ParameterList valid_parameters();
  explicit DisplacementCondition(const BoundaryConditionInput &input);

  bool is_constraint() const override { return true; }
  void add_constraints(const Mesh &mesh, NodalConstraints &constraints) const override;
  /// The constrained components (0 x, 1 y, 2 z), in input order.
  const std::vector<int> &components() const { return components_; }

private:
  TimeFunction displacement_;
  std::vector<int> components_;
};
} // namespace kiln
