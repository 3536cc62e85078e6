#pragma once
/// A roller, or a prescribed normal motion, on side sets.
#include "physics/boundary_condition.hpp"

namespace kiln
{
/// u . n = Displacement(t) [m] at the nodes of the faces, n the outward normal of each side
/// set at the node (the area-weighted mean of its faces' normals there: exact on a plane
/// face); free in the face's plane. Side sets meeting at an edge give one constraint each.
class NormalDisplacementCondition final : public BoundaryCondition
{
public:
  static std::string description();
  static Teuchos::ParameterList valid_parameters();
  explicit NormalDisplacementCondition(const BoundaryConditionInput &input);

  bool is_constraint() const override { return true; }
  void add_constraints(const Mesh &mesh, NodalConstraints &constraints) const override;

private:
  TimeFunction displacement_;
};
} // namespace kiln
