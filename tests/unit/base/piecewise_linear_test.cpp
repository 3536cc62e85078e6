// Tests base/piecewise_linear: values and slopes inside, at and beyond the
// breakpoints, a single point as a constant, and the table checks.
// KILN_TEST_NP: 1
#include "base/errors.hpp"
#include "base/piecewise_linear.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using kiln::PiecewiseLinear;
using testing::HasSubstr;

TEST(PiecewiseLinear, ValuesAndSlopes)
{
  const PiecewiseLinear f({0.0, 10.0, 20.0}, {1.0, 3.0, 2.0}, {"t.xml: B", "X", "Y", " s"});
  EXPECT_DOUBLE_EQ(f.value(-5.0), 1.0);
  EXPECT_DOUBLE_EQ(f.value(5.0), 2.0);
  EXPECT_DOUBLE_EQ(f.value(10.0), 3.0);
  EXPECT_DOUBLE_EQ(f.value(15.0), 2.5);
  EXPECT_DOUBLE_EQ(f.value(99.0), 2.0);
  EXPECT_DOUBLE_EQ(f.slope(-5.0), 0.0);
  EXPECT_DOUBLE_EQ(f.slope(0.0), 0.2);
  EXPECT_DOUBLE_EQ(f.slope(10.0), -0.1); // the interval to the right
  EXPECT_DOUBLE_EQ(f.slope(20.0), 0.0);
}

TEST(PiecewiseLinear, SinglePointIsConstant)
{
  const PiecewiseLinear f({0.0}, {4.0}, {});
  EXPECT_DOUBLE_EQ(f.value(-1e9), 4.0);
  EXPECT_DOUBLE_EQ(f.value(1e9), 4.0);
  EXPECT_DOUBLE_EQ(f.slope(0.0), 0.0);
}

TEST(PiecewiseLinear, ChecksTheTable)
{
  const PiecewiseLinear::Names names{"t.xml: B", "X", "Y", " s"};
  try
  {
    PiecewiseLinear({0.0, 1.0}, {1.0}, names);
    FAIL() << "no error for unequal lengths";
  }
  catch (const kiln::InputError &e)
  {
    EXPECT_THAT(e.what(), HasSubstr("t.xml: B/\"Y\": has 1 entries but \"X\" has 2"));
  }
  try
  {
    PiecewiseLinear({0.0, 2.0, 2.0}, {1.0, 2.0, 3.0}, names);
    FAIL() << "no error for non-increasing x";
  }
  catch (const kiln::InputError &e)
  {
    EXPECT_THAT(
        e.what(),
        HasSubstr(
            "B/\"X\": must be strictly increasing (entries counted from 1), but entry 3 (2 s) "
            "<= entry 2 (2 s)"));
  }
}
