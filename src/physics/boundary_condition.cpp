#include "physics/boundary_condition.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"

#include <Teuchos_Array.hpp>

#include <map>

namespace kiln
{
Teuchos::ParameterList boundary_condition_parameters(const BoundaryConditionRegistry &registry)
{
  Teuchos::ParameterList p("Boundary Condition");
  p.set("Type", registry.names().front(), registry.describe(), choice_validator(registry.names()));
  p.set("Side Sets", Teuchos::Array<int>(),
        "the mesh side set ids the condition applies to (at least one) [-]");
  for (const auto &entry : registry.entries())
    for (auto it = entry.parameters.begin(); it != entry.parameters.end(); ++it)
    {
      const std::string &name = entry.parameters.name(it);
      const Teuchos::ParameterEntry &e = entry.parameters.entry(it);
      if (!p.isParameter(name))
        p.setEntry(name, e);
      else
      {
        // Read by several types: one entry, both docs.
        const auto joined = p.getEntryRCP(name);
        joined->setDocString(joined->docString() + "; " + e.docString());
      }
    }
  return p;
}

std::vector<std::unique_ptr<BoundaryCondition>> read_boundary_conditions(
    const BoundaryConditionRegistry &registry, const Teuchos::ParameterList &list, const Mesh &mesh,
    const InteriorFaceCheck &interior, const std::string &where, const std::string &gap_note)
{
  // The parameters each Type reads besides Type and Side Sets.
  std::map<std::string, std::vector<std::string>> parameters_of_type;
  for (const auto &entry : registry.entries())
  {
    auto &names = parameters_of_type[entry.name];
    for (auto it = entry.parameters.begin(); it != entry.parameters.end(); ++it)
      names.push_back(entry.parameters.name(it));
  }
  std::vector<std::unique_ptr<BoundaryCondition>> conditions;
  for (auto it = list.begin(); it != list.end(); ++it)
  {
    const std::string &name = list.name(it);
    const Teuchos::ParameterList &p = list.sublist(name);
    const std::string path = where + "/" + name;
    const std::string type = p.get<std::string>("Type");
    check_parameters_of_type(p, type, parameters_of_type, path);
    const std::vector<int> side_sets = read_boundary_side_sets(p, mesh, path, gap_note);
    conditions.push_back(registry.create(type, {name, p, mesh, path, side_sets}));
    interior.check(side_sets, path + "/\"Side Sets\"");
  }
  return conditions;
}

NodalConstraintValues::NodalConstraintValues(const Mesh &mesh, NodalConstraints &constraints,
                                             const std::string &name, const TimeFunction &f)
    : mesh_(mesh), constraints_(constraints), name_(name), f_(f)
{
  if (!f_.varies_in_space())
  {
    const TimeFunction g = f_;
    shared_ = constraints_.add_value(name_, [g](const double t) { return g.value(t); });
  }
}

int NodalConstraintValues::at(const int node)
{
  if (shared_ >= 0)
    return shared_;
  const TimeFunction g = f_;
  const Point x = mesh_.coordinates[node];
  return constraints_.add_value(name_, [g, x](const double t) { return g.value(t, x); });
}

std::vector<Point> condition_node_points(const BoundaryConditionInput &input)
{
  std::vector<Point> points;
  for (const int id : input.side_sets)
  {
    const SideSet &set = *input.mesh.find_side_set(id);
    for (int s = 0; s < set.n_sides(); ++s)
      for (const int node : input.mesh.face_nodes(set.cells[s], set.faces[s]))
        points.push_back(input.mesh.coordinates[node]);
  }
  return points;
}

TimeFunction required_time_function(const BoundaryConditionInput &input, const std::string &name,
                                    const std::string &example)
{
  KILN_CHECK_INPUT(given_in_input(input.params, name), input.path + "/\"" + name + "\"",
                   "is required for Type \""
                       << input.params.get<std::string>("Type")
                       << "\"; give it as a sublist, e.g. <ParameterList name=\"" << name
                       << "\"><Parameter name=\"Value\" type=\"double\" value=\"" << example
                       << "\"/></ParameterList>");
  TimeFunction f(input.params.sublist(name), input.path + "/" + name);
  if (f.varies_in_space())
  {
    // The formula at every node of the condition's faces at t = 0: finite, or an InputError
    // at --check rather than a NaN in the first step.
    f.check_finite(condition_node_points(input), 0.0, input.path + "/" + name);
  }
  return f;
}
} // namespace kiln
