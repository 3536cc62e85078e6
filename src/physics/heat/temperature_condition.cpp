#include "physics/heat/temperature_condition.hpp"

namespace kiln
{
std::string TemperatureCondition::description()
{
  return "prescribed temperature";
}

Teuchos::ParameterList TemperatureCondition::valid_parameters()
{
  Teuchos::ParameterList p;
  p.sublist("Temperature", false,
            "for Type \"Temperature\": T(t) [K], a function of time (doc/heat.md, Input)")
      .setParameters(TimeFunction::valid_parameters());
  return p;
}

TemperatureCondition::TemperatureCondition(const BoundaryConditionInput &input)
    : BoundaryCondition(input), temperature_(required_time_function(input, "Temperature", "300"))
{
}

void TemperatureCondition::add_constraints(const Mesh &mesh, NodalConstraints &constraints) const
{
  NodalConstraintValues values(mesh, constraints, name(), temperature_);
  for_each_node(mesh,
                [&](const int node) { constraints.constrain_temperature(node, values.at(node)); });
}
} // namespace kiln
