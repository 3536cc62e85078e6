#include "physics/mechanics/pressure_condition.hpp"

#include "physics/mechanics/traction_kernel.hpp"

namespace kiln
{
std::string PressureCondition::description()
{
  return "a load -p n per area";
}

Teuchos::ParameterList PressureCondition::valid_parameters()
{
  Teuchos::ParameterList p;
  p.sublist("Pressure", false,
            "for Type \"Pressure\": p(t), positive pushing into the body [Pa], a function of time "
            "(doc/heat.md, Input)")
      .setParameters(TimeFunction::valid_parameters());
  return p;
}

PressureCondition::PressureCondition(const BoundaryConditionInput &input)
    : BoundaryCondition(input), pressure_(required_time_function(input, "Pressure", "1e5"))
{
}

void PressureCondition::evaluate(const FaceState &state, LocalSystem &local) const
{
  TractionKernel::evaluate_pressure(state.fv, ValueAt(pressure_, state.time), state.slots.u, local);
}
} // namespace kiln
