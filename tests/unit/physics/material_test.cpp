// Tests src/physics/materials/material.cpp: the spec aluminium as default, the elastic
// constants computed from whichever pair (E, nu) or (lambda, G) is given, and the messages
// for pairs given partly, both pairs given and values out of range.
// KILN_TEST_NP: 1
#include "physics/materials/material.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "support/parameter_lists.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

using testing::HasSubstr;

namespace
{
kiln::Material make(const Teuchos::ParameterList &user)
{
  const Teuchos::ParameterList p =
      kiln::validated(user, kiln::Material::valid_parameters(), "test.xml", "Kiln/Material");
  return kiln::Material(p, "test.xml: Kiln/Material");
}

std::string error_of(const Teuchos::ParameterList &user)
{
  return kiln_test::input_error_message([&] { make(user); });
}

Teuchos::ParameterList E_nu(const double E, const double nu)
{
  Teuchos::ParameterList p;
  p.set("Young's Modulus", E);
  p.set("Poisson's Ratio", nu);
  return p;
}

Teuchos::ParameterList lambda_G(const double lambda, const double G)
{
  Teuchos::ParameterList p;
  p.set("Lame Lambda", lambda);
  p.set("Shear Modulus", G);
  return p;
}

/// Equal up to round-off. Converting between the pairs divides by 1 + nu and 1 - 2 nu, so
/// near nu = -1 or 0.5 a round trip loses a few hundred ulp: hence 1e-12 relative, not 4 ulp.
void expect_same_elasticity(const kiln::Material &a, const kiln::Material &b)
{
  const double rel_tol = 1.0e-12;
  EXPECT_NEAR(a.lame_lambda(), b.lame_lambda(), rel_tol * std::abs(a.lame_lambda()));
  EXPECT_NEAR(a.shear_modulus(), b.shear_modulus(), rel_tol * a.shear_modulus());
  EXPECT_NEAR(a.youngs_modulus(), b.youngs_modulus(), rel_tol * a.youngs_modulus());
  EXPECT_NEAR(a.poissons_ratio(), b.poissons_ratio(), rel_tol);
}
} // namespace

TEST(Material, DefaultIsTheSpecAluminium)
{
  const kiln::Material m;
  EXPECT_EQ(m.density(), 2.7e3);
  EXPECT_EQ(m.specific_heat(), 9.0e2);
  EXPECT_EQ(m.conductivity().value(300.0), 2.4e2);
  EXPECT_EQ(m.lame_lambda(), 5.2e10);
  EXPECT_EQ(m.shear_modulus(), 2.6e10);
  EXPECT_DOUBLE_EQ(m.youngs_modulus(), 2.6e10 * (3 * 5.2e10 + 2 * 2.6e10) / (5.2e10 + 2.6e10));
  EXPECT_NEAR(m.youngs_modulus(), 6.9333333333e10, 1.0);
  EXPECT_DOUBLE_EQ(m.poissons_ratio(), 1.0 / 3.0);
  EXPECT_EQ(m.thermal_expansion(), 2.2e-5);
  EXPECT_EQ(m.reference_temperature(), 298.0);
}

TEST(Material, EmptyInputGivesTheDefaults)
{
  const kiln::Material m = make(Teuchos::ParameterList());
  const kiln::Material aluminium;
  EXPECT_EQ(m.density(), aluminium.density());
  EXPECT_EQ(m.specific_heat(), aluminium.specific_heat());
  EXPECT_EQ(m.lame_lambda(), aluminium.lame_lambda());
  EXPECT_EQ(m.shear_modulus(), aluminium.shear_modulus());
  EXPECT_EQ(m.youngs_modulus(), aluminium.youngs_modulus());
  EXPECT_EQ(m.poissons_ratio(), aluminium.poissons_ratio());
  EXPECT_EQ(m.thermal_expansion(), aluminium.thermal_expansion());
  EXPECT_EQ(m.reference_temperature(), aluminium.reference_temperature());
}

TEST(Material, DefaultsOfTheValidListAreTheDefaultMaterial)
{
  const Teuchos::ParameterList valid = kiln::Material::valid_parameters();
  const kiln::Material aluminium;
  EXPECT_EQ(valid.get<double>("Young's Modulus"), aluminium.youngs_modulus());
  EXPECT_EQ(valid.get<double>("Poisson's Ratio"), aluminium.poissons_ratio());
  EXPECT_EQ(valid.get<double>("Lame Lambda"), aluminium.lame_lambda());
  EXPECT_EQ(valid.get<double>("Shear Modulus"), aluminium.shear_modulus());
  EXPECT_EQ(valid.get<double>("Thermal Expansion"), 2.2e-5);
  EXPECT_EQ(valid.get<double>("Reference Temperature"), 298.0);
}

