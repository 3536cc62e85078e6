// Tests src/physics/materials/temperature_function.cpp and property_range.cpp: a property of T
// as a number (also written as a plain number in its parent list), a table and a formula;
// derivatives against analytic values and central finite differences; the range checks at the
// table points and at a formula's sample temperatures, and their messages.
// KILN_TEST_NP: 1
#include "physics/materials/temperature_function.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "support/parameter_lists.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using testing::HasSubstr;

namespace
{
/// The parent list of one property "Modulus" (E [Pa], > 0, default 7e10), as Material declares.
Teuchos::ParameterList valid_parent(const kiln::PropertyRange &range)
{
  Teuchos::ParameterList valid;
  kiln::set_number_or_sublist(valid, "Modulus", "E [Pa]",
                              kiln::TemperatureFunction::valid_parameters(7.0e10, "E [Pa]", range));
  return valid;
}

/// The property as the input gives it in `parent` (a number or a sublist named "Modulus").
kiln::TemperatureFunction make(const Teuchos::ParameterList &parent,
                               const kiln::PropertyRange &range = kiln::PropertyRange::positive())
{
  const Teuchos::ParameterList p =
      kiln::validated(parent, valid_parent(range), "in.xml", "Kiln/Materials/steel");
  return kiln::TemperatureFunction(p.sublist("Modulus"), "in.xml: Kiln/Materials/steel/Modulus",
                                   range);
}

std::string error_of(const Teuchos::ParameterList &parent,
                     const kiln::PropertyRange &range = kiln::PropertyRange::positive())
{
  return kiln_test::input_error_message([&] { make(parent, range); });
}

Teuchos::ParameterList table(const std::vector<double> &temperatures,
                             const std::vector<double> &values)
{
  Teuchos::ParameterList parent;
  Teuchos::ParameterList &p = parent.sublist("Modulus");
  p.set("Type", "Table");
  p.set("Temperatures", kiln_test::values(temperatures));
  p.set("Values", kiln_test::values(values));
  return parent;
}

Teuchos::ParameterList expression(const std::string &text,
                                  const std::vector<double> &temperatures = {300.0, 1000.0})
{
  Teuchos::ParameterList parent;
  Teuchos::ParameterList &p = parent.sublist("Modulus");
  p.set("Type", "Expression");
  p.set("Expression", text);
  p.set("Temperatures", kiln_test::values(temperatures));
  return parent;
}

/// Central difference of f at T with step h.
double central_difference(const kiln::TemperatureFunction &f, const double T, const double h)
{
  return (f.value(T + h) - f.value(T - h)) / (2.0 * h);
}
} // namespace

TEST(TemperatureFunction, PlainNumberIsAConstant)
{
  Teuchos::ParameterList parent;
  parent.set("Modulus", 2.0e11);
  const kiln::TemperatureFunction E = make(parent);
  EXPECT_TRUE(E.is_constant());
  EXPECT_EQ(E.value(300.0), 2.0e11);
  EXPECT_EQ(E.value(1500.0), 2.0e11);
  EXPECT_EQ(E.derivative(300.0), 0.0);
  EXPECT_TRUE(E.checked_temperatures().empty());
}

TEST(TemperatureFunction, ConstantSublistAndDefault)
{
  Teuchos::ParameterList parent;
  parent.sublist("Modulus").set("Value", 1.5e11);
  EXPECT_EQ(make(parent).value(500.0), 1.5e11);
  EXPECT_EQ(make(Teuchos::ParameterList()).value(500.0), 7.0e10); // the default
  EXPECT_EQ(kiln::TemperatureFunction::constant(3.0).value(1.0), 3.0);
  EXPECT_EQ(kiln::TemperatureFunction().value(1.0), 1.0);
}

