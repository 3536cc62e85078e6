// Tests src/physics/materials/material_map.cpp: Kiln/Material for every block, Kiln/Materials
// by name with their "Blocks", the messages for a block without material, a block in two
// materials, an unknown block, both lists given, and uniform_material (the first material,
// for the scales: the heat equation takes several materials and rho(T), c(T), k(T), the
// mechanics E(T), nu(T), alpha(T) and rho(T) g).
// KILN_TEST_NP: 1
#include "physics/materials/material_map.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "support/parameter_lists.hpp"

#include <Teuchos_Tuple.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

using testing::HasSubstr;

namespace
{
const std::vector<int> blocks{1, 2};

/// The part of Kiln's valid list that MaterialMap reads.
Teuchos::ParameterList valid_kiln()
{
  Teuchos::ParameterList valid("Kiln");
  valid.sublist("Material").setParameters(kiln::Material::valid_parameters());
  kiln::set_named_sublists(valid, "Materials", "materials by name",
                           kiln::MaterialMap::valid_named_parameters());
  return valid;
}

kiln::MaterialMap make(const Teuchos::ParameterList &kiln_user,
                       const std::vector<int> &block_ids = blocks)
{
  return kiln::MaterialMap(kiln::validated(kiln_user, valid_kiln(), "in.xml", "Kiln"), block_ids,
                           "in.xml");
}

std::string error_of(const Teuchos::ParameterList &kiln_user)
{
  return kiln_test::input_error_message([&] { make(kiln_user).uniform_material(); });
}

/// A Materials entry: density `rho` on `block_ids`.
void add_material(Teuchos::ParameterList &kiln_user, const std::string &name, const double rho,
                  const std::vector<int> &block_ids)
{
  Teuchos::ParameterList &m = kiln_user.sublist("Materials").sublist(name);
  m.set("Density", rho);
  m.set("Blocks", kiln_test::ids(block_ids));
}
} // namespace

TEST(MaterialMap, SingleMaterialListAppliesToEveryBlock)
{
  Teuchos::ParameterList user;
  user.sublist("Material").set("Density", 7900.0);
  const kiln::MaterialMap map = make(user);
  EXPECT_EQ(map.n_materials(), 1);
  EXPECT_EQ(map.name(0), "Material");
  EXPECT_EQ(map.of_block(1).density(), 7900.0);
  EXPECT_EQ(map.of_block(2).density(), 7900.0);
  EXPECT_TRUE(map.all_constant());
  EXPECT_EQ(map.uniform_material().density(), 7900.0);
  // Nothing given: the default material (the spec aluminium) everywhere.
  EXPECT_EQ(make(Teuchos::ParameterList()).of_block(2).density(), 2.7e3);
}

TEST(MaterialMap, MaterialsByNameOnBlocks)
{
  Teuchos::ParameterList user;
  add_material(user, "aluminium", 2700.0, {1});
  add_material(user, "steel", 7900.0, {2});
  const kiln::MaterialMap map = make(user);
  EXPECT_EQ(map.n_materials(), 2);
  EXPECT_EQ(map.name(0), "aluminium");
  EXPECT_EQ(map.name(1), "steel");
  EXPECT_EQ(map.index_of_block(2), 1);
  EXPECT_EQ(map.of_block(1).density(), 2700.0);
  EXPECT_EQ(map.of_block(2).density(), 7900.0);
  // Both physics take them by block; the scales take the first.
  EXPECT_EQ(map.uniform_material().density(), 2700.0);
  EXPECT_EQ(map.material_of_block().at(2), 1);
  // One named material for every block is what Kiln/Material is.
  Teuchos::ParameterList one;
  add_material(one, "steel", 7900.0, {2, 1});
  EXPECT_EQ(make(one).uniform_material().density(), 7900.0);
}

TEST(MaterialMap, BlockWithoutMaterial)
{
  Teuchos::ParameterList user;
  add_material(user, "aluminium", 2700.0, {1});
  EXPECT_EQ(error_of(user), "in.xml: Kiln/Materials: element block 2 has no material; add it "
                            "to the \"Blocks\" of one of the materials (\"aluminium\")");
}

TEST(MaterialMap, BlockInTwoMaterials)
{
  Teuchos::ParameterList user;
  add_material(user, "aluminium", 2700.0, {1, 2});
  add_material(user, "steel", 7900.0, {2});
  EXPECT_EQ(error_of(user),
            "in.xml: Kiln/Materials/steel/\"Blocks\": block 2 is also in "
            "Kiln/Materials/aluminium/\"Blocks\"; every block has exactly one material: remove "
            "it from one of them");
  Teuchos::ParameterList twice;
  add_material(twice, "steel", 7900.0, {1, 2, 1});
  EXPECT_THAT(error_of(twice), HasSubstr("block 1 is also in Kiln/Materials/steel/\"Blocks\""));
}

TEST(MaterialMap, UnknownOrNoBlocks)
{
  Teuchos::ParameterList user;
  add_material(user, "steel", 7900.0, {1, 2, 7});
  EXPECT_EQ(error_of(user), "in.xml: Kiln/Materials/steel/\"Blocks\": block 7 is not in the mesh "
                            "(the mesh's element blocks: 1, 2)");
  Teuchos::ParameterList none;
  none.sublist("Materials").sublist("steel").set("Density", 7900.0);
  EXPECT_THAT(error_of(none), HasSubstr("Kiln/Materials/steel/\"Blocks\": is missing or empty"));
}

