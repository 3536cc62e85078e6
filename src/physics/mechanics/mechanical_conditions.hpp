#pragma once
/// The mechanical boundary conditions Kiln has.
#include "physics/boundary_condition.hpp"

namespace kiln
{
/// Every type of Kiln/Mechanics/"Boundary Conditions", by its "Type" name; faces in no
/// condition are free of traction (mechanical_conditions.cpp: one line per type).
const BoundaryConditionRegistry &mechanical_conditions();
} // namespace kiln
