// Tests src/physics/materials/time_function.cpp: constant, smooth step (the contact-box end-face
// temperature) and table functions, and the messages for inconsistent parameters.
// KILN_TEST_NP: 1
#include "physics/materials/time_function.hpp"

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
const std::string where = "in.xml: Kiln/Boundary Conditions/Left/Temperature";

kiln::TimeFunction make(const Teuchos::ParameterList &user)
{
  const Teuchos::ParameterList p = kiln::validated(user, kiln::TimeFunction::valid_parameters(),
                                                   "in.xml", "Kiln/Boundary Conditions/Left");
  return kiln::TimeFunction(p, where);
}

std::string error_of(const Teuchos::ParameterList &user)
{
  return kiln_test::input_error_message([&] { make(user); });
}

/// A Smooth Step from y0 at x0 to y1 at x1.
Teuchos::ParameterList smooth_step(const double x0, const double x1, const double y0,
                                   const double y1)
{
  return kiln_test::smooth_step(y0, y1, x0, x1);
}

Teuchos::ParameterList table(const std::vector<double> &times, const std::vector<double> &values)
{
  Teuchos::ParameterList p;
  p.set("Type", "Table");
  p.set("Times", Teuchos::Array<double>(times.begin(), times.end()));
  p.set("Values", Teuchos::Array<double>(values.begin(), values.end()));
  return p;
}
} // namespace

TEST(TimeFunction, ConstantByParametersAndFactory)
{
  Teuchos::ParameterList user;
  user.set("Value", 298.0);
  const kiln::TimeFunction f = make(user); // "Type" defaults to "Constant"
  EXPECT_EQ(f.value(-5.0), 298.0);
  EXPECT_EQ(f.value(1e6), 298.0);
  EXPECT_EQ(kiln::TimeFunction::constant(-3.5).value(10.0), -3.5);
  EXPECT_EQ(kiln::TimeFunction().value(1.0), 0.0);
}

TEST(TimeFunction, SmoothStepOfContactBoxClose)
{
  // 288 -> 308 K over 0..100 s. At t = 25: s = 1/4, s^2 (3 - 2 s) = (1/16)(5/2) = 0.15625.
  const kiln::TimeFunction f = make(smooth_step(0, 100, 288, 308));
  EXPECT_EQ(f.value(-10.0), 288.0);
  EXPECT_EQ(f.value(0.0), 288.0);
  EXPECT_NEAR(f.value(25.0), 288 + 20 * 0.15625, 1e-12);
  EXPECT_NEAR(f.value(50.0), 298.0, 1e-12);
  EXPECT_NEAR(f.value(75.0), 308 - 20 * 0.15625, 1e-12); // odd symmetry about the midpoint
  EXPECT_EQ(f.value(100.0), 308.0);
  EXPECT_EQ(f.value(150.0), 308.0);
  // Continuous at both ends.
  EXPECT_NEAR(f.value(1e-9), 288.0, 1e-12);
  EXPECT_NEAR(f.value(100 - 1e-9), 308.0, 1e-12);
}

TEST(TimeFunction, SmoothStepDownWithShiftedTimes)
{
  // 308 -> 288 K over 10..30 s: the midpoint is at 20 s.
  const kiln::TimeFunction f = make(smooth_step(10, 30, 308, 288));
  EXPECT_EQ(f.value(5.0), 308.0);
  EXPECT_NEAR(f.value(15.0), 308 - 20 * 0.15625, 1e-12);
  EXPECT_NEAR(f.value(20.0), 298.0, 1e-12);
  EXPECT_EQ(f.value(31.0), 288.0);
}

TEST(TimeFunction, TableInterpolatesAndExtrapolatesConstant)
{
  const kiln::TimeFunction f = make(table({0, 10, 30}, {100, 200, 150}));
  EXPECT_EQ(f.value(-1.0), 100.0);
  EXPECT_EQ(f.value(0.0), 100.0);
  EXPECT_NEAR(f.value(2.5), 125.0, 1e-12);
  EXPECT_NEAR(f.value(10.0), 200.0, 1e-12);
  EXPECT_NEAR(f.value(20.0), 175.0, 1e-12);
  EXPECT_EQ(f.value(30.0), 150.0);
  EXPECT_EQ(f.value(1e9), 150.0);

  // A single entry is a constant.
  const kiln::TimeFunction g = make(table({5}, {42}));
  EXPECT_EQ(g.value(0.0), 42.0);
  EXPECT_EQ(g.value(5.0), 42.0);
  EXPECT_EQ(g.value(9.0), 42.0);
}

