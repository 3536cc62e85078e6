// Tests base/parameters: validation against a valid list (names with the closest
// suggestion, types, validators, nested paths, defaults) and closest_name.
// KILN_TEST_NP: 1
#include "base/errors.hpp"
#include "base/parameters.hpp"

#include <Teuchos_Array.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

using testing::HasSubstr;

namespace
{
Teuchos::ParameterList valid_list()
{
  Teuchos::ParameterList p("Top");
  p.set("Conductivity", 1.0, "k [W/(m K)]", kiln::positive_double_validator());
  p.set("Steps", 3, "count [-]", kiln::positive_int_validator());
  p.set("Method", "BDF2", "time integrator", kiln::choice_validator({"BDF2", "Backward Euler"}));
  p.sublist("Inner").set("Angle", 0.0, "[degrees]", kiln::double_range_validator(-360, 360));
  p.sublist("Inner").set("Sizes", Teuchos::Array<double>(3, 1.0), "[m]",
                         kiln::positive_double_array_validator(3));
  return p;
}

std::string error_of(const Teuchos::ParameterList &user)
{
  try
  {
    kiln::validated(user, valid_list(), "in.xml", "Top");
  }
  catch (const kiln::InputError &e)
  {
    return e.what();
  }
  return "";
}
} // namespace

TEST(Parameters, DefaultsAreSetAndValuesKept)
{
  Teuchos::ParameterList user;
  user.set("Steps", 7);
  const auto p = kiln::validated(user, valid_list(), "in.xml", "Top");
  EXPECT_EQ(p.get<int>("Steps"), 7);
  EXPECT_EQ(p.get<double>("Conductivity"), 1.0);
  EXPECT_EQ(p.get<std::string>("Method"), "BDF2");
  EXPECT_EQ(p.sublist("Inner").get<double>("Angle"), 0.0);
}

TEST(Parameters, MisspelledNameSuggestsClosest)
{
  Teuchos::ParameterList user;
  user.set("Conductivty", 2.0);
  const std::string e = error_of(user);
  EXPECT_THAT(e, HasSubstr("in.xml: Top/\"Conductivty\": unknown parameter."));
  EXPECT_THAT(e, HasSubstr("Did you mean \"Conductivity\"?"));
  EXPECT_THAT(e, HasSubstr("Valid names in Top: \"Conductivity\", \"Steps\""));
}

TEST(Parameters, FarNameGetsNoSuggestion)
{
  Teuchos::ParameterList user;
  user.set("Xyzzy", 2.0);
  const std::string e = error_of(user);
  EXPECT_THAT(e, HasSubstr("unknown parameter"));
  EXPECT_THAT(e, testing::Not(HasSubstr("Did you mean")));
}

TEST(Parameters, NestedPathAndValidator)
{
  Teuchos::ParameterList user;
  user.sublist("Inner").set("Angle", 400.0);
  EXPECT_THAT(error_of(user),
              HasSubstr("in.xml: Top/Inner/\"Angle\" = 400: must be in [-360, 360]"));
  Teuchos::ParameterList sizes;
  sizes.sublist("Inner").set("Sizes", Teuchos::Array<double>(2, 1.0));
  EXPECT_THAT(error_of(sizes), HasSubstr("must have exactly 3 entries, each > 0"));
}

TEST(Parameters, WrongTypeAndNonPositive)
{
  Teuchos::ParameterList user;
  user.set("Conductivity", 2);
  EXPECT_THAT(error_of(user),
              HasSubstr("Top/\"Conductivity\": expected type \"double\", got type \"int\""));
  Teuchos::ParameterList negative;
  negative.set("Conductivity", -1.0);
  EXPECT_THAT(error_of(negative), HasSubstr("Top/\"Conductivity\" = -1: must be > 0"));
  Teuchos::ParameterList zero_steps;
  zero_steps.set("Steps", 0);
  EXPECT_THAT(error_of(zero_steps), HasSubstr("\"Steps\" = 0: must be > 0"));
}

TEST(Parameters, ChoiceListsOptions)
{
  Teuchos::ParameterList user;
  user.set("Method", "RK4");
  EXPECT_THAT(error_of(user), HasSubstr("must be one of \"BDF2\", \"Backward Euler\""));
}

TEST(Parameters, SublistWhereParameterExpected)
{
  Teuchos::ParameterList user;
  user.sublist("Steps");
  EXPECT_THAT(error_of(user), HasSubstr("Top/\"Steps\": expected a parameter of type int"));
}

TEST(Parameters, ClosestName)
{
  const std::vector<std::string> names{"Cells", "Size", "Phi", "Theta"};
  EXPECT_EQ(kiln::closest_name("cels", names), "Cells");
  EXPECT_EQ(kiln::closest_name("Thetta", names), "Theta");
  EXPECT_EQ(kiln::closest_name("Temperature", names), "");
}