TEST(MaterialMap, MaterialAndMaterialsTogether)
{
  Teuchos::ParameterList user;
  user.sublist("Material").set("Density", 7900.0);
  add_material(user, "steel", 7900.0, {1, 2});
  EXPECT_THAT(error_of(user), HasSubstr("in.xml: Kiln/\"Material\": is given together with "
                                        "Kiln/\"Materials\""));
}

TEST(MaterialMap, PropertyErrorsNameTheMaterial)
{
  Teuchos::ParameterList user;
  add_material(user, "steel", -7900.0, {1, 2});
  EXPECT_EQ(error_of(user), "in.xml: Kiln/Materials/steel/\"Density\" = -7900: must be > 0");
}

TEST(MaterialMap, PropertiesOfTemperatureAndTheDensityUnderGravity)
{
  Teuchos::ParameterList k_of_T;
  Teuchos::ParameterList &k = k_of_T.sublist("Material").sublist("Conductivity");
  k.set("Type", "Expression");
  k.set("Expression", "240 - 0.05*(T - 300)");
  const kiln::MaterialMap map = make(k_of_T);
  EXPECT_FALSE(map.all_constant());
  EXPECT_NEAR(map.uniform_material().conductivity().value(400.0), 235.0, 1e-12);

  Teuchos::ParameterList E_of_T;
  Teuchos::ParameterList &E = E_of_T.sublist("Material").sublist("Young's Modulus");
  E.set("Type", "Expression");
  E.set("Expression", "7e10 - 3e7*(T - 300)");
  E_of_T.sublist("Material").set("Poisson's Ratio", 0.33);
  // The mechanics takes E(T) (its general path).
  EXPECT_FALSE(make(E_of_T).uniform_material().elastically_constant());
  EXPECT_TRUE(make(E_of_T).uniform_material().mechanical_model() != nullptr);
  EXPECT_FALSE(make(E_of_T).uniform_material().mechanical_model()->constant_linear());

  Teuchos::ParameterList rho_of_T;
  Teuchos::ParameterList &rho = rho_of_T.sublist("Material").sublist("Density");
  rho.set("Type", "Expression");
  rho.set("Expression", "7900 - 0.3*(T - 300)");
  Teuchos::ParameterList &c = rho_of_T.sublist("Material").sublist("Specific Heat");
  c.set("Type", "Table");
  c.set("Temperatures", Teuchos::Array<double>(Teuchos::tuple(300.0, 500.0)));
  c.set("Values", Teuchos::Array<double>(Teuchos::tuple(450.0, 520.0)));
  // The heat equation takes rho(T) and c(T) (its enthalpy); the mechanics rho(T) g (a
  // GravityKernel: tests/unit/physics/gravity_kernel_test.cpp).
  EXPECT_FALSE(make(rho_of_T).uniform_material().enthalpy().is_linear());
  EXPECT_FALSE(make(rho_of_T).uniform_material().density_function().is_constant());
}

TEST(MaterialMap, ModelSublistChoosesTheMechanicalModel)
{
  // Without Model: the material's constants, the fast path's LinearElasticModel.
  Teuchos::ParameterList plain;
  plain.sublist("Material").set("Lame Lambda", 2e9);
  plain.sublist("Material").set("Shear Modulus", 1e9);
  const auto elastic = make(plain).uniform_material().mechanical_model();
  EXPECT_TRUE(elastic->constant_linear());
  EXPECT_EQ(elastic->n_state(), 0);

  // A Power Law model takes the material's elastic constants where it does not give them.
  Teuchos::ParameterList power = plain;
  Teuchos::ParameterList &model = power.sublist("Material").sublist("Model");
  model.set("Type", "Power Law");
  model.set("Power Law A", 1e-12);
  model.set("Power Law n", 0.5);
  const auto viscoplastic = make(power).uniform_material().mechanical_model();
  EXPECT_FALSE(viscoplastic->constant_linear());
  EXPECT_EQ(viscoplastic->n_state(), 8);
  // A uniaxial strain 1e-3 gives the material's stress (lambda + 2G) 1e-3 = 4e6 Pa.
  kiln::PointInput in;
  in.strain[0] = 1e-3;
  in.temperature = in.temperature_old = 298.0;
  std::vector<double> old_state(8), new_state(8);
  viscoplastic->initial_state(old_state.data());
  kiln::PointResponse out;
  viscoplastic->evaluate(in, old_state.data(), new_state.data(), out);
  EXPECT_NEAR(out.stress[0], 4e6, 1e-6);
  EXPECT_NEAR(out.stress[1], 2e6, 1e-6);

  // With E(T), a model must give its own constants.
  Teuchos::ParameterList E_of_T = power;
  Teuchos::ParameterList &material = E_of_T.sublist("Material");
  material.remove("Lame Lambda");
  material.remove("Shear Modulus");
  material.sublist("Young's Modulus").set("Type", "Expression");
  material.sublist("Young's Modulus").set("Expression", "7e10 - 3e7*(T - 300)");
  material.set("Poisson's Ratio", 0.33);
  EXPECT_EQ(error_of(E_of_T),
            "in.xml: Kiln/Material/Model/\"Lame Lambda\": is not given, so it would be the "
            "material's, but the material's elastic constants or expansion depend on T, which the "
            "\"Power Law\" model does not take; give it in Model, or give the material's elastic "
            "constants and expansion as numbers");
}
