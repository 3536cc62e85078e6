#include "physics/materials/material.hpp"

#include "physics/materials/constitutive_models.hpp"
#include "physics/materials/linear_elastic_model.hpp"
#include "physics/materials/material_elastic_model.hpp"

#include "base/errors.hpp"
#include "base/log.hpp"
#include "base/parameters.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <stdexcept>

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
  const double T_ref = aluminium.reference_temperature();
  const PropertyRange positive = PropertyRange::positive();
  const std::string of_T = "; a number, or a sublist for a table or a formula in T "
                           "(doc/materials.md)";
  Teuchos::ParameterList p("Material");
  set_number_or_sublist(
      p, "Density", "rho, must be > 0 [kg/m^3]" + of_T,
      TemperatureFunction::valid_parameters(aluminium.density(T_ref), "rho [kg/m^3]", positive));
  set_number_or_sublist(p, "Specific Heat", "c, must be > 0 [J/(kg K)]" + of_T,
                        TemperatureFunction::valid_parameters(aluminium.specific_heat(T_ref),
                                                              "c [J/(kg K)]", positive));
  set_number_or_sublist(p, "Conductivity",
                        "thermal conductivity k(T), must be > 0 [W/(m K)]" + of_T +
                            " and doc/heat.md",
                        TemperatureFunction::valid_parameters(aluminium.conductivity().value(T_ref),
                                                              "k [W/(m K)]", positive));
  set_number_or_sublist(
      p, youngs_modulus_name,
      "E, must be > 0; give it with \"Poisson's Ratio\", or give neither and the elasticity "
      "comes from \"Lame Lambda\" and \"Shear Modulus\" [Pa]" +
          of_T,
      TemperatureFunction::valid_parameters(aluminium.youngs_modulus(T_ref), "E [Pa]", positive));
  set_number_or_sublist(p, poissons_ratio_name,
                        "nu, must be > -1 and < 0.5; give it with \"Young's Modulus\" [-]" + of_T,
                        TemperatureFunction::valid_parameters(aluminium.poissons_ratio(T_ref),
                                                              "nu [-]",
                                                              PropertyRange::open(-1.0, 0.5)));
  set_number_or_sublist(
      p, lame_lambda_name,
      "lambda, the first Lame constant; give it with \"Shear Modulus\", not with \"Young's "
      "Modulus\" and \"Poisson's Ratio\"; the bulk modulus lambda + 2G/3 must be > 0 [Pa]" +
          of_T,
      TemperatureFunction::valid_parameters(aluminium.lame_lambda(T_ref), "lambda [Pa]",
                                            PropertyRange::any()));
  set_number_or_sublist(
      p, shear_modulus_name,
      "G (the second Lame constant mu), must be > 0; give it with \"Lame Lambda\" [Pa]" + of_T,
      TemperatureFunction::valid_parameters(aluminium.shear_modulus(T_ref), "G [Pa]", positive));
  set_number_or_sublist(p, "Thermal Expansion",
                        "alpha, the secant linear thermal expansion coefficient from the "
                        "Reference Temperature: the thermal strain is alpha(T) (T - T_ref); "
                        "must be >= 0 [1/K]" +
                            of_T,
                        TemperatureFunction::valid_parameters(aluminium.thermal_expansion(T_ref),
                                                              "alpha [1/K]",
                                                              PropertyRange::nonnegative()));
  p.set("Reference Temperature", T_ref,
        "T_ref, the stress-free temperature: the thermal strain is alpha(T) (T - T_ref); a "
        "number, must be > 0 [K]",
        positive_double_validator());
  p.set("Model", constitutive_model_parameters(),
        "The mechanical constitutive model (doc/materials.md): \"Type\" and that model's "
        "parameters; its elastic constants, when not given here, are the material's. Without "
        "it, linear elasticity from the material's constants");
  return p;
}

Material::Material(const Teuchos::ParameterList &p, const std::string &where)
    : density_(p.sublist("Density"), where + "/Density", PropertyRange::positive()),
      specific_heat_(p.sublist("Specific Heat"), where + "/Specific Heat",
                     PropertyRange::positive()),
      conductivity_(p.sublist("Conductivity"), where + "/Conductivity", PropertyRange::positive()),
      thermal_expansion_(p.sublist("Thermal Expansion"), where + "/Thermal Expansion",
                         PropertyRange::nonnegative()),
      reference_temperature_(p.get<double>("Reference Temperature")),
      model_given_(given_in_input(p, "Model")), where_(where)
{
  set_elasticity(p, where);
  if (model_given_)
  {
    model_ = p.sublist("Model");
    mechanical_model(); // its errors now, with the material's others
  }
}

bool Material::elastically_constant() const
{
  return first_.is_constant() && second_.is_constant() && thermal_expansion_.is_constant();
}

