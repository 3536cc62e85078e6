#include "physics/materials/material.hpp"

#include "base/parameters.hpp"

namespace kiln
{
Teuchos::ParameterList Material::valid_parameters()
{
  Teuchos::ParameterList p("Material");
  p.set("Density", 2.7e3, "rho, must be > 0 [kg/m^3]", positive_double_validator());
  p.set("Specific Heat", 9.0e2, "c, must be > 0 [J/(kg K)]", positive_double_validator());
  Teuchos::ParameterList k = ConductivityModel::valid_parameters();
  k.set("Value", 2.4e2, "k for Type \"Constant\", must be > 0 [W/(m K)]",
        positive_double_validator());
  p.sublist("Conductivity", false, "thermal conductivity k(T); see ConductivityModel")
      .setParameters(k);
  return p;
}

Material::Material(const Teuchos::ParameterList &p, const std::string &where)
    : density_(p.get<double>("Density")), specific_heat_(p.get<double>("Specific Heat")),
      conductivity_(p.sublist("Conductivity"), where + "/Conductivity")
{
}
} // namespace kiln
