// The registration list of the mechanical boundary conditions: a new condition is a new class
// in its own files and one line here (doc/architecture.md).
#include "physics/mechanics/mechanical_conditions.hpp"

#include "physics/mechanics/displacement_condition.hpp"
#include "physics/mechanics/normal_displacement_condition.hpp"
#include "physics/mechanics/pressure_condition.hpp"
#include "physics/mechanics/traction_condition.hpp"

namespace kiln
{
const BoundaryConditionRegistry &mechanical_conditions()
{
  static const BoundaryConditionRegistry registry = []
  {
    BoundaryConditionRegistry r;
    r.add<NormalDisplacementCondition>("Normal Displacement");
    r.add<DisplacementCondition>("Displacement");
    r.add<TractionCondition>("Traction");
    r.add<PressureCondition>("Pressure");
    return r;
  }();
  return registry;
}
} // namespace kiln