std::shared_ptr<const ConstitutiveModel> Material::mechanical_model() const
{
  const double T_ref = reference_temperature_;
  if (!model_given_)
  {
    if (elastically_constant())
      return std::make_shared<LinearElasticModel>(lame_lambda(T_ref), shear_modulus(T_ref),
                                                  thermal_expansion(T_ref), T_ref);
    return std::make_shared<MaterialElasticModel>(*this);
  }
  Teuchos::ParameterList p = model_;
  const std::pair<std::string, double> own[] = {{"Lame Lambda", lame_lambda(T_ref)},
                                                {"Shear Modulus", shear_modulus(T_ref)},
                                                {"Thermal Expansion", thermal_expansion(T_ref)},
                                                {"Reference Temperature", T_ref}};
  for (const auto &[name, value] : own)
    if (!given_in_input(model_, name))
    {
      KILN_CHECK_INPUT(elastically_constant(), where_ + "/Model/\"" + name + "\"",
                       "is not given, so it would be the material's, but the material's "
                       "elastic constants or expansion depend on T, which the \""
                           << p.get<std::string>("Type")
                           << "\" model does not take; give it in Model, or give the "
                              "material's elastic constants and expansion as numbers");
      p.set(name, value);
    }
  return create_constitutive_model(p, where_, "Model");
}

/// Reads whichever pair of elastic constants the input gives, (E, nu) or (lambda, G), and
/// checks it at every temperature its functions were checked at.
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

  given_E_nu_ = given_E;
  const std::string first = given_E ? youngs_modulus_name : lame_lambda_name;
  const std::string second = given_E ? poissons_ratio_name : shear_modulus_name;
  first_ = TemperatureFunction(p.sublist(first), where + "/" + first,
                               given_E ? PropertyRange::positive() : PropertyRange::any());
  second_ = TemperatureFunction(p.sublist(second), where + "/" + second,
                                given_E ? PropertyRange::any() : PropertyRange::positive());
  if (given_E)
    check_poissons_ratio(where);
  else
    check_bulk_modulus(where);
  warn_if_nearly_incompressible(where);
}

std::vector<double> Material::elastic_check_temperatures() const
{
  std::vector<double> T = first_.checked_temperatures();
  T.insert(T.end(), second_.checked_temperatures().begin(), second_.checked_temperatures().end());
  std::sort(T.begin(), T.end());
  T.erase(std::unique(T.begin(), T.end()), T.end());
  if (T.empty())
    T.push_back(reference_temperature_);
  return T;
}

namespace
{
/// "" for a constant property, else " at T = 400 K": where a value was found.
std::string at_temperature(const bool constant, const double T)
{
  std::ostringstream s;
  if (!constant)
    s << " at T = " << T << " K";
  return s.str();
}
} // namespace

/// nu in (-1, 0.5) at each checked temperature: nu is linear between a table's points (so
/// checking them covers the table), and E > 0 is checked by its own range.
void Material::check_poissons_ratio(const std::string &where) const
{
  for (const double T : elastic_check_temperatures())
  {
    const double nu = second_.value(T);
    KILN_CHECK_INPUT(nu > -1.0 && nu < 0.5,
                     with_value(where, poissons_ratio_name, nu) +
                         at_temperature(second_.is_constant(), T),
                     "must be > -1 and < 0.5"
                         << (nu >= 0.5 ? "; 0.5 is an incompressible material, which the "
                                         "displacement formulation cannot represent: give a "
                                         "value below 0.5"
                                       : ""));
  }
}

/// lambda + 2G/3 > 0 at each checked temperature, the union of both tables' points: between
/// them both are linear, so the bulk modulus is too.
void Material::check_bulk_modulus(const std::string &where) const
{
  const bool constant = first_.is_constant() && second_.is_constant();
  for (const double T : elastic_check_temperatures())
  {
    const double lambda = first_.value(T);
    const double G = second_.value(T);
    const double bulk_modulus = lambda + 2.0 * G / 3.0;
    KILN_CHECK_INPUT(bulk_modulus > 0.0,
                     with_value(where, lame_lambda_name, lambda) + at_temperature(constant, T),
                     "gives the bulk modulus lambda + 2G/3 = "
                         << bulk_modulus << " Pa with " << quoted(shear_modulus_name) << " = " << G
                         << " Pa, but it must be > 0: give " << quoted(lame_lambda_name) << " > "
                         << -2.0 * G / 3.0 << " Pa");
  }
}

/// Valid but nearly incompressible (nu > 0.49, lambda > 49 G) at some checked temperature:
/// the run goes on, so say once what will happen and what to do.
void Material::warn_if_nearly_incompressible(const std::string &where) const
{
  for (const double T : elastic_check_temperatures())
  {
    const double nu = poissons_ratio(T);
    if (!(nu > max_compressible_poissons_ratio))
      continue;
    const std::string &name = given_E_nu_ ? poissons_ratio_name : lame_lambda_name;
    const bool constant = first_.is_constant() && second_.is_constant();
    std::ostringstream s;
    s << std::setprecision(12) << where << "/" << quoted(name) << " = "
      << (given_E_nu_ ? second_ : first_).value(T) << at_temperature(constant, T)
      << " makes the material nearly incompressible (nu = " << nu
      << ", lambda/G = " << std::setprecision(3) << lame_lambda(T) / shear_modulus(T)
      << "): the displacement formulation locks (cells too stiff in bending, the pressure "
         "oscillates) and the linear solver converges slowly or stops at its iteration limit; "
         "Kiln has no mixed formulation for such materials: unless the incompressibility "
         "matters, give \"Poisson's Ratio\" <= "
      << max_compressible_poissons_ratio << " (metals have about 0.3)";
    warn_once(s.str());
    return;
  }
}