TEST(TimeFunction, EndTimeNotAfterStartTimeIsAnError)
{
  for (const double end : {100.0, 50.0})
  {
    const std::string e = error_of(smooth_step(100, end, 288, 308));
    EXPECT_THAT(e, HasSubstr(where + "/\"End Time\": = "));
    EXPECT_THAT(e, HasSubstr("must be > \"Start Time\" = 100"));
  }
}

TEST(TimeFunction, NonIncreasingTableTimesAreAnError)
{
  const std::string e = error_of(table({0, 10, 10, 20}, {1, 2, 3, 4}));
  EXPECT_THAT(e, HasSubstr(where + "/\"Times\": must be strictly increasing"));
  EXPECT_THAT(e, HasSubstr("entry 3 (10) <= entry 2 (10)"));
  EXPECT_THAT(error_of(table({0, 10, 5}, {1, 2, 3})), HasSubstr("entry 3 (5) <= entry 2 (10)"));
}

TEST(TimeFunction, TableLengthsMustAgree)
{
  const std::string e = error_of(table({0, 10, 20}, {1, 2}));
  EXPECT_THAT(e, HasSubstr(where + "/\"Values\": has 2 entries but \"Times\" has 3"));
}

TEST(TimeFunction, EmptyTableAndUnknownTypeAreRejectedByValidation)
{
  EXPECT_THAT(error_of(table({}, {})), HasSubstr("\"Times\""));
  Teuchos::ParameterList user;
  user.set("Type", "Ramp");
  const std::string e = error_of(user);
  EXPECT_THAT(e, HasSubstr("\"Type\""));
  EXPECT_THAT(e, HasSubstr("\"Constant\""));
  EXPECT_THAT(e, HasSubstr("\"Smooth Step\""));
}

// --- Type "Expression": a formula in x, y, z, t ------------------------------------------------

namespace
{
Teuchos::ParameterList expression(const std::string &text)
{
  Teuchos::ParameterList p;
  p.set("Type", "Expression");
  p.set("Expression", text);
  return p;
}
} // namespace

TEST(TimeFunction, ExpressionOfSpaceAndTime)
{
  const kiln::TimeFunction f = make(expression("1 + x + 2*y + 3*z + 0.5*t^2"));
  EXPECT_TRUE(f.varies_in_space());
  EXPECT_DOUBLE_EQ(f.value(2.0, {0.1, 0.2, 0.3}), 1 + 0.1 + 0.4 + 0.9 + 2.0);
  EXPECT_DOUBLE_EQ(f.value(0.0, {-1.0, 0.0, 2.0}), 6.0);
  // Copies share the formula and give the same values.
  const kiln::TimeFunction g = f;
  EXPECT_DOUBLE_EQ(g.value(1.0, {1.0, 1.0, 1.0}), 7.5);
  EXPECT_DOUBLE_EQ(f.value(1.0, {0.0, 0.0, 0.0}), 1.5);
}

TEST(TimeFunction, ExpressionOfTimeAloneIsAFunctionOfTime)
{
  const kiln::TimeFunction f = make(expression("300 + 10*sin(pi*t/60)"));
  EXPECT_FALSE(f.varies_in_space());
  EXPECT_NEAR(f.value(30.0), 310.0, 1e-12);
  EXPECT_NEAR(f.value(30.0, {5.0, 6.0, 7.0}), 310.0, 1e-12);
  // ValueAt: a function of time is evaluated once, at any point the same.
  const kiln::ValueAt at(f, 30.0);
  EXPECT_NEAR(at({1.0, 2.0, 3.0}), 310.0, 1e-12);
  const kiln::TimeFunction g = make(expression("x*t"));
  const kiln::ValueAt varying(g, 2.0); // holds g by address: g outlives it
  EXPECT_DOUBLE_EQ(varying({3.0, 0.0, 0.0}), 6.0);
}

TEST(TimeFunction, ExpressionErrorsNameTheParameter)
{
  EXPECT_THAT(
      error_of(expression("1 + (x")),
      HasSubstr(where + "/\"Expression\": = \"1 + (x\" cannot be read: Missing parenthesis"));
  EXPECT_THAT(error_of(expression("2*temperature")),
              HasSubstr("\"temperature\" is not a variable or function Kiln knows"));
  EXPECT_THAT(error_of(expression("  ")), HasSubstr("is empty; give a formula in x, y, z"));
  const kiln::TimeFunction f = make(expression("1/(x - 1)"));
  EXPECT_THAT(kiln_test::input_error_message(
                  [&] {
                    f.check_finite({{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}, 0.0, where);
                  }),
              HasSubstr("= \"1/(x - 1)\" is inf at (1, 0, 0) m, t = 0 s"));
  EXPECT_NO_THROW(f.check_finite({{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}}, 0.0, where));
}
