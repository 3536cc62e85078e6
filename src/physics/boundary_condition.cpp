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

TimeFunction required_time_function(const BoundaryConditionInput &input, const std::string &name,
                                    const std::string &example)
{
  KILN_CHECK_INPUT(given_in_input(input.params, name), input.path + "/\"" + name + "\"",
                   "is required for Type \""
                       << input.params.get<std::string>("Type")
                       << "\"; give it as a sublist, e.g. <ParameterList name=\"" << name
                       << "\"><Parameter name=\"Value\" type=\"double\" value=\"" << example
                       << "\"/></ParameterList>");
  return TimeFunction(input.params.sublist(name), input.path + "/" + name);
}
} // namespace kiln
