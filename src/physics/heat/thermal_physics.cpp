#include "physics/heat/thermal_physics.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "physics/heat/contact_conductance_kernel.hpp"
#include "physics/heat/gap_conductance_kernel.hpp"
#include "physics/heat/thermal_conditions.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace kiln
{
Teuchos::ParameterList ThermalPhysics::valid_parameters()
{
  Teuchos::ParameterList p("Thermal");
  p.set("Initial Temperature", 298.0, "the uniform initial temperature, must be > 0 [K]",
        positive_double_validator());
  p.set("Initial Temperature Expression", "",
        "the initial temperature as a formula in x, y, z [m] (the reference coordinates, after "
        "any Coordinate Scale), e.g. \"300 + 50*x\", instead of Initial Temperature; must be "
        "finite and > 0 at every node; \"\": none (muparser's syntax, as Type \"Expression\" "
        "of a boundary value) [K]");
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

namespace
{
/// Initial Temperature Expression, checked at every node; none if not given.
std::shared_ptr<const Expression> read_initial_field(const Teuchos::ParameterList &thermal,
                                                     const Mesh &mesh, const std::string &where)
{
  const std::string text = thermal.get<std::string>("Initial Temperature Expression");
  if (!given_in_input(thermal, "Initial Temperature Expression"))
    return nullptr;
  const std::string path = where + "/\"Initial Temperature Expression\"";
  KILN_CHECK_INPUT(!given_in_input(thermal, "Initial Temperature"), path,
                   "and \"Initial Temperature\" are both given; remove one");
  auto field = std::make_shared<const Expression>(text, path);
  KILN_CHECK_INPUT(!field->depends_on_time(), path,
                   "= \"" << text
                          << "\" names t; the initial temperature is at t = 0: use "
                             "x, y, z only");
  for (int n = 0; n < mesh.n_nodes(); ++n)
  {
    const Point &x = mesh.coordinates[n];
    const double T = (*field)(x[0], x[1], x[2], 0.0);
    KILN_CHECK_INPUT(std::isfinite(T) && T > 0.0, path,
                     "= \"" << text << "\" is " << T << " K at node " << n + 1 << " (" << x[0]
                            << ", " << x[1] << ", " << x[2]
                            << ") m; it must be finite and > 0 at every node");
  }
  return field;
}
} // namespace

namespace
{
/// One conduction kernel per material of `materials`, or `material`'s alone: rho c and k of
/// each; a constant rho c as a number (the kernel's constant path).
BlockHeatConductionKernel conduction_kernels(const Teuchos::ParameterList &thermal,
                                             const Material &material, const Mesh &mesh,
                                             const MaterialMap *materials)
{
  const auto capacity = thermal.get<std::string>("Capacity") == "Consistent"
                            ? HeatConductionKernel::Capacity::consistent
                            : HeatConductionKernel::Capacity::lumped;
  std::vector<HeatConductionKernel> kernels;
  std::map<int, int> kernel_of_block;
  const int n = materials != nullptr ? materials->n_materials() : 1;
  for (int i = 0; i < n; ++i)
  {
    const Material &m = materials != nullptr ? materials->material(i) : material;
    kernels.emplace_back(m.enthalpy(), m.conductivity(), capacity);
  }
  if (materials != nullptr)
    for (const int block : mesh.block_ids())
      kernel_of_block[block] = materials->index_of_block(block);
  return BlockHeatConductionKernel(mesh, std::move(kernels), std::move(kernel_of_block));
}
} // namespace

ThermalPhysics::ThermalPhysics(const Teuchos::ParameterList &thermal, const Material &material,
                               const Mesh &mesh, const DofLayout &layout,
                               const InteriorFaceCheck &interior, const std::string &where,
                               const MaterialMap *materials)
    : initial_temperature_(thermal.get<double>("Initial Temperature")),
      initial_field_(read_initial_field(thermal, mesh, where)),
      conduction_(conduction_kernels(thermal, material, mesh, materials))
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
    std::vector<int> cells;
    for (const GapFace &face : mesh.gap_faces)
      cells.insert(cells.end(), {face.cell_a, face.cell_b});
    gap_ = std::make_unique<ContactConductanceKernel>(ContactConductanceKernel::for_materials(
        k, material, mesh, materials, cells, where + "/\"Gap Conductance Model\"",
        "is \"Contact Dependent\"", "use \"Constant\", or an elastic material beside the gap"));
  }
  else
  {
    for (const char *key : {"Gap Width Scale", "Gap Pressure Coefficient"})
      KILN_CHECK_INPUT(!given_in_input(thermal, key), where + "/\"" + key + "\"",
                       "is given but \"Gap Conductance Model\" is \"Constant\"; remove it "
                       "or set the model to \"Contact Dependent\"");
    gap_ = std::make_unique<GapConductanceKernel>(h);
  }
  KILN_CHECK_INPUT(!mesh.gap_side_sets.empty() || !given_in_input(thermal, "Gap Conductance"),
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
  double k = 0.0;
  for (const HeatConductionKernel &kernel : conduction_.kernels())
    k = std::max(k, kernel.conductivity().value(initial_temperature_));
  return k;
}
} // namespace kiln
