#pragma once
/// One mechanical boundary condition of the input, on a set of side sets.
#include "mesh/mesh.hpp"
#include "physics/materials/time_function.hpp"

#include <Teuchos_ParameterList.hpp>

#include <array>
#include <string>
#include <vector>

namespace kiln
{
/// A sublist of Kiln/Mechanics/"Boundary Conditions", named by the user:
/// - "Normal Displacement": u . n = Displacement(t) at the faces' nodes, n the outward
///   normal of the side set at the node; free in the face's plane (a roller, or a
///   prescribed normal motion). Enforced exactly: the node's displacement unknowns are
///   rotated into a frame whose first axes are the constrained directions.
/// - "Displacement": u_c = Displacement(t) for each listed component c of "Components"
///   (x, y, z) at the faces' nodes.
/// - "Traction": a load t = "Traction" [Pa] (3 components, fixed direction) on the faces.
/// - "Pressure": t = -Pressure(t) n on the faces (n the outward normal; p > 0 pushes).
/// Faces in no condition are traction-free. Side sets must exist and must not be the gap.
class MechanicalBoundaryCondition
{
public:
  enum class Type
  {
    normal_displacement,
    displacement,
    traction,
    pressure
  };
  static Teuchos::ParameterList valid_parameters();
  /// `p` (validated against valid_parameters()) is the sublist called `name`; `where`
  /// names the block ("in.xml: Kiln/Mechanics/Boundary Conditions").
  MechanicalBoundaryCondition(const std::string &name, const Teuchos::ParameterList &p,
                              const Mesh &mesh, const std::string &where);

  const std::string &name() const { return name_; }
  Type type() const { return type_; }
  bool is_constraint() const
  {
    return type_ == Type::normal_displacement || type_ == Type::displacement;
  }
  const std::vector<int> &side_sets() const { return side_sets_; }
  /// Displacement [m] or Pressure [Pa] at t [s].
  double value(const double t) const { return value_.value(t); }
  /// "Displacement": the constrained components (0 x, 1 y, 2 z), in input order.
  const std::vector<int> &components() const { return components_; }
  /// "Traction" [Pa].
  const Point &traction() const { return traction_; }

private:
  std::string name_;
  Type type_ = Type::normal_displacement;
  std::vector<int> side_sets_;
  TimeFunction value_;
  std::vector<int> components_;
  Point traction_{};
};
} // namespace kiln
