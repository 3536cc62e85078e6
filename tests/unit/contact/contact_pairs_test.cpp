// Tests src/contact/contact_pairs.cpp: the input Mechanics/Contact/Pairs (issue 30): the pairs
// read with their paths, defaults and values; a misspelled key, a missing side set and a
// Search Update Fraction outside (0, 1] are input errors naming the parameter; a pair's Heat
// Transfer, as MechanicalPhysics declares it.
// KILN_TEST_NP: 1
#include "contact/contact_pairs.hpp"

#include "base/parameters.hpp"
#include "contact/interface_parameters.hpp"
#include "physics/mechanics/mechanical_physics.hpp"
#include "support/parameter_lists.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace
{
using testing::HasSubstr;

const std::string path = "Kiln/Mechanics/Contact";

/// The Contact sublist with the pair "Pellet" (side sets 3 and 4) and "Flange" (5 and 6, a
/// search distance and a tolerance), validated.
Teuchos::ParameterList contact(const std::string &misspelled = "")
{
  Teuchos::ParameterList user("Contact");
  Teuchos::ParameterList &pellet = user.sublist("Pairs").sublist("Pellet");
  pellet.set("Primary Side Set", 3);
  pellet.set("Secondary Side Set", 4);
  Teuchos::ParameterList &flange = user.sublist("Pairs").sublist("Flange");
  flange.set("Primary Side Set", 5);
  flange.set("Secondary Side Set", 6);
  flange.set("Search Distance", 0.002);
  flange.set("Penetration Tolerance", 1e-5);
  flange.set("Search Update Fraction", 0.5);
  flange.set("Sliding Distance", 0.03);
  if (!misspelled.empty())
    flange.set(misspelled, 1);
  return kiln::validated(user, kiln::interface_parameters(), "in.xml", path);
}
} // namespace

TEST(ContactPairs, ReadInOrderWithDefaults)
{
  const std::vector<kiln::ContactPairInput> pairs =
      kiln::contact_pairs(contact(), "in.xml: " + path);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].name, "Pellet");
  EXPECT_EQ(pairs[0].where, "in.xml: Kiln/Mechanics/Contact/Pairs/\"Pellet\"");
  EXPECT_EQ(pairs[0].primary_side_set, 3);
  EXPECT_EQ(pairs[0].secondary_side_set, 4);
  EXPECT_EQ(pairs[0].options.search_distance, 0.0);
  EXPECT_EQ(pairs[0].options.penetration_tolerance, 1e-9);
  EXPECT_EQ(pairs[0].options.search_update_fraction, 0.25);
  EXPECT_EQ(pairs[0].options.sliding_distance, 0.0);
  EXPECT_EQ(pairs[1].name, "Flange");
  EXPECT_EQ(pairs[1].primary_side_set, 5);
  EXPECT_EQ(pairs[1].secondary_side_set, 6);
  EXPECT_EQ(pairs[1].options.search_distance, 0.002);
  EXPECT_EQ(pairs[1].options.penetration_tolerance, 1e-5);
  EXPECT_EQ(pairs[1].options.search_update_fraction, 0.5);
  EXPECT_EQ(pairs[1].options.sliding_distance, 0.03);
}

TEST(ContactPairs, NegativeSlidingDistance)
{
  Teuchos::ParameterList user("Contact");
  Teuchos::ParameterList &pellet = user.sublist("Pairs").sublist("Pellet");
  pellet.set("Primary Side Set", 3);
  pellet.set("Secondary Side Set", 4);
  pellet.set("Sliding Distance", -0.01);
  const std::string message = kiln_test::input_error_message(
      [&] { (void)kiln::validated(user, kiln::interface_parameters(), "in.xml", path); });
  EXPECT_THAT(message, HasSubstr("Sliding Distance"));
}

TEST(ContactPairs, NoPairs)
{
  const Teuchos::ParameterList none = kiln::validated(Teuchos::ParameterList("Contact"),
                                                      kiln::interface_parameters(), "in.xml", path);
  EXPECT_TRUE(kiln::contact_pairs(none, "in.xml: " + path).empty());
}

