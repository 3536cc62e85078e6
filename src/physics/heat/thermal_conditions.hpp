#pragma once
/// The thermal boundary conditions Kiln has.
#include "physics/boundary_condition.hpp"

namespace kiln
{
/// Every type of Kiln/Thermal/"Boundary Conditions", by its "Type" name; faces in no
/// condition are insulated (thermal_conditions.cpp: one line per type).
const BoundaryConditionRegistry &thermal_conditions();
} // namespace kiln