TEST(Material, YoungsModulusAndPoissonsRatio)
{
  // lambda = E nu / ((1 + nu)(1 - 2 nu)) = 0.25 / (1.25 * 0.5), G = E / (2 (1 + nu)) = 1 / 2.5.
  const kiln::Material m = make(E_nu(1.0, 0.25));
  EXPECT_DOUBLE_EQ(m.lame_lambda(), 0.4);
  EXPECT_DOUBLE_EQ(m.shear_modulus(), 0.4);
  EXPECT_EQ(m.youngs_modulus(), 1.0);
  EXPECT_EQ(m.poissons_ratio(), 0.25);
}

TEST(Material, LameConstants)
{
  // G = lambda gives nu = 1/4 and E = G (3 + 2) / 2 = 2.5 G.
  const kiln::Material m = make(lambda_G(0.4, 0.4));
  EXPECT_EQ(m.lame_lambda(), 0.4);
  EXPECT_EQ(m.shear_modulus(), 0.4);
  EXPECT_DOUBLE_EQ(m.youngs_modulus(), 1.0);
  EXPECT_DOUBLE_EQ(m.poissons_ratio(), 0.25);
}

TEST(Material, PairsRoundTrip)
{
  for (const double nu : {-0.9, -0.2, 0.0, 0.3, 1.0 / 3.0, 0.45, 0.499})
  {
    const kiln::Material from_E_nu = make(E_nu(7.0e10, nu));
    const kiln::Material from_lambda_G =
        make(lambda_G(from_E_nu.lame_lambda(), from_E_nu.shear_modulus()));
    expect_same_elasticity(from_E_nu, from_lambda_G);
    const kiln::Material back =
        make(E_nu(from_lambda_G.youngs_modulus(), from_lambda_G.poissons_ratio()));
    expect_same_elasticity(from_E_nu, back);
  }
  // Negative lambda is allowed as long as the bulk modulus is positive (nu < 0).
  const kiln::Material m = make(lambda_G(-1.0e10, 2.6e10));
  EXPECT_LT(m.poissons_ratio(), 0.0);
  expect_same_elasticity(m, make(E_nu(m.youngs_modulus(), m.poissons_ratio())));
}

TEST(Material, AluminiumFromEitherPair)
{
  const kiln::Material aluminium;
  expect_same_elasticity(aluminium, make(lambda_G(5.2e10, 2.6e10)));
  expect_same_elasticity(aluminium, make(E_nu(aluminium.youngs_modulus(), 1.0 / 3.0)));
}

TEST(Material, ThermalExpansionAndReferenceTemperature)
{
  Teuchos::ParameterList user;
  user.set("Thermal Expansion", 1.2e-5);
  user.set("Reference Temperature", 293.15);
  const kiln::Material m = make(user);
  EXPECT_EQ(m.thermal_expansion(), 1.2e-5);
  EXPECT_EQ(m.reference_temperature(), 293.15);
  user.set("Thermal Expansion", 0.0);
  EXPECT_EQ(make(user).thermal_expansion(), 0.0);
}

TEST(Material, PairGivenPartly)
{
  for (const auto &[given, missing] :
       {std::pair<std::string, std::string>{"Young's Modulus", "Poisson's Ratio"},
        {"Poisson's Ratio", "Young's Modulus"},
        {"Lame Lambda", "Shear Modulus"},
        {"Shear Modulus", "Lame Lambda"}})
  {
    Teuchos::ParameterList user;
    user.set(given, 0.3);
    const std::string e = error_of(user);
    EXPECT_THAT(e, HasSubstr("test.xml: Kiln/Material/\"" + given + "\": is given without \"" +
                             missing + "\"; give both "));
    EXPECT_THAT(e, HasSubstr(", or neither"));
  }
  Teuchos::ParameterList user;
  user.set("Young's Modulus", 7.0e10);
  EXPECT_EQ(error_of(user), "test.xml: Kiln/Material/\"Young's Modulus\": is given without "
                            "\"Poisson's Ratio\"; give both \"Young's Modulus\" and \"Poisson's "
                            "Ratio\", or neither");
}

