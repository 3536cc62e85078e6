// Tests the complementarity functions of src/contact (Min, Fischer-Burmeister) and their
// registry: C is zero exactly on the complementarity set (P >= 0, c g >= 0, P c g = 0) and
// not off it; the derivatives match central differences away from the kinks; Min combines
// the rows of a pair exactly where P - c g > 0; the generalized derivative of
// Fischer-Burmeister at the origin; the names the input offers.
#include "contact/complementarity_function.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace
{
std::unique_ptr<kiln::ComplementarityFunction> make(const std::string &name)
{
  return kiln::complementarity_functions().create(name);
}
} // namespace

TEST(ComplementarityFunctions, RegistryOffersMinFirstThenFischerBurmeister)
{
  const auto names = kiln::complementarity_functions().names();
  ASSERT_EQ(names.size(), 2u);
  EXPECT_EQ(names[0], "Min");
  EXPECT_EQ(names[1], "Fischer-Burmeister");
  EXPECT_THROW(make("Penalty"), kiln::InternalError);
}

TEST(ComplementarityFunctions, MinIsAnActiveSet)
{
  const auto min = make("Min");
  // In contact (P > c g): the rows are combined and C = c g; open: the rows stay.
  const auto closed = min->evaluate(5.0, 2.0);
  EXPECT_TRUE(closed.combined);
  EXPECT_EQ(closed.C, 2.0);
  EXPECT_EQ(closed.dC_dP, 0.0);
  EXPECT_EQ(closed.dC_dcg, 1.0);
  EXPECT_FALSE(min->evaluate(2.0, 5.0).combined);
  EXPECT_FALSE(min->evaluate(0.0, 0.0).combined); // the kink belongs to the open side
  EXPECT_FALSE(min->evaluate(-1.0, 0.0).combined);
  EXPECT_TRUE(min->evaluate(1.0, -1.0).combined); // penetrating: pushed apart
}

TEST(ComplementarityFunctions, FischerBurmeisterVanishesOnTheComplementaritySet)
{
  const auto fb = make("Fischer-Burmeister");
  for (const double v : {0.0, 1e-3, 1.0, 1e7})
  {
    EXPECT_NEAR(fb->evaluate(v, 0.0).C, 0.0, 1e-9 * std::max(1.0, v));
    EXPECT_NEAR(fb->evaluate(0.0, v).C, 0.0, 1e-9 * std::max(1.0, v));
    EXPECT_TRUE(fb->evaluate(v, 0.0).combined);
  }
  EXPECT_GT(std::abs(fb->evaluate(1.0, 1.0).C), 0.5);  // both positive
  EXPECT_GT(std::abs(fb->evaluate(-1.0, 0.0).C), 1.0); // negative pressure
  EXPECT_GT(std::abs(fb->evaluate(0.0, -1.0).C), 1.0); // penetration
  // Derivatives against central differences.
  const double h = 1e-6;
  for (const auto &[P, cg] : {std::pair{3.0, 4.0}, std::pair{-2.0, 1.0}, std::pair{5.0, -0.5}})
  {
    const auto v = fb->evaluate(P, cg);
    EXPECT_NEAR(v.dC_dP, (fb->evaluate(P + h, cg).C - fb->evaluate(P - h, cg).C) / (2 * h), 1e-8);
    EXPECT_NEAR(v.dC_dcg, (fb->evaluate(P, cg + h).C - fb->evaluate(P, cg - h).C) / (2 * h), 1e-8);
  }
  // At the origin: the derivative along (1, 1), 1 - 1/sqrt(2) for both.
  const auto origin = fb->evaluate(0.0, 0.0);
  EXPECT_DOUBLE_EQ(origin.dC_dP, 1.0 - 1.0 / std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(origin.dC_dcg, 1.0 - 1.0 / std::sqrt(2.0));
}
