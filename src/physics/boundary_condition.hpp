#pragma once
/// A boundary condition of the input, on a set of side sets: either constraints on the nodes
/// of its faces, or terms on its faces.
#include "base/registry.hpp"
#include "discretization/nodal_constraints.hpp"
#include "mesh/mesh.hpp"
#include "physics/boundary_input.hpp"
#include "physics/kernel.hpp"
#include "physics/materials/time_function.hpp"

#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <string>
#include <vector>

namespace kiln
{
/// What a condition's constructor reads: the user's name of its sublist, the sublist
/// (validated), the mesh, its path in messages ("in.xml: Kiln/Thermal/Boundary
/// Conditions/hot end") and its side sets (checked: present, not the gap).
struct BoundaryConditionInput
{
  const std::string &name;
  const Teuchos::ParameterList &params;
  const Mesh &mesh;
  const std::string &path;
  const std::vector<int> &side_sets;
};

/// One condition. Each type is a class of its own (heat/*_condition, mechanics/*_condition)
/// with description() and valid_parameters() (its own parameters, besides Type and Side
/// Sets), registered by name in its physics' registry (heat/thermal_conditions.cpp,
/// mechanics/mechanical_conditions.cpp).
class BoundaryCondition : public FaceKernel
{
public:
  const std::string &name() const { return name_; }
  const std::vector<int> &side_sets() const { return side_sets_; }
  /// Whether the condition constrains the unknowns of its nodes (add_constraints) instead
  /// of adding terms on its faces (evaluate).
  virtual bool is_constraint() const = 0;
  /// Adds the condition's constraints at the nodes of its faces.
  virtual void add_constraints(const Mesh & /*mesh*/, NodalConstraints & /*constraints*/) const {}
  /// The terms on one of its faces; none by default.
  void evaluate(const FaceState & /*state*/, LocalSystem & /*local*/) const override {}

protected:
  explicit BoundaryCondition(const BoundaryConditionInput &input)
      : name_(input.name), side_sets_(input.side_sets)
  {
  }
  /// Calls f(node) once for every node of the condition's faces, side set after side set.
  template <typename F> void for_each_node(const Mesh &mesh, F &&f) const
  {
    for (const int id : side_sets_)
    {
      const SideSet &set = *mesh.find_side_set(id);
      for (int s = 0; s < set.n_sides(); ++s)
        for (const int node : mesh.face_nodes(set.cells[s], set.faces[s]))
          f(node);
    }
  }

private:
  std::string name_;
  std::vector<int> side_sets_;
};

using BoundaryConditionRegistry = Registry<BoundaryCondition, const BoundaryConditionInput &>;

/// The valid list of one condition sublist: "Type" (the registered names; the first is the
/// default), "Side Sets", and every type's own parameters (the doc strings of a parameter
/// that several types read are joined).
Teuchos::ParameterList boundary_condition_parameters(const BoundaryConditionRegistry &registry);

/// The conditions of `list` (validated: its sublists are named by the user), in input order.
/// Checks for each: no parameter of another Type, its side sets (`gap_note`: what happens at
/// the gap instead), then the type's own checks, then no face inside the body. `where`
/// names `list` ("in.xml: Kiln/Thermal/Boundary Conditions").
std::vector<std::unique_ptr<BoundaryCondition>> read_boundary_conditions(
    const BoundaryConditionRegistry &registry, const Teuchos::ParameterList &list, const Mesh &mesh,
    const InteriorFaceCheck &interior, const std::string &where, const std::string &gap_note);

/// The constraint values of a condition's function f: one value shared by every node when f
/// does not vary in space, else one per node, f(t, x_node) (x the node's reference position).
class NodalConstraintValues
{
public:
  NodalConstraintValues(const Mesh &mesh, NodalConstraints &constraints, const std::string &name,
                        const TimeFunction &f);
  /// The index of the value at `node` (NodalConstraints::add_value).
  int at(int node);

private:
  const Mesh &mesh_;
  NodalConstraints &constraints_;
  std::string name_;
  TimeFunction f_;
  int shared_ = -1; ///< the one value of a function constant in space
};

/// The positions of the nodes of a condition's faces (a node on several faces once per face):
/// where a formula of its values is checked at set-up.
std::vector<Point> condition_node_points(const BoundaryConditionInput &input);

/// The time function `name` of a condition, which its Type requires: InputError naming
/// it, with an example sublist whose value is `example`, if the input lacks it.
TimeFunction required_time_function(const BoundaryConditionInput &input, const std::string &name,
                                    const std::string &example);
} // namespace kiln
