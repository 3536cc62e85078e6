#include "physics/heat/thermal_boundary_condition.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "physics/boundary_input.hpp"

#include <Teuchos_Array.hpp>

#include <map>

namespace kiln
{
namespace internal
{
const std::map<std::string, ThermalBoundaryCondition::Type> thermal_bc_types = {
    {"Temperature", ThermalBoundaryCondition::Type::temperature},
    {"Heat Flux", ThermalBoundaryCondition::Type::heat_flux},
    {"Convection", ThermalBoundaryCondition::Type::convection}};

/// The parameters each Type reads besides Type and Side Sets.
const std::map<std::string, std::vector<std::string>> thermal_bc_parameters = {
    {"Temperature", {"Temperature"}},
    {"Heat Flux", {"Heat Flux"}},
    {"Convection", {"Coefficient", "Ambient Temperature"}}};
} // namespace internal

Teuchos::ParameterList ThermalBoundaryCondition::valid_parameters()
{
  Teuchos::ParameterList p("Boundary Condition");
  p.set("Type", "Temperature",
        "\"Temperature\": prescribed temperature; \"Heat Flux\": prescribed flux into the "
        "body; \"Convection\": outward flux Coefficient (T - Ambient Temperature)",
        choice_validator({"Temperature", "Heat Flux", "Convection"}));
  p.set("Side Sets", Teuchos::Array<int>(),
        "the mesh side set ids the condition applies to (at least one) [-]");
  p.sublist("Temperature", false, "for Type \"Temperature\": T(t) [K]; see TimeFunction")
      .setParameters(TimeFunction::valid_parameters());
  p.sublist("Heat Flux", false,
            "for Type \"Heat Flux\": q(t) into the body [W/m^2]; see TimeFunction")
      .setParameters(TimeFunction::valid_parameters());
  p.set("Coefficient", 0.0,
        "for Type \"Convection\", where it is required: h, must be >= 0 [W/(m^2 K)]",
        nonnegative_double_validator());
  p.sublist("Ambient Temperature", false,
            "for Type \"Convection\": T_ambient(t) [K]; see TimeFunction")
      .setParameters(TimeFunction::valid_parameters());
  return p;
}

ThermalBoundaryCondition::ThermalBoundaryCondition(const std::string &name,
                                                   const Teuchos::ParameterList &p,
                                                   const Mesh &mesh, const std::string &where)
    : name_(name)
{
  const std::string path = where + "/" + name;
  const std::string type = p.get<std::string>("Type");
  type_ = internal::thermal_bc_types.at(type);
  check_parameters_of_type(p, type, internal::thermal_bc_parameters, path);
  side_sets_ = read_boundary_side_sets(p, mesh, path,
                                       "heat crosses it through Kiln/Thermal/\"Gap Conductance\"");

  if (type_ == Type::convection)
  {
    coefficient_ = p.get<double>("Coefficient");
    KILN_CHECK_INPUT(given_in_input(p, "Coefficient"), path + "/\"Coefficient\"",
                     "is required for Type \"Convection\" (h [W/(m^2 K)]), e.g. <Parameter "
                     "name=\"Coefficient\" type=\"double\" value=\"50\"/>");
  }
  const std::string function = internal::thermal_bc_parameters.at(type).back();
  KILN_CHECK_INPUT(given_in_input(p, function), path + "/\"" + function + "\"",
                   "is required for Type \"" << type << "\"; give it as a sublist, e.g. "
                                             << "<ParameterList name=\"" << function
                                             << "\"><Parameter name=\"Value\" type=\"double\" "
                                                "value=\"300\"/></ParameterList>");
  value_ = TimeFunction(p.sublist(function), path + "/" + function);
}
} // namespace kiln
