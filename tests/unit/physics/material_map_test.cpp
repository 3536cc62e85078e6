// Tests src/physics/materials/material_map.cpp: Kiln/Material for every block, Kiln/Materials
// by name with their "Blocks", the messages for a block without material, a block in two
// materials, an unknown block, both lists given, and the bridge to today's kernels
// (uniform_material: one material, only the conductivity may depend on T).
// KILN_TEST_NP: 1
#include "physics/materials/material_map.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "support/parameter_lists.hpp"

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
  EXPECT_EQ(error_of(user),
            "in.xml: Kiln/Materials: gives 2 materials (\"aluminium\" on block 1, \"steel\" on "
            "block 2); several materials need the kernels to take the material of each cell's "
            "block, which Kiln does not do yet: give one material for every block");
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

TEST(MaterialMap, OnlyTheConductivityMayDependOnTemperatureYet)
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
  EXPECT_EQ(error_of(E_of_T),
            "in.xml: Kiln/Material/\"Young's Modulus\": depends on temperature, but the kernels "
            "take only the conductivity as a function of T yet; give a number (the value at the "
            "temperatures of interest)");
}
