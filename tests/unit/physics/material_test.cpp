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
#include <stdexcept>
#include <string>
#include <vector>

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
  EXPECT_EQ(valid.sublist("Young's Modulus").get<double>("Value"), aluminium.youngs_modulus());
  EXPECT_EQ(valid.sublist("Poisson's Ratio").get<double>("Value"), aluminium.poissons_ratio());
  EXPECT_EQ(valid.sublist("Lame Lambda").get<double>("Value"), aluminium.lame_lambda());
  EXPECT_EQ(valid.sublist("Shear Modulus").get<double>("Value"), aluminium.shear_modulus());
  EXPECT_EQ(valid.sublist("Thermal Expansion").get<double>("Value"), 2.2e-5);
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

namespace
{
/// A property sublist of Type "Table".
Teuchos::ParameterList property_table(const std::vector<double> &temperatures,
                                      const std::vector<double> &values)
{
  Teuchos::ParameterList p;
  p.set("Type", "Table");
  p.set("Temperatures", kiln_test::values(temperatures));
  p.set("Values", kiln_test::values(values));
  return p;
}

/// A property sublist of Type "Expression" checked at 300 and 1000 K.
Teuchos::ParameterList property_expression(const std::string &text)
{
  Teuchos::ParameterList p;
  p.set("Type", "Expression");
  p.set("Expression", text);
  p.set("Temperatures", kiln_test::values({300.0, 1000.0}));
  return p;
}

/// d/dT of `f` by central differences with step h [K].
template <typename F> double central_difference(const F &f, const double T, const double h)
{
  return (f(T + h) - f(T - h)) / (2.0 * h);
}
} // namespace

TEST(Material, TemperatureDependentElasticityFromENu)
{
  Teuchos::ParameterList user;
  user.set("Young's Modulus", property_expression("2e11 - 8e7*(T - 300)"));
  user.set("Poisson's Ratio", property_expression("0.28 + 1e-4*(T - 300)"));
  const kiln::Material m = make(user);
  EXPECT_EQ(m.temperature_dependent_properties(),
            (std::vector<std::string>{"Young's Modulus", "Poisson's Ratio"}));
  EXPECT_FALSE(m.is_constant());
  for (const double T : {300.0, 650.0, 950.0})
  {
    const double E = 2e11 - 8e7 * (T - 300), nu = 0.28 + 1e-4 * (T - 300);
    EXPECT_NEAR(m.youngs_modulus(T), E, 1e-12 * E);
    EXPECT_NEAR(m.poissons_ratio(T), nu, 1e-14);
    EXPECT_NEAR(m.lame_lambda(T), E * nu / ((1 + nu) * (1 - 2 * nu)), 1e-12 * E);
    EXPECT_NEAR(m.shear_modulus(T), E / (2 * (1 + nu)), 1e-12 * E);
    const auto lambda = [&m](const double t) { return m.lame_lambda(t); };
    const auto G = [&m](const double t) { return m.shear_modulus(t); };
    // The chain rule through (E, nu) against central differences (O(h^2) = 1e-8 relative).
    EXPECT_NEAR(m.d_lame_lambda_d_T(T), central_difference(lambda, T, 0.1),
                1e-6 * std::abs(m.d_lame_lambda_d_T(T)))
        << T;
    EXPECT_NEAR(m.d_shear_modulus_d_T(T), central_difference(G, T, 0.1),
                1e-6 * std::abs(m.d_shear_modulus_d_T(T)))
        << T;
  }
  EXPECT_THROW((void)m.lame_lambda(), std::logic_error);
  EXPECT_THROW((void)m.youngs_modulus(), std::logic_error);
  EXPECT_EQ(m.density(), 2.7e3); // constant ones still answer
}

TEST(Material, TemperatureDependentLameConstants)
{
  Teuchos::ParameterList user;
  user.set("Lame Lambda", property_table({300, 900}, {6e10, 4e10}));
  user.set("Shear Modulus", property_table({400, 800}, {3e10, 2e10}));
  const kiln::Material m = make(user);
  EXPECT_NEAR(m.lame_lambda(600.0), 5e10, 1e-3);
  EXPECT_NEAR(m.d_lame_lambda_d_T(600.0), -2e10 / 600.0, 1e-3);
  EXPECT_NEAR(m.shear_modulus(600.0), 2.5e10, 1e-3);
  EXPECT_NEAR(m.d_shear_modulus_d_T(600.0), -2.5e7, 1e-6);
  EXPECT_NEAR(m.poissons_ratio(600.0), 5e10 / (2 * 7.5e10), 1e-14);
}