TEST(ContactPairs, MisspelledKey)
{
  const std::string message = kiln_test::input_error_message([] { contact("Secondary Sideset"); });
  EXPECT_THAT(message, HasSubstr("in.xml: Kiln/Mechanics/Contact/Pairs/Flange/\"Secondary "
                                 "Sideset\": unknown parameter. Did you mean \"Secondary Side "
                                 "Set\"?"));
}

TEST(ContactPairs, MissingSideSet)
{
  Teuchos::ParameterList user("Contact");
  user.sublist("Pairs").sublist("Pellet").set("Primary Side Set", 3);
  const Teuchos::ParameterList list =
      kiln::validated(user, kiln::interface_parameters(), "in.xml", path);
  const std::string message =
      kiln_test::input_error_message([&] { kiln::contact_pairs(list, "in.xml: " + path); });
  EXPECT_THAT(message, HasSubstr("in.xml: Kiln/Mechanics/Contact/Pairs/\"Pellet\"/\"Secondary "
                                 "Side Set\": is missing"));
}

TEST(ContactPairs, NegativeSearchDistance)
{
  Teuchos::ParameterList user("Contact");
  Teuchos::ParameterList &pellet = user.sublist("Pairs").sublist("Pellet");
  pellet.set("Primary Side Set", 3);
  pellet.set("Secondary Side Set", 4);
  pellet.set("Search Distance", -1.0);
  const std::string message = kiln_test::input_error_message(
      [&] { kiln::validated(user, kiln::interface_parameters(), "in.xml", path); });
  EXPECT_THAT(message, HasSubstr("Pairs/Pellet/\"Search Distance\""));
}

TEST(ContactPairs, SearchUpdateFractionOutOfRange)
{
  for (const double fraction : {0.0, 1.5, -0.1})
  {
    Teuchos::ParameterList user("Contact");
    Teuchos::ParameterList &pellet = user.sublist("Pairs").sublist("Pellet");
    pellet.set("Primary Side Set", 3);
    pellet.set("Secondary Side Set", 4);
    pellet.set("Search Update Fraction", fraction);
    const std::string message = kiln_test::input_error_message(
        [&]
        {
          const Teuchos::ParameterList list =
              kiln::validated(user, kiln::interface_parameters(), "in.xml", path);
          kiln::contact_pairs(list, "in.xml: " + path);
        });
    EXPECT_THAT(message, HasSubstr("Pellet")) << fraction;
    EXPECT_THAT(message, HasSubstr("/\"Search Update Fraction\"")) << fraction;
  }
}

// A pair's "Heat Transfer" (declared by MechanicalPhysics: the heat terms live in physics) is
// read into the pair's input, validated with its defaults; a pair without it gets them too.
TEST(ContactPairs, HeatTransferAsMechanicsDeclaresIt)
{
  Teuchos::ParameterList user("Contact");
  Teuchos::ParameterList &pellet = user.sublist("Pairs").sublist("Pellet");
  pellet.set("Primary Side Set", 3);
  pellet.set("Secondary Side Set", 4);
  pellet.sublist("Heat Transfer").set("Conductance", 1.0e4);
  const Teuchos::ParameterList contact = kiln::validated(
      user, kiln::MechanicalPhysics::valid_parameters().sublist("Contact"), "in.xml", path);
  const std::vector<kiln::ContactPairInput> pairs = kiln::contact_pairs(contact, "in.xml: " + path);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].heat_transfer.get<double>("Conductance"), 1.0e4);
  EXPECT_EQ(pairs[0].heat_transfer.get<double>("Jump Distance"), 0.0);
  // Without the physics' declaration (the contact module's own list) there is none.
  EXPECT_EQ(kiln::contact_pairs(::contact(), "in.xml: " + path)[0].heat_transfer.numParams(), 0);
}