double Material::d_heat_capacity_d_T(const double T) const
{
  return density_.derivative(T) * specific_heat_.value(T) +
         density_.value(T) * specific_heat_.derivative(T);
}

double Material::lame_lambda(const double T) const
{
  if (!given_E_nu_)
    return first_.value(T);
  const double E = first_.value(T);
  const double nu = second_.value(T);
  return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
}

/// From (E, nu): lambda = E g(nu), g = nu / D, D = (1 + nu)(1 - 2 nu) = 1 - nu - 2 nu^2, so
/// g' = (D - nu D') / D^2 = (1 + 2 nu^2) / D^2 and lambda' = E' g + E g' nu'.
double Material::d_lame_lambda_d_T(const double T) const
{
  if (!given_E_nu_)
    return first_.derivative(T);
  const double E = first_.value(T);
  const double nu = second_.value(T);
  const double D = (1.0 + nu) * (1.0 - 2.0 * nu);
  return first_.derivative(T) * nu / D +
         E * (1.0 + 2.0 * nu * nu) / (D * D) * second_.derivative(T);
}

double Material::shear_modulus(const double T) const
{
  return given_E_nu_ ? first_.value(T) / (2.0 * (1.0 + second_.value(T))) : second_.value(T);
}

/// From (E, nu): G = E / (2 (1 + nu)), G' = E' / (2 (1 + nu)) - E nu' / (2 (1 + nu)^2).
double Material::d_shear_modulus_d_T(const double T) const
{
  if (!given_E_nu_)
    return second_.derivative(T);
  const double E = first_.value(T);
  const double one_plus_nu = 1.0 + second_.value(T);
  return first_.derivative(T) / (2.0 * one_plus_nu) -
         E * second_.derivative(T) / (2.0 * one_plus_nu * one_plus_nu);
}

double Material::youngs_modulus(const double T) const
{
  if (given_E_nu_)
    return first_.value(T);
  const double lambda = first_.value(T);
  const double G = second_.value(T);
  return G * (3.0 * lambda + 2.0 * G) / (lambda + G);
}

double Material::poissons_ratio(const double T) const
{
  if (given_E_nu_)
    return second_.value(T);
  const double lambda = first_.value(T);
  return lambda / (2.0 * (lambda + second_.value(T)));
}

double Material::thermal_strain(const double T) const
{
  return thermal_expansion_.value(T) * (T - reference_temperature_);
}

double Material::d_thermal_strain_d_T(const double T) const
{
  return thermal_expansion_.derivative(T) * (T - reference_temperature_) +
         thermal_expansion_.value(T);
}

std::vector<std::string> Material::temperature_dependent_properties() const
{
  std::vector<std::string> names;
  const auto add_if_varying = [&names](const TemperatureFunction &f, const std::string &name)
  {
    if (!f.is_constant())
      names.push_back(name);
  };
  add_if_varying(density_, "Density");
  add_if_varying(specific_heat_, "Specific Heat");
  add_if_varying(conductivity_, "Conductivity");
  add_if_varying(first_, given_E_nu_ ? youngs_modulus_name : lame_lambda_name);
  add_if_varying(second_, given_E_nu_ ? poissons_ratio_name : shear_modulus_name);
  add_if_varying(thermal_expansion_, "Thermal Expansion");
  return names;
}

namespace
{
/// The value of a constant property; a varying one is a caller's bug.
double constant_value(const TemperatureFunction &f, const char *name)
{
  if (!f.is_constant())
    throw std::logic_error(std::string("Material: ") + name +
                           " depends on T; ask for its value at a temperature");
  return f.value(0.0);
}

void require_constant(const TemperatureFunction &first, const TemperatureFunction &second)
{
  constant_value(first, "the elastic constants");
  constant_value(second, "the elastic constants");
}
} // namespace

double Material::density() const
{
  return constant_value(density_, "the density");
}

double Material::specific_heat() const
{
  return constant_value(specific_heat_, "the specific heat");
}

double Material::lame_lambda() const
{
  require_constant(first_, second_);
  return lame_lambda(reference_temperature_);
}

double Material::shear_modulus() const
{
  require_constant(first_, second_);
  return shear_modulus(reference_temperature_);
}

double Material::youngs_modulus() const
{
  require_constant(first_, second_);
  return youngs_modulus(reference_temperature_);
}

double Material::poissons_ratio() const
{
  require_constant(first_, second_);
  return poissons_ratio(reference_temperature_);
}

double Material::thermal_expansion() const
{
  return constant_value(thermal_expansion_, "the expansion coefficient");
}
} // namespace kiln