TEST(Material, ThermalStrainIsTheSecantDefinition)
{
  // alpha(T) = 1e-5 + 2e-8 (T - 300), T_ref = 300 K. Secant: eps = alpha(T) (T - T_ref).
  // The instantaneous definition would give the integral 1e-5 (T - 300) + 1e-8 (T - 300)^2.
  Teuchos::ParameterList user;
  user.set("Thermal Expansion", property_expression("1e-5 + 2e-8*(T - 300)"));
  user.set("Reference Temperature", 300.0);
  const kiln::Material m = make(user);
  const double T = 800.0, d = T - 300.0;
  const double secant = (1e-5 + 2e-8 * d) * d;          // 1e-2
  const double instantaneous = 1e-5 * d + 1e-8 * d * d; // 7.5e-3
  EXPECT_NEAR(m.thermal_strain(T), secant, 1e-15);
  EXPECT_GT(std::abs(m.thermal_strain(T) - instantaneous), 1e-3);
  EXPECT_NEAR(m.d_thermal_strain_d_T(T), 2e-8 * d + 1e-5 + 2e-8 * d, 1e-14);
  const auto eps = [&m](const double t) { return m.thermal_strain(t); };
  for (const double t : {250.0, 300.0, 555.0, 1000.0})
    EXPECT_NEAR(m.d_thermal_strain_d_T(t), central_difference(eps, t, 0.01), 1e-12) << t;
  EXPECT_EQ(m.thermal_strain(300.0), 0.0);
}

TEST(Material, HeatCapacityDerivative)
{
  Teuchos::ParameterList user;
  user.set("Density", property_table({300, 900}, {7900, 7600}));
  user.set("Specific Heat", property_expression("450 + 0.3*(T - 300)"));
  const kiln::Material m = make(user);
  const auto rho_c = [&m](const double t) { return m.heat_capacity(t); };
  for (const double T : {350.0, 600.0, 850.0})
  {
    EXPECT_NEAR(m.heat_capacity(T), m.density(T) * m.specific_heat(T), 1e-6);
    EXPECT_NEAR(m.d_heat_capacity_d_T(T), central_difference(rho_c, T, 0.01),
                1e-6 * std::abs(m.d_heat_capacity_d_T(T)))
        << T;
  }
  EXPECT_EQ(m.temperature_dependent_properties(),
            (std::vector<std::string>{"Density", "Specific Heat"}));
  EXPECT_THROW((void)m.heat_capacity(), std::logic_error);
}

TEST(Material, PropertyTablesOutOfRangeNameMaterialPropertyAndRange)
{
  Teuchos::ParameterList user;
  user.set("Young's Modulus", property_table({300, 600}, {2e11, -1e9}));
  user.set("Poisson's Ratio", 0.3);
  EXPECT_EQ(error_of(user), "test.xml: Kiln/Material/Young's Modulus/\"Values\" entry 2 (at "
                            "600 K) = -1e+09: must be > 0 at every temperature of the table");

  Teuchos::ParameterList nu;
  nu.set("Young's Modulus", 2e11);
  nu.set("Poisson's Ratio", property_table({300, 600}, {0.3, 0.5}));
  EXPECT_THAT(error_of(nu), HasSubstr("test.xml: Kiln/Material/\"Poisson's Ratio\" = 0.5 at T = "
                                      "600 K: must be > -1 and < 0.5; 0.5 is an incompressible"));

  // The bulk modulus is checked at the points of both tables: lambda + 2G/3 < 0 at 700 K.
  Teuchos::ParameterList bulk;
  bulk.set("Lame Lambda", property_table({300, 700}, {1e10, -3e10}));
  bulk.set("Shear Modulus", property_table({300, 500}, {3e10, 3e10}));
  EXPECT_THAT(error_of(bulk), HasSubstr("Kiln/Material/\"Lame Lambda\" = -3e+10 at T = 700 K: "
                                        "gives the bulk modulus lambda + 2G/3 = -1e+10 Pa"));

  Teuchos::ParameterList k;
  k.set("Conductivity", property_expression("240 - 0.3*T"));
  EXPECT_THAT(error_of(k), HasSubstr("test.xml: Kiln/Material/Conductivity/\"Expression\": = "
                                     "\"240 - 0.3*T\" is -60 at T = 1000 K"));
}

TEST(Material, ConductivityAsAPlainNumber)
{
  Teuchos::ParameterList user;
  user.set("Conductivity", 45.0);
  const kiln::Material m = make(user);
  EXPECT_EQ(m.conductivity().value(1000.0), 45.0);
  EXPECT_TRUE(m.is_constant());
}