TEST(Parameters, PassThroughSublistIsNotCheckedButGetsDefaults)
{
  Teuchos::ParameterList valid = valid_list();
  Teuchos::ParameterList package_defaults;
  package_defaults.set("Solver Type", "GMRES");
  package_defaults.sublist("Deep").set("Level", 2);
  kiln::set_pass_through_sublist(valid, "Package", "SomePackage", "options of SomePackage",
                                 package_defaults);

  Teuchos::ParameterList user;
  user.sublist("Package").set("Any Option The Package Knows", 3.5);
  const auto p = kiln::validated(user, valid, "in.xml", "Top");
  EXPECT_EQ(p.sublist("Package").get<double>("Any Option The Package Knows"), 3.5);
  EXPECT_EQ(p.sublist("Package").get<std::string>("Solver Type"), "GMRES");
  EXPECT_EQ(p.sublist("Package").sublist("Deep").get<int>("Level"), 2);

  // Only its own content is free: the sublist's name is still checked.
  Teuchos::ParameterList misspelled;
  misspelled.sublist("Pakage");
  try
  {
    kiln::validated(misspelled, valid, "in.xml", "Top");
    FAIL() << "no error for a misspelled sublist";
  }
  catch (const kiln::InputError &e)
  {
    EXPECT_THAT(e.what(), HasSubstr("Did you mean \"Package\"?"));
  }
}

namespace
{
/// A list with one property "Density" that is a number or a sublist (Type, Value > 0, Values).
Teuchos::ParameterList valid_with_property()
{
  Teuchos::ParameterList each;
  each.set("Type", "Constant");
  each.set("Value", 2700.0, "rho [kg/m^3]", kiln::positive_double_validator());
  each.set("Values", Teuchos::Array<double>(2, 2700.0));
  Teuchos::ParameterList valid("Material");
  kiln::set_number_or_sublist(valid, "Density", "rho", each);
  return valid;
}
} // namespace

TEST(Parameters, NumberOrSublistReadsANumberAsTheConstantSublist)
{
  Teuchos::ParameterList user;
  user.set("Density", 7900.0);
  const Teuchos::ParameterList p =
      kiln::validated(user, valid_with_property(), "in.xml", "Kiln/Material");
  ASSERT_TRUE(p.isSublist("Density"));
  EXPECT_EQ(p.sublist("Density").get<std::string>("Type"), "Constant");
  EXPECT_EQ(p.sublist("Density").get<double>("Value"), 7900.0);
  EXPECT_TRUE(kiln::given_in_input(p, "Density"));
  EXPECT_TRUE(kiln::given_in_input(p.sublist("Density"), "Value"));
  EXPECT_FALSE(kiln::given_in_input(p.sublist("Density"), "Type"));

  // Not given: the sublist of defaults, not given.
  const Teuchos::ParameterList d =
      kiln::validated(Teuchos::ParameterList(), valid_with_property(), "in.xml", "Kiln/Material");
  EXPECT_EQ(d.sublist("Density").get<double>("Value"), 2700.0);
  EXPECT_FALSE(kiln::given_in_input(d, "Density"));

  // The long form is kept as given.
  Teuchos::ParameterList long_form;
  long_form.sublist("Density").set("Type", "Table");
  const Teuchos::ParameterList l =
      kiln::validated(long_form, valid_with_property(), "in.xml", "Kiln/Material");
  EXPECT_EQ(l.sublist("Density").get<std::string>("Type"), "Table");
  EXPECT_EQ(l.sublist("Density").get<double>("Value"), 2700.0);
}

TEST(Parameters, NumberOrSublistChecksTheNumberAsItsValue)
{
  const auto error_of = [](const Teuchos::ParameterList &user)
  {
    try
    {
      kiln::validated(user, valid_with_property(), "in.xml", "Kiln/Material");
    }
    catch (const kiln::InputError &e)
    {
      return std::string(e.what());
    }
    return std::string();
  };
  Teuchos::ParameterList negative;
  negative.set("Density", -1.0);
  EXPECT_EQ(error_of(negative), "in.xml: Kiln/Material/\"Density\" = -1: must be > 0");
  Teuchos::ParameterList text;
  text.set("Density", std::string("heavy"));
  EXPECT_THAT(error_of(text), HasSubstr("Kiln/Material/\"Density\": expected type \"double\", "
                                        "got type \"string\""));
  Teuchos::ParameterList misspelled;
  misspelled.sublist("Density").set("Valeu", 1.0);
  EXPECT_THAT(error_of(misspelled), HasSubstr("Kiln/Material/Density/\"Valeu\": unknown parameter. "
                                              "Did you mean \"Value\"?"));
}