TEST(TemperatureFunction, PlainNumberOutOfRangeNamesTheProperty)
{
  Teuchos::ParameterList parent;
  parent.set("Modulus", -1.0);
  EXPECT_EQ(error_of(parent), "in.xml: Kiln/Materials/steel/\"Modulus\" = -1: must be > 0");
  Teuchos::ParameterList as_int;
  as_int.set("Modulus", 7);
  EXPECT_THAT(error_of(as_int),
              HasSubstr("\"Modulus\": expected type \"double\", got type \"int\""));
}

TEST(TemperatureFunction, TableValuesAndDerivatives)
{
  // E = 200e9 at 300 K, 150e9 at 800 K, 50e9 at 1300 K: slopes -1e8 and -2e8 Pa/K.
  const kiln::TemperatureFunction E = make(table({300, 800, 1300}, {200e9, 150e9, 50e9}));
  EXPECT_FALSE(E.is_constant());
  EXPECT_EQ(E.value(100.0), 200e9);
  EXPECT_NEAR(E.value(550.0), 175e9, 1e-3);
  EXPECT_NEAR(E.value(1050.0), 100e9, 1e-3);
  EXPECT_EQ(E.value(2000.0), 50e9);
  EXPECT_NEAR(E.derivative(550.0), -1e8, 1e-6);
  EXPECT_NEAR(E.derivative(800.0), -2e8, 1e-6); // at a breakpoint: the slope to the right
  EXPECT_EQ(E.derivative(2000.0), 0.0);
  EXPECT_EQ(E.derivative(100.0), 0.0);
  for (const double T : {350.0, 500.0, 790.0, 810.0, 1200.0})
    EXPECT_NEAR(E.derivative(T), central_difference(E, T, 1e-3), 1e-6 * 2e8) << "T = " << T;
  EXPECT_EQ(E.checked_temperatures(), (std::vector<double>{300, 800, 1300}));
}

TEST(TemperatureFunction, ExpressionValueAndDerivative)
{
  // E = 2e11 - 5e7 (T - 300) - 2e4 (T - 300)^2: E' = -5e7 - 4e4 (T - 300).
  const kiln::TemperatureFunction E = make(expression("2e11 - 5e7*(T - 300) - 2e4*(T - 300)^2"));
  EXPECT_FALSE(E.is_constant());
  for (const double T : {1.0, 300.0, 450.5, 900.0})
  {
    const double d = T - 300.0;
    EXPECT_NEAR(E.value(T), 2e11 - 5e7 * d - 2e4 * d * d, 1e-15 * 2e11);
    const double exact = -5e7 - 4e4 * d;
    // The 5-point difference is exact for a quadratic up to round-off: ~1e-16 |E| / h.
    EXPECT_NEAR(E.derivative(T), exact, 1e-10 * std::abs(2e11) / std::max(T, 1.0)) << T;
    EXPECT_NEAR(E.derivative(T), central_difference(E, T, 1e-2), 1e-6 * std::abs(exact)) << T;
  }
  // A smooth non-polynomial one: k = 100 exp(-T/500), k' = -k/500.
  const kiln::TemperatureFunction k = make(expression("100*exp(-T/500)"));
  for (const double T : {10.0, 300.0, 2000.0})
    EXPECT_NEAR(k.derivative(T), -k.value(T) / 500.0, 1e-10 * k.value(T) / 500.0) << T;
  // At T = 0 the step is 1e-4 K (its floor): round-off ~1e-16 |k| / h, 5e-10 relative here.
  EXPECT_NEAR(k.derivative(0.0), -0.2, 1e-8 * 0.2);
}

TEST(TemperatureFunction, ExpressionWithoutTIsConstant)
{
  const kiln::TemperatureFunction E = make(expression("2*pi*1e10"));
  EXPECT_TRUE(E.is_constant());
  EXPECT_EQ(E.derivative(300.0), 0.0);
  EXPECT_NEAR(E.value(300.0), 2 * M_PI * 1e10, 1.0);
}