TEST(Material, BothPairsGiven)
{
  Teuchos::ParameterList user = E_nu(7.0e10, 0.3);
  user.setParameters(lambda_G(5.2e10, 2.6e10));
  EXPECT_EQ(error_of(user),
            "test.xml: Kiln/Material/\"Lame Lambda\": is given together with \"Young's "
            "Modulus\", but the elastic constants are one pair: give either \"Young's Modulus\" "
            "and \"Poisson's Ratio\", or \"Lame Lambda\" and \"Shear Modulus\", not both");
  // One of each pair is also a mix of the two pairs, not a pair given partly.
  Teuchos::ParameterList mixed;
  mixed.set("Poisson's Ratio", 0.3);
  mixed.set("Shear Modulus", 2.6e10);
  EXPECT_THAT(error_of(mixed), HasSubstr("Kiln/Material/\"Shear Modulus\": is given together "
                                         "with \"Poisson's Ratio\", but the elastic constants "
                                         "are one pair"));
}

TEST(Material, YoungsModulusMustBePositive)
{
  EXPECT_THAT(error_of(E_nu(0.0, 0.3)),
              HasSubstr("test.xml: Kiln/Material/\"Young's Modulus\" = 0: must be > 0"));
  EXPECT_THAT(error_of(E_nu(-7.0e10, 0.3)),
              HasSubstr("Kiln/Material/\"Young's Modulus\" = -7e+10: must be > 0"));
}

TEST(Material, PoissonsRatioMustBeBetweenMinusOneAndOneHalf)
{
  EXPECT_EQ(error_of(E_nu(7.0e10, 0.5)),
            "test.xml: Kiln/Material/\"Poisson's Ratio\" = 0.5: must be > -1 and < 0.5; 0.5 is "
            "an incompressible material, which the displacement formulation cannot represent: "
            "give a value below 0.5");
  EXPECT_THAT(error_of(E_nu(7.0e10, 0.6)),
              HasSubstr("Kiln/Material/\"Poisson's Ratio\" = 0.6: must be > -1 and < 0.5;"));
  EXPECT_EQ(error_of(E_nu(7.0e10, -1.0)),
            "test.xml: Kiln/Material/\"Poisson's Ratio\" = -1: must be > -1 and < 0.5");
  EXPECT_EQ(error_of(E_nu(7.0e10, -1.5)),
            "test.xml: Kiln/Material/\"Poisson's Ratio\" = -1.5: must be > -1 and < 0.5");
  EXPECT_EQ(error_of(E_nu(7.0e10, 0.4999)), "");
  EXPECT_EQ(error_of(E_nu(7.0e10, -0.999)), "");
}

TEST(Material, ShearModulusMustBePositive)
{
  EXPECT_THAT(error_of(lambda_G(5.2e10, 0.0)),
              HasSubstr("test.xml: Kiln/Material/\"Shear Modulus\" = 0: must be > 0"));
  EXPECT_THAT(error_of(lambda_G(5.2e10, -2.6e10)),
              HasSubstr("Kiln/Material/\"Shear Modulus\" = -2.6e+10: must be > 0"));
}

TEST(Material, BulkModulusMustBePositive)
{
  // lambda + 2G/3 = -3e10 + 2e10 = -1e10.
  EXPECT_EQ(error_of(lambda_G(-3.0e10, 3.0e10)),
            "test.xml: Kiln/Material/\"Lame Lambda\" = -3e+10: gives the bulk modulus lambda + "
            "2G/3 = -1e+10 Pa with \"Shear Modulus\" = 3e+10 Pa, but it must be > 0: give "
            "\"Lame Lambda\" > -2e+10 Pa");
  EXPECT_THAT(error_of(lambda_G(-2.0e10, 3.0e10)), HasSubstr("gives the bulk modulus"));
  EXPECT_EQ(error_of(lambda_G(-1.9e10, 3.0e10)), "");
}

TEST(Material, ThermalExpansionAndReferenceTemperatureRanges)
{
  Teuchos::ParameterList alpha;
  alpha.set("Thermal Expansion", -1.0e-5);
  EXPECT_THAT(error_of(alpha),
              HasSubstr("test.xml: Kiln/Material/\"Thermal Expansion\" = -1e-05: must be >= 0"));
  Teuchos::ParameterList T_ref;
  T_ref.set("Reference Temperature", 0.0);
  EXPECT_THAT(error_of(T_ref),
              HasSubstr("test.xml: Kiln/Material/\"Reference Temperature\" = 0: must be > 0"));
}
