#include "physics/heat/radiation_condition.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"

namespace kiln
{
std::string RadiationCondition::description()
{
  return "outward radiative flux Emissivity sigma (T^4 - Ambient Temperature^4)";
}

Teuchos::ParameterList RadiationCondition::valid_parameters()
{
  Teuchos::ParameterList p;
  p.set("Emissivity", 1.0,
        "for Type \"Radiation\", where it is required: eps of the grey surface, 0 <= eps <= 1 "
        "[-]",
        double_range_validator(0.0, 1.0));
  p.sublist("Ambient Temperature", false,
            "for Type \"Radiation\": the temperature of the surroundings T_amb(t) [K], a "
            "function of time (doc/heat.md, Input)")
      .setParameters(TimeFunction::valid_parameters());
  return p;
}

RadiationCondition::RadiationCondition(const BoundaryConditionInput &input)
    : BoundaryCondition(input), emissivity_(input.params.get<double>("Emissivity"))
{
  KILN_CHECK_INPUT(given_in_input(input.params, "Emissivity"), input.path + "/\"Emissivity\"",
                   "is required for Type \"Radiation\" (eps, 0 to 1), e.g. <Parameter "
                   "name=\"Emissivity\" type=\"double\" value=\"0.8\"/>");
  ambient_ = required_time_function(input, "Ambient Temperature", "300");
}

void RadiationCondition::evaluate(const FaceState &state, LocalSystem &local) const
{
  const FaceValues &fv = state.fv;
  const int T_field = state.slots.T;
  const double eps_sigma = emissivity_ * stefan_boltzmann;
  const ValueAt ambient(ambient_, state.time);
  for (int q = 0; q < fv.n_qpoints(); ++q)
  {
    const double T_amb = ambient(fv.quadrature_point(q));
    const double T_amb4 = T_amb * T_amb * T_amb * T_amb;
    double T = 0.0;
    for (int j = 0; j < fv.n_shape(); ++j)
      T += fv.shape(j, q) * state.T[j];
    const double T3 = T * T * T;
    const double JxW = fv.JxW(q);
    for (int i = 0; i < fv.n_shape(); ++i)
    {
      local.residual(T_field, i) += eps_sigma * (T3 * T - T_amb4) * fv.shape(i, q) * JxW;
      if (!local.has_jacobian())
        continue;
      for (int j = 0; j < fv.n_shape(); ++j)
        local.jacobian(T_field, i, T_field, j) +=
            4.0 * eps_sigma * T3 * fv.shape(j, q) * fv.shape(i, q) * JxW;
    }
  }
}
} // namespace kiln
