#include "physics/mechanics/mechanical_physics.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "contact/interface_parameters.hpp"
#include "physics/heat/mortar_gap_heat.hpp"
#include "physics/mechanics/mechanical_conditions.hpp"

#include <Teuchos_Array.hpp>

#include <algorithm>

namespace kiln
{
namespace internal
{
/// The body force rho g + f [N/m^3] of the "Mechanics" block.
Point body_force(const Teuchos::ParameterList &mechanics, const double density,
                 const std::string &where)
{
  Point b{};
  for (const char *name : {"Body Force", "Gravity"})
  {
    const auto &v = mechanics.get<Teuchos::Array<double>>(name);
    KILN_CHECK_INPUT(v.size() == 3, where + "/\"" + name + "\"",
                     "must have 3 entries (x, y, z), has " << v.size());
  }
  const auto &f = mechanics.get<Teuchos::Array<double>>("Body Force");
  const auto &g = mechanics.get<Teuchos::Array<double>>("Gravity");
  for (int d = 0; d < 3; ++d)
    b[d] = f[d] + density * g[d];
  return b;
}
} // namespace internal

Teuchos::ParameterList MechanicalPhysics::valid_parameters()
{
  Teuchos::ParameterList p("Mechanics");
  p.set("Body Force", Teuchos::Array<double>(3, 0.0),
        "a force per volume f = (fx, fy, fz), added to rho g [N/m^3]");
  p.set("Gravity", Teuchos::Array<double>(3, 0.0),
        "the acceleration of gravity g = (gx, gy, gz); the body force is rho g + f [m/s^2]");
  set_named_sublists(p, "Boundary Conditions",
                     "mechanical boundary conditions on side sets; faces in none are free of "
                     "traction",
                     boundary_condition_parameters(mechanical_conditions()));
  p.set("Free Motions", "Error",
        "what to do when the displacement conditions (and, with contact, the gap's normal) "
        "leave a body free to move as a rigid body (doc/mechanics.md, \"Free motions\"): "
        "\"Error\": refuse the input at set-up, naming the body and its free translations "
        "and rotations; \"Minimum Norm\": solve, and give the displacement with no "
        "component in the free motions (sum over the nodes of u . r = 0 for each free motion "
        "r); a load with a net force or moment along a free motion is then an error of the "
        "run [-]",
        choice_validator({"Error", "Minimum Norm"}));
  // A pair's "Heat Transfer" (the heat terms live here, above contact).
  Teuchos::ParameterList contact = interface_parameters();
  Teuchos::ParameterList pair_heat;
  pair_heat.set("Heat Transfer", MortarGapHeat::valid_parameters(),
                "the heat across the pair's gap (doc/heat.md, \"Heat across the gap of a mortar "
                "pairing\"): every term 0 by default, no heat crosses; needs Kiln/Thermal");
  set_named_sublists(contact, "Pairs", "", pair_heat);
  p.set("Contact", contact,
        "the interface across the gap (Kiln/Mesh/\"Gap Side Set\"): frictionless contact, "
        "sliding or bonded; doc/contact.md");
  return p;
}

namespace
{
/// The materials of the kernels: each of `materials`, or `material` alone.
std::vector<const Material *> materials_of(const Material &material, const MaterialMap *materials)
{
  if (materials == nullptr)
    return {&material};
  std::vector<const Material *> result;
  for (int i = 0; i < materials->n_materials(); ++i)
    result.push_back(&materials->material(i));
  return result;
}

/// Whether `m`'s weight is the GravityKernel's (its density depends on T) rather than a
/// constant body force of its elasticity kernel.
bool weighed_apart(const Material &m)
{
  return !m.density_function().is_constant();
}

/// One kernel per material of `materials`, or `material`'s alone. The body force ρ g + f
/// takes each material's ρ, if it is a number; a ρ(T) is the GravityKernel's (f alone here).
std::vector<ElasticityKernel> elasticity_kernels(const Teuchos::ParameterList &mechanics,
                                                 const Material &material,
                                                 const MaterialMap *materials,
                                                 const std::string &where)
{
  const auto density = [](const Material &m)
  { return weighed_apart(m) ? 0.0 : m.density(m.reference_temperature()); };
  std::vector<ElasticityKernel> kernels;
  if (materials == nullptr)
  {
    kernels.emplace_back(material.lame_lambda(), material.shear_modulus(),
                         material.thermal_expansion(), material.reference_temperature(),
                         internal::body_force(mechanics, density(material), where));
    return kernels;
  }
  for (const Material *m : materials_of(material, materials))
    kernels.emplace_back(m->mechanical_model(),
                         internal::body_force(mechanics, density(*m), where));
  return kernels;
}

/// Block id -> material index of `materials` (empty without).
std::map<int, int> kernel_of_block(const Mesh &mesh, const MaterialMap *materials)
{
  std::map<int, int> result;
  if (materials != nullptr)
    for (const int block : mesh.block_ids())
      result[block] = materials->index_of_block(block);
  return result;
}

/// ρ(T) g of the materials whose density depends on T; null if none does or g = 0.
std::unique_ptr<GravityKernel> gravity_kernel(const Teuchos::ParameterList &mechanics,
                                              const Material &material, const Mesh &mesh,
                                              const MaterialMap *materials)
{
  const auto &g = mechanics.get<Teuchos::Array<double>>("Gravity");
  const Point gravity{g[0], g[1], g[2]};
  std::vector<TemperatureFunction> densities;
  std::vector<char> weighed;
  for (const Material *m : materials_of(material, materials))
  {
    densities.push_back(m->density_function());
    weighed.push_back(weighed_apart(*m));
  }
  if (gravity == Point{} || std::none_of(weighed.begin(), weighed.end(), [](char w) { return w; }))
    return nullptr;
  return std::make_unique<GravityKernel>(mesh, std::move(densities), std::move(weighed),
                                         kernel_of_block(mesh, materials), gravity);
}
} // namespace

std::vector<const CellKernel *> MechanicalPhysics::cell_kernels() const
{
  std::vector<const CellKernel *> kernels{&elasticity_};
  if (gravity_)
    kernels.push_back(gravity_.get());
  return kernels;
}

MechanicalPhysics::MechanicalPhysics(const Teuchos::ParameterList &mechanics,
                                     const Material &material, const Mesh &mesh,
                                     const InteriorFaceCheck &interior, const std::string &where,
                                     const MaterialMap *materials)
    : elasticity_(mesh, elasticity_kernels(mechanics, material, materials, where),
                  kernel_of_block(mesh, materials)),
      gravity_(gravity_kernel(mechanics, material, mesh, materials))
{
  conditions_ =
      read_boundary_conditions(mechanical_conditions(), mechanics.sublist("Boundary Conditions"),
                               mesh, interior, where + "/Boundary Conditions",
                               "its two sides touch through frictionless contact "
                               "(Mechanics/Contact), not a boundary condition");
  KILN_CHECK_INPUT(!mesh.gap_side_sets.empty() || !given_in_input(mechanics, "Contact") ||
                       mechanics.sublist("Contact").sublist("Pairs").numParams() > 0,
                   where + "/Contact",
                   "is given but the mesh has no gap (Kiln/Mesh/\"Gap Side Set\" is 0); remove "
                   "it or name the side set to split at");
  check_interface_parameters(mechanics.sublist("Contact"), mesh.gap_side_sets, where + "/Contact");
}
} // namespace kiln
