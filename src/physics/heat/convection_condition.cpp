#include "physics/heat/convection_condition.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "physics/heat/convection_kernel.hpp"

namespace kiln
{
std::string ConvectionCondition::description()
{
  return "outward flux Coefficient (T - Ambient Temperature)";
}

Teuchos::ParameterList ConvectionCondition::valid_parameters()
{
  Teuchos::ParameterList p;
  p.set("Coefficient", 0.0,
        "for Type \"Convection\", where it is required: h, must be >= 0 [W/(m^2 K)]",
        nonnegative_double_validator());
  p.sublist("Ambient Temperature", false,
            "for Type \"Convection\": T_ambient(t) [K], a function of time (doc/heat.md, Input)")
      .setParameters(TimeFunction::valid_parameters());
  return p;
}

ConvectionCondition::ConvectionCondition(const BoundaryConditionInput &input)
    : BoundaryCondition(input), coefficient_(input.params.get<double>("Coefficient"))
{
  KILN_CHECK_INPUT(given_in_input(input.params, "Coefficient"), input.path + "/\"Coefficient\"",
                   "is required for Type \"Convection\" (h [W/(m^2 K)]), e.g. <Parameter "
                   "name=\"Coefficient\" type=\"double\" value=\"50\"/>");
  ambient_ = required_time_function(input, "Ambient Temperature", "300");
}

void ConvectionCondition::evaluate(const FaceState &state, LocalSystem &local) const
{
  ConvectionKernel(coefficient_).evaluate(state.fv, state.T, ValueAt(ambient_, state.time), local);
}
} // namespace kiln
