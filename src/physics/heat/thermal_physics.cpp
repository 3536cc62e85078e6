#include "physics/heat/thermal_physics.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "physics/heat/contact_conductance_kernel.hpp"
#include "physics/heat/gap_conductance_kernel.hpp"
#include "physics/heat/thermal_conditions.hpp"

namespace kiln
{
Teuchos::ParameterList ThermalPhysics::valid_parameters()
{
  Teuchos::ParameterList p("Thermal");
  p.set("Initial Temperature", 298.0, "the uniform initial temperature, must be > 0 [K]",
        positive_double_validator());
  p.set("Capacity", "Lumped",
        "the heat-capacity matrix: \"Lumped\" (rows' sums on the diagonal: no temperature "
        "below the initial after a thermal shock; with backward Euler none outside the data's "
        "range) or \"Consistent\" (∫ rho c φ_i φ_j: the same order of accuracy, but a sudden "
        "heating first cools the nodes behind the face, by 6.4 K on 1 cm cells in "
        "inputs/contact-box-close-convection.xml; doc/heat.md)",
        choice_validator({"Lumped", "Consistent"}));
  p.set("Gap Conductance", 1.0e4,
        "h, the heat-transfer coefficient between the two sides of the split gap: flux "
        "h (T_a - T_b) from side a to side b; must be >= 0 [W/(m^2 K)]",
        nonnegative_double_validator());
  p.set("Gap Conductance Model", "Constant",
        "\"Constant\": h = \"Gap Conductance\" whatever the contact state (as Truchas); "
        "\"Contact Dependent\": h = h0 L/(L + g) while the gap is open by g, h0 + h_p p "
        "while pressed together with the normal stress p (h0: \"Gap Conductance\"; needs "
        "Physics Thermo-Elasticity with Mechanics/Contact enabled; doc/contact.md)",
        choice_validator({"Constant", "Contact Dependent"}));
  p.set("Gap Width Scale", 1.0e-5,
        "L of the Contact Dependent model: the opening at which h has fallen to h0/2, must be "
        "> 0 [m]",
        positive_double_validator());
  p.set("Gap Pressure Coefficient", 1.0e-3,
        "h_p of the Contact Dependent model: the rise of h per contact pressure, must be >= 0 "
        "[W/(m^2 K Pa)]",
        nonnegative_double_validator());
  set_named_sublists(p, "Boundary Conditions",
                     "thermal boundary conditions on side sets; faces in none are insulated",
                     boundary_condition_parameters(thermal_conditions()));
  return p;
}

ThermalPhysics::ThermalPhysics(const Teuchos::ParameterList &thermal, const Material &material,
                               const Mesh &mesh, const DofLayout &layout,
                               const InteriorFaceCheck &interior, const std::string &where)
    : initial_temperature_(thermal.get<double>("Initial Temperature")),
      conduction_(material.heat_capacity(), material.conductivity(),
                  thermal.get<std::string>("Capacity") == "Consistent"
                      ? HeatConductionKernel::Capacity::consistent
                      : HeatConductionKernel::Capacity::lumped)
{
  const double h = thermal.get<double>("Gap Conductance");
  if (thermal.get<std::string>("Gap Conductance Model") == "Contact Dependent")
  {
    KILN_CHECK_INPUT(layout.contact && layout.displacement, where + "/\"Gap Conductance Model\"",
                     "is \"Contact Dependent\", which needs the contact state: set Kiln/"
                     "\"Physics\" to \"Thermo-Elasticity\" with Mechanics/Contact/\"Enabled\" "
                     "true, or use \"Constant\"");
    ContactConductanceKernel::Parameters k;
    k.h0 = h;
    k.length = thermal.get<double>("Gap Width Scale");
    k.pressure_coefficient = thermal.get<double>("Gap Pressure Coefficient");
    k.lambda = material.lame_lambda();
    k.shear_modulus = material.shear_modulus();
    k.beta = (3.0 * k.lambda + 2.0 * k.shear_modulus) * material.thermal_expansion();
    k.reference_temperature = material.reference_temperature();
    gap_ = std::make_unique<ContactConductanceKernel>(k);
  }
  else
  {
    for (const char *key : {"Gap Width Scale", "Gap Pressure Coefficient"})
      KILN_CHECK_INPUT(!given_in_input(thermal, key), where + "/\"" + key + "\"",
                       "is given but \"Gap Conductance Model\" is \"Constant\"; remove it "
                       "or set the model to \"Contact Dependent\"");
    gap_ = std::make_unique<GapConductanceKernel>(h);
  }
  KILN_CHECK_INPUT(mesh.gap_side_set != 0 || !given_in_input(thermal, "Gap Conductance"),
                   where + "/\"Gap Conductance\"",
                   "is given but the mesh has no gap (Kiln/Mesh/\"Gap Side Set\" is 0); remove "
                   "it or name the side set to split at");
  if (mesh.gap_faces.empty())
    gap_.reset();
  conditions_ = read_boundary_conditions(
      thermal_conditions(), thermal.sublist("Boundary Conditions"), mesh, interior,
      where + "/Boundary Conditions", "heat crosses it through Kiln/Thermal/\"Gap Conductance\"");
}

double ThermalPhysics::conductivity_scale() const
{
  return conduction_.conductivity().value(initial_temperature_);
}
} // namespace kiln
