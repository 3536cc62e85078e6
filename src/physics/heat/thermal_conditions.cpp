// The registration list of the thermal boundary conditions: a new condition is a new class in
// its own files and one line here (doc/architecture.md).
#include "physics/heat/thermal_conditions.hpp"

#include "physics/heat/convection_condition.hpp"
#include "physics/heat/heat_flux_condition.hpp"
#include "physics/heat/radiation_condition.hpp"
#include "physics/heat/temperature_condition.hpp"

namespace kiln
{
const BoundaryConditionRegistry &thermal_conditions()
{
  static const BoundaryConditionRegistry registry = []
  {
    BoundaryConditionRegistry r;
    r.add<TemperatureCondition>("Temperature");
    r.add<HeatFluxCondition>("Heat Flux");
    r.add<ConvectionCondition>("Convection");
    r.add<RadiationCondition>("Radiation");
    return r;
  }();
  return registry;
}
} // namespace kiln