TEST(TemperatureFunction, ExpressionCheckedAtItsSampleTemperatures)
{
  // 1e11 - 1e8 T crosses 0 at 1000 K: fine up to 900 K, an error if 1200 K is sampled.
  EXPECT_NO_THROW(make(expression("1e11 - 1e8*T", {300, 900})));
  const std::string e = error_of(expression("1e11 - 1e8*T", {300, 900, 1200}));
  EXPECT_THAT(e, HasSubstr("in.xml: Kiln/Materials/steel/Modulus/\"Expression\": = \"1e11 - "
                           "1e8*T\" is -2e+10 at T = 1200 K"));
  EXPECT_THAT(e, HasSubstr("\"Temperatures\" entry 3), but the property must be > 0 at every "
                           "temperature"));
  EXPECT_THAT(error_of(expression("1/(T - 300)", {300})), HasSubstr("is inf at T = 300 K"));
}

TEST(TemperatureFunction, ExpressionSyntaxAndVariables)
{
  EXPECT_THAT(error_of(expression("2e11 - t")),
              HasSubstr("\"t\" is not a variable or function Kiln knows"));
  EXPECT_THAT(error_of(expression("2e11 - t")), HasSubstr("use T [K], numbers"));
  EXPECT_THAT(error_of(expression("  ")), HasSubstr("is empty; give a formula in T [K]"));
}

TEST(TemperatureFunction, TableOutsideTheRangeNamesEntryTemperatureAndRange)
{
  EXPECT_EQ(error_of(table({300, 800, 1300}, {200e9, -1e9, 50e9})),
            "in.xml: Kiln/Materials/steel/Modulus/\"Values\" entry 2 (at 800 K) = -1e+09: must "
            "be > 0 at every temperature of the table");
  EXPECT_THAT(error_of(table({300, 800}, {0.3, 0.5}), kiln::PropertyRange::open(-1.0, 0.5)),
              HasSubstr("\"Values\" entry 2 (at 800 K) = 0.5: must be > -1 and < 0.5"));
  EXPECT_NO_THROW(make(table({300, 800}, {-3e9, 5.0}), kiln::PropertyRange::any()));
}

TEST(TemperatureFunction, TableShapeErrors)
{
  EXPECT_THAT(error_of(table({300, 800, 700}, {1, 2, 3})),
              HasSubstr("Modulus/\"Temperatures\": must be strictly increasing (entries counted "
                        "from 1), but entry 3 (700 K) <= entry 2 (800 K)"));
  EXPECT_THAT(error_of(table({300}, {1})), HasSubstr("has 1 entry but a table needs at least 2"));
  EXPECT_THAT(error_of(table({300, 400}, {1})),
              HasSubstr("\"Values\": has 1 entries but \"Temperatures\" has 2"));
}

TEST(PropertyRange, ContainsAndText)
{
  using kiln::PropertyRange;
  EXPECT_TRUE(PropertyRange::positive().contains(1e-300));
  EXPECT_FALSE(PropertyRange::positive().contains(0.0));
  EXPECT_FALSE(PropertyRange::positive().contains(std::nan("")));
  EXPECT_TRUE(PropertyRange::nonnegative().contains(0.0));
  EXPECT_FALSE(PropertyRange::nonnegative().contains(-1e-300));
  EXPECT_TRUE(PropertyRange::open(-1, 0.5).contains(0.49));
  EXPECT_FALSE(PropertyRange::open(-1, 0.5).contains(0.5));
  EXPECT_FALSE(PropertyRange::open(-1, 0.5).contains(-1.0));
  EXPECT_TRUE(PropertyRange::any().contains(-1e300));
  EXPECT_FALSE(PropertyRange::any().contains(INFINITY));
  EXPECT_EQ(PropertyRange::positive().text(), "must be > 0");
  EXPECT_EQ(PropertyRange::nonnegative().text(), "must be >= 0");
  EXPECT_EQ(PropertyRange::open(-1, 0.5).text(), "must be > -1 and < 0.5");
  EXPECT_EQ(PropertyRange::any().text(), "must be finite");
}
