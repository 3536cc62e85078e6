// Tests src/physics/materials/constitutive_models.cpp: the registry of models by name, the
// joined parameter list, the creation of each model and the input errors of a model block
// (unknown Type, a parameter of another Type, a misspelled name).
// KILN_TEST_NP: 1
#include "physics/materials/constitutive_models.hpp"

#include "base/errors.hpp"
#include "support/parameter_lists.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using testing::ElementsAre;
using testing::HasSubstr;

namespace
{
std::string error_of(const Teuchos::ParameterList &p)
{
  return kiln_test::input_error_message(
      [&] { kiln::create_constitutive_model(p, "test.xml", "Kiln/Materials/steel/Model"); });
}

TEST(ConstitutiveModels, RegistersTheModelsByName)
{
  EXPECT_THAT(kiln::constitutive_models().names(),
              ElementsAre("Linear Elastic", "Power Law", "MTS"));
  const Teuchos::ParameterList p = kiln::constitutive_model_parameters();
  for (const char *name : {"Type", "Lame Lambda", "Shear Modulus", "Thermal Expansion",
                           "Reference Temperature", "Power Law A", "MTS b", "Local Tolerance"})
    EXPECT_TRUE(p.isParameter(name)) << name;
  for (auto it = p.begin(); it != p.end(); ++it)
    EXPECT_FALSE(p.entry(it).docString().empty()) << p.name(it);
}

TEST(ConstitutiveModels, CreatesEachModel)
{
  Teuchos::ParameterList elastic;
  const auto linear = kiln::create_constitutive_model(elastic, "test.xml", "Kiln/Model");
  EXPECT_TRUE(linear->constant_linear());
  EXPECT_EQ(linear->n_state(), 0);

  Teuchos::ParameterList mts;
  mts.set("Type", "MTS");
  const auto m = kiln::create_constitutive_model(mts, "test.xml", "Kiln/Model");
  EXPECT_FALSE(m->constant_linear());
  EXPECT_EQ(m->n_state(), 8);
  EXPECT_EQ(m->state_names().size(), 8u);
  EXPECT_EQ(m->state_names()[6], "equivalent_plastic_strain");
  std::vector<double> state(8, 1.0);
  m->initial_state(state.data());
  for (const double s : state)
    EXPECT_EQ(s, 0.0);
}

TEST(ConstitutiveModels, BadModelBlocksAreInputErrors)
{
  Teuchos::ParameterList unknown;
  unknown.set("Type", "Plastic");
  EXPECT_THAT(error_of(unknown), HasSubstr("Kiln/Materials/steel/Model/\"Type\""));
  EXPECT_THAT(error_of(unknown), HasSubstr("Power Law"));

  Teuchos::ParameterList other;
  other.set("Type", "Power Law");
  other.set("Power Law A", 1e-20);
  other.set("Power Law n", 3.0);
  other.set("MTS b", 3e-10);
  EXPECT_THAT(error_of(other),
              HasSubstr("test.xml: Kiln/Materials/steel/Model/\"MTS b\": is not a parameter of "
                        "the \"Power Law\" model (\"Type\")"));

  Teuchos::ParameterList misspelled;
  misspelled.set("Type", "Power Law");
  misspelled.set("Power Law  A", 1e-20);
  EXPECT_THAT(error_of(misspelled), HasSubstr("Power Law A"));
}
} // namespace
