#include "physics/mechanics/displacement_condition.hpp"

#include "base/errors.hpp"
#include "mesh/side_set_nodes.hpp"

#include <Teuchos_Array.hpp>

#include <algorithm>
#include <vector>

namespace kiln
{
std::string DisplacementCondition::description()
{
  return "the listed Components of u = Displacement(t)";
}

Teuchos::ParameterList DisplacementCondition::valid_parameters()
{
  Teuchos::ParameterList p;
  p.set("Components", Teuchos::Array<std::string>(),
        "for Type \"Displacement\", where it is required: the components set, any of x, y, z "
        "[-]");
  p.sublist("Displacement", false,
            "for Type \"Displacement\": the value(t) of each listed component (default 0) [m], "
            "a function of time (doc/heat.md, Input)")
      .setParameters(TimeFunction::valid_parameters());
  return p;
}

DisplacementCondition::DisplacementCondition(const BoundaryConditionInput &input)
    : BoundaryCondition(input),
      displacement_(input.params.sublist("Displacement"), input.path + "/Displacement")
{
  const std::string where = input.path + "/\"Components\"";
  const auto &names = input.params.get<Teuchos::Array<std::string>>("Components");
  KILN_CHECK_INPUT(!names.empty(), where,
                   "is required for Type \"Displacement\": list the components to set, e.g. "
                   "<Parameter name=\"Components\" type=\"Array(string)\" value=\"{x, y, z}\"/>");
  for (const auto &c : names)
  {
    KILN_CHECK_INPUT(c == "x" || c == "y" || c == "z", where,
                     "\"" << c << "\" is not a component; use x, y or z");
    const int d = c[0] - 'x';
    KILN_CHECK_INPUT(std::find(components_.begin(), components_.end(), d) == components_.end(),
                     where, "lists " << c << " twice");
    components_.push_back(d);
  }
}

void DisplacementCondition::add_constraints(const Mesh &mesh, NodalConstraints &constraints) const
{
  NodalConstraintValues values(mesh, constraints, name(), displacement_);
  for (const int id : side_sets())
  {
    const SideSet &set = *mesh.find_side_set(id);
    // Each node once, in the order the faces reach it; `seen` per node of the set (its
    // position among side_set_nodes()), not per mesh node.
    const std::vector<int> nodes = side_set_nodes(mesh, set);
    std::vector<char> seen(nodes.size(), 0);
    for (int s = 0; s < set.n_sides(); ++s)
      for (const int node : mesh.face_nodes(set.cells[s], set.faces[s]))
      {
        const auto k = std::lower_bound(nodes.begin(), nodes.end(), node) - nodes.begin();
        if (seen[k]++)
          continue;
        const int value = values.at(node);
        for (const int c : components_)
        {
          Point e{};
          e[c] = 1.0;
          constraints.constrain_direction(node, e, value);
        }
      }
  }
}
} // namespace kiln
