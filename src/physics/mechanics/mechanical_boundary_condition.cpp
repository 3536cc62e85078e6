#include "physics/mechanics/mechanical_boundary_condition.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "physics/boundary_input.hpp"

#include <Teuchos_Array.hpp>

#include <algorithm>
#include <map>

namespace kiln
{
namespace internal
{
const std::map<std::string, MechanicalBoundaryCondition::Type> mechanical_bc_types = {
    {"Normal Displacement", MechanicalBoundaryCondition::Type::normal_displacement},
    {"Displacement", MechanicalBoundaryCondition::Type::displacement},
    {"Traction", MechanicalBoundaryCondition::Type::traction},
    {"Pressure", MechanicalBoundaryCondition::Type::pressure}};

/// The parameters each Type reads besides Type and Side Sets.
const std::map<std::string, std::vector<std::string>> mechanical_bc_parameters = {
    {"Normal Displacement", {"Displacement"}},
    {"Displacement", {"Components", "Displacement"}},
    {"Traction", {"Traction"}},
    {"Pressure", {"Pressure"}}};
} // namespace internal

Teuchos::ParameterList MechanicalBoundaryCondition::valid_parameters()
{
  Teuchos::ParameterList p("Boundary Condition");
  p.set("Type", "Normal Displacement",
        "\"Normal Displacement\": u.n = Displacement(t) along the outward normal, free in the "
        "face's plane; \"Displacement\": the listed Components of u = Displacement(t); "
        "\"Traction\": a load vector per area; \"Pressure\": a load -p n per area",
        choice_validator({"Normal Displacement", "Displacement", "Traction", "Pressure"}));
  p.set("Side Sets", Teuchos::Array<int>(),
        "the mesh side set ids the condition applies to (at least one) [-]");
  p.sublist("Displacement", false,
            "for Types \"Normal Displacement\" and \"Displacement\": the prescribed value(t) "
            "(default 0) [m]; see TimeFunction")
      .setParameters(TimeFunction::valid_parameters());
  p.set("Components", Teuchos::Array<std::string>(),
        "for Type \"Displacement\", where it is required: the components set, any of x, y, z "
        "[-]");
  p.set("Traction", Teuchos::Array<double>(),
        "for Type \"Traction\", where it is required: the load per area (tx, ty, tz) [Pa]");
  p.sublist("Pressure", false,
            "for Type \"Pressure\": p(t), positive pushing into the body [Pa]; see TimeFunction")
      .setParameters(TimeFunction::valid_parameters());
  return p;
}

MechanicalBoundaryCondition::MechanicalBoundaryCondition(const std::string &name,
                                                         const Teuchos::ParameterList &p,
                                                         const Mesh &mesh, const std::string &where)
    : name_(name)
{
  const std::string path = where + "/" + name;
  const std::string type = p.get<std::string>("Type");
  type_ = internal::mechanical_bc_types.at(type);
  check_parameters_of_type(p, type, internal::mechanical_bc_parameters, path);
  side_sets_ = read_boundary_side_sets(p, mesh, path,
                                       "its two sides touch through frictionless contact "
                                       "(Mechanics/Contact), not a boundary condition");

  switch (type_)
  {
  case Type::normal_displacement:
    value_ = TimeFunction(p.sublist("Displacement"), path + "/Displacement");
    break;
  case Type::displacement:
  {
    value_ = TimeFunction(p.sublist("Displacement"), path + "/Displacement");
    const auto &names = p.get<Teuchos::Array<std::string>>("Components");
    KILN_CHECK_INPUT(!names.empty(), path + "/\"Components\"",
                     "is required for Type \"Displacement\": list the components to set, e.g. "
                     "<Parameter name=\"Components\" type=\"Array(string)\" value=\"{x, y, z}\"/>");
    for (const auto &c : names)
    {
      KILN_CHECK_INPUT(c == "x" || c == "y" || c == "z", path + "/\"Components\"",
                       "\"" << c << "\" is not a component; use x, y or z");
      const int d = c[0] - 'x';
      KILN_CHECK_INPUT(std::find(components_.begin(), components_.end(), d) == components_.end(),
                       path + "/\"Components\"", "lists " << c << " twice");
      components_.push_back(d);
    }
    break;
  }
  case Type::traction:
  {
    const auto &t = p.get<Teuchos::Array<double>>("Traction");
    KILN_CHECK_INPUT(t.size() == 3, path + "/\"Traction\"",
                     "must have 3 entries (tx, ty, tz) [Pa], has " << t.size());
    traction_ = {t[0], t[1], t[2]};
    break;
  }
  case Type::pressure:
    KILN_CHECK_INPUT(given_in_input(p, "Pressure"), path + "/\"Pressure\"",
                     "is required for Type \"Pressure\"; give it as a sublist, e.g. "
                     "<ParameterList name=\"Pressure\"><Parameter name=\"Value\" "
                     "type=\"double\" value=\"1e5\"/></ParameterList>");
    value_ = TimeFunction(p.sublist("Pressure"), path + "/Pressure");
    break;
  }
}
} // namespace kiln
