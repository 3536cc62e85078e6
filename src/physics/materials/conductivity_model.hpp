#pragma once
/// Thermal conductivity as a function of temperature, k(T) [W/(m K)]: a TemperatureFunction
/// (one home for a property of T; this name stays for the heat kernel and its tests). Its input
/// is the "Conductivity" sublist ("Type", "Value", "Temperatures", "Values", "Expression"), or
/// a plain number.
#include "physics/materials/temperature_function.hpp"

namespace kiln
{
using ConductivityModel = TemperatureFunction;
} // namespace kiln
