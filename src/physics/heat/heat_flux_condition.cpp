#include "physics/heat/heat_flux_condition.hpp"

#include "physics/heat/heat_flux_kernel.hpp"

namespace kiln
{
std::string HeatFluxCondition::description()
{
  return "prescribed flux into the body";
}

Teuchos::ParameterList HeatFluxCondition::valid_parameters()
{
  Teuchos::ParameterList p;
  p.sublist("Heat Flux", false,
            "for Type \"Heat Flux\": q(t) into the body [W/m^2], a function of time (doc/heat.md, "
            "Input)")
      .setParameters(TimeFunction::valid_parameters());
  return p;
}

HeatFluxCondition::HeatFluxCondition(const BoundaryConditionInput &input)
    : BoundaryCondition(input), flux_(required_time_function(input, "Heat Flux", "300"))
{
}

void HeatFluxCondition::evaluate(const FaceState &state, LocalSystem &local) const
{
  HeatFluxKernel::evaluate(state.fv, ValueAt(flux_, state.time), local);
}
} // namespace kiln
