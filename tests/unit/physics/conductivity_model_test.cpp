// Tests src/physics/materials/conductivity_model.cpp: constant and tabulated k(T), its
// derivative (inside, at breakpoints, outside, against finite differences), and the messages
// for inconsistent tables.
// KILN_TEST_NP: 1
#include "physics/materials/conductivity_model.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "support/parameter_lists.hpp"

#include <Teuchos_Array.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

using testing::HasSubstr;

namespace
{
const std::string where = "in.xml: Kiln/Physics/Heat/Conductivity";

kiln::ConductivityModel make(const Teuchos::ParameterList &user)
{
  const Teuchos::ParameterList p = kiln::validated(
      user, kiln::ConductivityModel::valid_parameters(), "in.xml", "Kiln/Physics/Heat");
  return kiln::ConductivityModel(p, where);
}

std::string error_of(const Teuchos::ParameterList &user)
{
  return kiln_test::input_error_message([&] { make(user); });
}

Teuchos::ParameterList table(const std::vector<double> &temperatures,
                             const std::vector<double> &values)
{
  Teuchos::ParameterList p;
  p.set("Type", "Table");
  p.set("Temperatures", Teuchos::Array<double>(temperatures.begin(), temperatures.end()));
  p.set("Values", Teuchos::Array<double>(values.begin(), values.end()));
  return p;
}

/// k = 200 at 250 K, 240 at 300 K, 230 at 400 K: slopes 0.8 and -0.1 W/(m K^2).
kiln::ConductivityModel aluminium_like()
{
  return make(table({250, 300, 400}, {200, 240, 230}));
}
} // namespace

TEST(ConductivityModel, Constant)
{
  Teuchos::ParameterList user;
  user.set("Value", 240.0);
  const kiln::ConductivityModel k = make(user);
  EXPECT_EQ(k.value(10.0), 240.0);
  EXPECT_EQ(k.value(1000.0), 240.0);
  EXPECT_EQ(k.derivative(300.0), 0.0);
  EXPECT_EQ(kiln::ConductivityModel::constant(2.5).value(300.0), 2.5);
  EXPECT_EQ(kiln::ConductivityModel::constant(2.5).derivative(300.0), 0.0);
  EXPECT_EQ(kiln::ConductivityModel().value(300.0), 1.0);
}

TEST(ConductivityModel, TableValues)
{
  const kiln::ConductivityModel k = aluminium_like();
  EXPECT_EQ(k.value(100.0), 200.0); // below: the first value
  EXPECT_EQ(k.value(250.0), 200.0);
  EXPECT_NEAR(k.value(275.0), 220.0, 1e-12);
  EXPECT_NEAR(k.value(300.0), 240.0, 1e-12);
  EXPECT_NEAR(k.value(350.0), 235.0, 1e-12);
  EXPECT_EQ(k.value(400.0), 230.0);
  EXPECT_EQ(k.value(900.0), 230.0); // above: the last value
}

TEST(ConductivityModel, TableDerivatives)
{
  const kiln::ConductivityModel k = aluminium_like();
  EXPECT_EQ(k.derivative(100.0), 0.0);          // below the table
  EXPECT_NEAR(k.derivative(250.0), 0.8, 1e-14); // first point: the interval to the right
  EXPECT_NEAR(k.derivative(275.0), 0.8, 1e-14);
  EXPECT_NEAR(k.derivative(300.0), -0.1, 1e-14); // breakpoint: the interval to the right
  EXPECT_NEAR(k.derivative(350.0), -0.1, 1e-14);
  EXPECT_EQ(k.derivative(400.0), 0.0); // last point: nothing to the right
  EXPECT_EQ(k.derivative(900.0), 0.0);
}

TEST(ConductivityModel, DerivativeMatchesFiniteDifferenceInsideIntervals)
{
  const kiln::ConductivityModel k = aluminium_like();
  const double h = 1e-4;
  for (const double T : {251.0, 262.5, 299.0, 301.0, 333.3, 399.0})
  {
    const double fd = (k.value(T + h) - k.value(T - h)) / (2 * h);
    EXPECT_NEAR(k.derivative(T), fd, 1e-7) << "T = " << T;
  }
}

TEST(ConductivityModel, TableWithOnePointIsAnError)
{
  const std::string e = error_of(table({300}, {240}));
  EXPECT_THAT(e, HasSubstr(where + "/\"Temperatures\": has 1 entry but a table needs at least 2"));
  EXPECT_THAT(e, HasSubstr("use Type \"Constant\""));
}

TEST(ConductivityModel, NonIncreasingTemperaturesAreAnError)
{
  const std::string e = error_of(table({250, 300, 290}, {1, 2, 3}));
  EXPECT_THAT(e, HasSubstr(where + "/\"Temperatures\": must be strictly increasing"));
  EXPECT_THAT(e, HasSubstr("entry 3 (290 K) <= entry 2 (300 K)"));
  EXPECT_THAT(error_of(table({250, 250}, {1, 2})), HasSubstr("entry 2 (250 K) <= entry 1 (250 K)"));
}

TEST(ConductivityModel, TableLengthsMustAgree)
{
  const std::string e = error_of(table({250, 300, 400}, {1, 2}));
  EXPECT_THAT(e, HasSubstr(where + "/\"Values\": has 2 entries but \"Temperatures\" has 3"));
}

TEST(ConductivityModel, NonPositiveValuesAreRejectedByValidation)
{
  Teuchos::ParameterList user;
  user.set("Value", 0.0);
  EXPECT_THAT(error_of(user), HasSubstr("in.xml: Kiln/Physics/Heat/\"Value\""));
  EXPECT_THAT(error_of(table({250, 300}, {1, -2})), HasSubstr("\"Values\""));
}
