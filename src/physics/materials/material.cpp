#include "physics/materials/material.hpp"

#include "base/errors.hpp"
#include "base/log.hpp"
#include "base/parameters.hpp"

#include <iomanip>
#include <sstream>

namespace kiln
{
namespace
{
const std::string youngs_modulus_name = "Young's Modulus";
const std::string poissons_ratio_name = "Poisson's Ratio";
const std::string lame_lambda_name = "Lame Lambda";
const std::string shear_modulus_name = "Shear Modulus";

std::string quoted(const std::string &name)
{
  return "\"" + name + "\"";
}

/// `where/"name" = value`, the way a message names a rejected value.
std::string with_value(const std::string &where, const std::string &name, const double value)
{
  std::ostringstream s;
  s << where << "/" << quoted(name) << " = " << value;
  return s.str();
}
} // namespace

Teuchos::ParameterList Material::valid_parameters()
{
  const Material aluminium;
  Teuchos::ParameterList p("Material");
  p.set("Density", aluminium.density(), "rho, must be > 0 [kg/m^3]", positive_double_validator());
  p.set("Specific Heat", aluminium.specific_heat(), "c, must be > 0 [J/(kg K)]",
        positive_double_validator());
  Teuchos::ParameterList k = ConductivityModel::valid_parameters();
  k.set("Value", 2.4e2, "k for Type \"Constant\", must be > 0 [W/(m K)]",
        positive_double_validator());
  p.sublist("Conductivity", false,
            "thermal conductivity k(T), constant or a table in T [W/(m K)]; see doc/heat.md")
      .setParameters(k);
  p.set(youngs_modulus_name, aluminium.youngs_modulus(),
        "E, must be > 0; give it with \"Poisson's Ratio\", or give neither and the elasticity "
        "comes from \"Lame Lambda\" and \"Shear Modulus\" [Pa]",
        positive_double_validator());
  p.set(poissons_ratio_name, aluminium.poissons_ratio(),
        "nu, must be > -1 and < 0.5; give it with \"Young's Modulus\" [-]");
  p.set(lame_lambda_name, aluminium.lame_lambda(),
        "lambda, the first Lame constant; give it with \"Shear Modulus\", not with \"Young's "
        "Modulus\" and \"Poisson's Ratio\"; the bulk modulus lambda + 2G/3 must be > 0 [Pa]");
  p.set(shear_modulus_name, aluminium.shear_modulus(),
        "G (the second Lame constant mu), must be > 0; give it with \"Lame Lambda\" [Pa]",
        positive_double_validator());
  p.set("Thermal Expansion", aluminium.thermal_expansion(),
        "alpha, the linear thermal expansion coefficient, must be >= 0 [1/K]",
        nonnegative_double_validator());
  p.set("Reference Temperature", aluminium.reference_temperature(),
        "T_ref, the stress-free temperature: the thermal strain is alpha (T - T_ref); must be > "
        "0 [K]",
        positive_double_validator());
  return p;
}

Material::Material(const Teuchos::ParameterList &p, const std::string &where)
    : density_(p.get<double>("Density")), specific_heat_(p.get<double>("Specific Heat")),
      conductivity_(p.sublist("Conductivity"), where + "/Conductivity"),
      thermal_expansion_(p.get<double>("Thermal Expansion")),
      reference_temperature_(p.get<double>("Reference Temperature"))
{
  set_elasticity(p, where);
}

/// Reads whichever pair of elastic constants the input gives, (E, nu) or (lambda, G),
/// checks it and computes the other pair.
void Material::set_elasticity(const Teuchos::ParameterList &p, const std::string &where)
{
  const std::string pairs = "give either " + quoted(youngs_modulus_name) + " and " +
                            quoted(poissons_ratio_name) + ", or " + quoted(lame_lambda_name) +
                            " and " + quoted(shear_modulus_name);
  const bool given_E = given_in_input(p, youngs_modulus_name);
  const bool given_nu = given_in_input(p, poissons_ratio_name);
  const bool given_lambda = given_in_input(p, lame_lambda_name);
  const bool given_G = given_in_input(p, shear_modulus_name);

  const std::string &first_of_E_nu = given_E ? youngs_modulus_name : poissons_ratio_name;
  const std::string &first_of_lambda_G = given_lambda ? lame_lambda_name : shear_modulus_name;
  KILN_CHECK_INPUT(!((given_E || given_nu) && (given_lambda || given_G)),
                   where + "/" + quoted(first_of_lambda_G),
                   "is given together with "
                       << quoted(first_of_E_nu)
                       << ", but the elastic constants are one pair: " << pairs << ", not both");
  KILN_CHECK_INPUT(given_E == given_nu, where + "/" + quoted(first_of_E_nu),
                   "is given without "
                       << quoted(given_E ? poissons_ratio_name : youngs_modulus_name)
                       << "; give both " << quoted(youngs_modulus_name) << " and "
                       << quoted(poissons_ratio_name) << ", or neither");
  KILN_CHECK_INPUT(given_lambda == given_G, where + "/" + quoted(first_of_lambda_G),
                   "is given without "
                       << quoted(given_lambda ? shear_modulus_name : lame_lambda_name)
                       << "; give both " << quoted(lame_lambda_name) << " and "
                       << quoted(shear_modulus_name) << ", or neither");

  if (given_E)
  {
    const double E = p.get<double>(youngs_modulus_name);
    const double nu = p.get<double>(poissons_ratio_name);
    KILN_CHECK_INPUT(nu > -1.0 && nu < 0.5, with_value(where, poissons_ratio_name, nu),
                     "must be > -1 and < 0.5"
                         << (nu >= 0.5 ? "; 0.5 is an incompressible material, which the "
                                         "displacement formulation cannot represent: give a "
                                         "value below 0.5"
                                       : ""));
    youngs_modulus_ = E;
    poissons_ratio_ = nu;
    lame_lambda_ = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    shear_modulus_ = E / (2.0 * (1.0 + nu));
  }
  else
  {
    const double lambda = p.get<double>(lame_lambda_name);
    const double G = p.get<double>(shear_modulus_name);
    const double bulk_modulus = lambda + 2.0 * G / 3.0;
    KILN_CHECK_INPUT(bulk_modulus > 0.0, with_value(where, lame_lambda_name, lambda),
                     "gives the bulk modulus lambda + 2G/3 = "
                         << bulk_modulus << " Pa with " << quoted(shear_modulus_name) << " = " << G
                         << " Pa, but it must be > 0: give " << quoted(lame_lambda_name) << " > "
                         << -2.0 * G / 3.0 << " Pa");
    lame_lambda_ = lambda;
    shear_modulus_ = G;
    youngs_modulus_ = youngs_modulus_of(lambda, G);
    poissons_ratio_ = poissons_ratio_of(lambda, G);
  }
  warn_if_nearly_incompressible(where, given_E ? poissons_ratio_name : lame_lambda_name,
                                given_E ? poissons_ratio_ : lame_lambda_);
}

/// Valid but nearly incompressible (nu > 0.49, lambda > 49 G): the run goes on, so say once
/// what will happen and what to do.
void Material::warn_if_nearly_incompressible(const std::string &where, const std::string &name,
                                             const double value) const
{
  if (!(poissons_ratio_ > max_compressible_poissons_ratio))
    return;
  std::ostringstream s;
  s << std::setprecision(12) << where << "/" << quoted(name) << " = " << value
    << " makes the material nearly incompressible (nu = " << poissons_ratio_
    << ", lambda/G = " << std::setprecision(3) << lame_lambda_ / shear_modulus_
    << "): the displacement formulation locks (cells too stiff in bending, the pressure "
       "oscillates) and the linear solver converges slowly or stops at its iteration limit; "
       "Kiln has no mixed formulation for such materials: unless the incompressibility "
       "matters, give \"Poisson's Ratio\" <= "
    << max_compressible_poissons_ratio << " (metals have about 0.3)";
  warn_once(s.str());
}
} // namespace kiln
