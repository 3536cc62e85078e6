// The deck fragments of tests/support/parameter_lists.hpp give the lists that the same deck
// written as XML gives: the same names, values and types (an "Array(int)" an Array<int>, a
// "double" a double, ...), so a test that builds its deck from them runs what the XML would.
#include "support/parameter_lists.hpp"

#include <Teuchos_XMLParameterListHelpers.hpp>
#include <gtest/gtest.h>

#include <sstream>

namespace
{
/// Whether `built` has the values of the deck `xml` (in any order), both printed if not.
::testing::AssertionResult same_deck(const Teuchos::ParameterList &built, const std::string &xml)
{
  const Teuchos::RCP<Teuchos::ParameterList> parsed = Teuchos::getParametersFromXmlString(xml);
  if (Teuchos::haveSameValuesSorted(built, *parsed, true))
    return ::testing::AssertionSuccess();
  std::ostringstream message;
  message << "built:\n";
  built.print(message, Teuchos::ParameterList::PrintOptions().showTypes(true));
  message << "from XML:\n";
  parsed->print(message, Teuchos::ParameterList::PrintOptions().showTypes(true));
  return ::testing::AssertionFailure() << message.str();
}
} // namespace

TEST(DeckFragments, ExodusMeshConditionsAndPair)
{
  using namespace kiln_test;
  Teuchos::ParameterList deck = steady_deck("Thermo-Elasticity", exodus_mesh("two.exo"));
  deck.set("Material", young(2e11, 0.3));
  thermal_conditions(deck).set("bottom", temperature({3}, 400.0));
  mechanical_conditions(deck).set("bottom", displacement({3}, {"z"}));
  mechanical_conditions(deck).set("top", displacement({4, 5}, {"x", "z"}, -2e-5));
  contact_pairs(deck).set("cut", contact_pair(1, 2));
  EXPECT_TRUE(same_deck(deck, R"xml(<ParameterList name="Kiln">
  <Parameter name="Physics" type="string" value="Thermo-Elasticity"/>
  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="Exodus"/>
    <Parameter name="Gap Side Set" type="int" value="0"/>
    <ParameterList name="Exodus"><Parameter name="File" type="string" value="two.exo"/></ParameterList>
  </ParameterList>
  <ParameterList name="Material">
    <Parameter name="Young's Modulus" type="double" value="2e11"/>
    <Parameter name="Poisson's Ratio" type="double" value="0.3"/>
  </ParameterList>
  <ParameterList name="Thermal"><ParameterList name="Boundary Conditions">
    <ParameterList name="bottom">
      <Parameter name="Type" type="string" value="Temperature"/>
      <Parameter name="Side Sets" type="Array(int)" value="{3}"/>
      <ParameterList name="Temperature">
        <Parameter name="Type" type="string" value="Constant"/>
        <Parameter name="Value" type="double" value="400"/>
      </ParameterList>
    </ParameterList>
  </ParameterList></ParameterList>
  <ParameterList name="Mechanics">
    <ParameterList name="Boundary Conditions">
      <ParameterList name="bottom">
        <Parameter name="Type" type="string" value="Displacement"/>
        <Parameter name="Side Sets" type="Array(int)" value="{3}"/>
        <Parameter name="Components" type="Array(string)" value="{z}"/>
      </ParameterList>
      <ParameterList name="top">
        <Parameter name="Type" type="string" value="Displacement"/>
        <Parameter name="Side Sets" type="Array(int)" value="{4, 5}"/>
        <Parameter name="Components" type="Array(string)" value="{x, z}"/>
        <ParameterList name="Displacement">
          <Parameter name="Type" type="string" value="Constant"/>
          <Parameter name="Value" type="double" value="-2e-5"/>
        </ParameterList>
      </ParameterList>
    </ParameterList>
    <ParameterList name="Contact"><ParameterList name="Pairs"><ParameterList name="cut">
      <Parameter name="Primary Side Set" type="int" value="1"/>
      <Parameter name="Secondary Side Set" type="int" value="2"/>
    </ParameterList></ParameterList></ParameterList>
  </ParameterList>
  <ParameterList name="Time Stepping"><Parameter name="Method" type="string" value="Steady"/></ParameterList>
</ParameterList>)xml"));
}

TEST(DeckFragments, BoxMeshLameRollersTableAndSolver)
{
  using namespace kiln_test;
  Teuchos::ParameterList deck = steady_deck("", box_mesh({0.04, 0.02, 0.01}, {6, 3, 2}, 10));
  deck.set("Material", lame(1.2e11, 8e10));
  Teuchos::ParameterList table;
  table.set("Type", "Table").set("Times", values({0, 1000})).set("Values", values({300, 1300}));
  thermal_conditions(deck).set("heated", temperature({3}, table));
  mechanical_conditions(deck).set("symmetry", normal_displacement({5, 6, 7}));
  deck.set("Solver", newton_tolerances(1e-11, 1e-14));
  EXPECT_TRUE(same_deck(deck, R"xml(<ParameterList name="Kiln">
  <ParameterList name="Mesh">
    <Parameter name="Gap Side Set" type="int" value="10"/>
    <ParameterList name="Box">
      <Parameter name="Size" type="Array(double)" value="{0.04, 0.02, 0.01}"/>
      <Parameter name="Cells" type="Array(int)" value="{6, 3, 2}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Material">
    <Parameter name="Lame Lambda" type="double" value="1.2e11"/>
    <Parameter name="Shear Modulus" type="double" value="8e10"/>
  </ParameterList>
  <ParameterList name="Thermal"><ParameterList name="Boundary Conditions">
    <ParameterList name="heated">
      <Parameter name="Type" type="string" value="Temperature"/>
      <Parameter name="Side Sets" type="Array(int)" value="{3}"/>
      <ParameterList name="Temperature">
        <Parameter name="Type" type="string" value="Table"/>
        <Parameter name="Times" type="Array(double)" value="{0, 1000}"/>
        <Parameter name="Values" type="Array(double)" value="{300, 1300}"/>
      </ParameterList>
    </ParameterList>
  </ParameterList></ParameterList>
  <ParameterList name="Mechanics"><ParameterList name="Boundary Conditions">
    <ParameterList name="symmetry">
      <Parameter name="Type" type="string" value="Normal Displacement"/>
      <Parameter name="Side Sets" type="Array(int)" value="{5, 6, 7}"/>
    </ParameterList>
  </ParameterList></ParameterList>
  <ParameterList name="Time Stepping"><Parameter name="Method" type="string" value="Steady"/></ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Absolute Tolerance" type="double" value="1e-11"/>
    <Parameter name="Relative Tolerance" type="double" value="1e-14"/>
  </ParameterList>
</ParameterList>)xml"));
}

// The check can fail: a fragment with another type (an int where the XML has a double) or value
// is told apart.
TEST(DeckFragments, AnotherTypeOrValueDiffers)
{
  Teuchos::ParameterList deck = kiln_test::newton_tolerances(1e-11, 1e-14);
  const std::string xml = R"xml(<ParameterList name="Solver">
    <Parameter name="Absolute Tolerance" type="double" value="1e-11"/>
    <Parameter name="Relative Tolerance" type="double" value="1e-14"/>
  </ParameterList>)xml";
  EXPECT_TRUE(same_deck(deck, xml));
  deck.set("Relative Tolerance", 1e-13);
  EXPECT_FALSE(same_deck(deck, xml));
  deck.set("Relative Tolerance", 0);
  EXPECT_FALSE(same_deck(deck, xml));
}
