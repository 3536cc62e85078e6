#pragma once
/// A material: the properties every physics kernel reads, each a function of temperature.
#include "physics/materials/conductivity_model.hpp"
#include "physics/materials/constitutive_model.hpp"
#include "physics/materials/enthalpy.hpp"
#include "physics/materials/temperature_function.hpp"

#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <string>
#include <vector>

namespace kiln
{
/// One material (SI units; doc/materials.md, "Properties"). Defaults are the contact-box
/// spec's aluminium, so that a deck that leaves a property out is still physical; the input
/// reference lists them. Every property but the reference temperature is a
/// TemperatureFunction: a number, a table in T or a formula in T.
///
/// Isotropic linear thermo-elasticity: the input gives one pair of elastic constants,
/// (E, nu) or (lambda, G), each a function of T; the other pair follows at each T from
///   lambda = E nu / ((1 + nu)(1 - 2 nu)),  G = E / (2 (1 + nu)),
///   E = G (3 lambda + 2 G) / (lambda + G),  nu = lambda / (2 (lambda + G)).
/// Thermal strain: the secant (mean) definition from the stress-free temperature T_ref,
///   eps_th(T) = alpha(T) (T - T_ref) I,  d eps_th/dT = (alpha'(T) (T - T_ref) + alpha(T)) I,
/// alpha the secant coefficient measured from T_ref (as Truchas, and MOOSE's "mean" option);
/// not the instantaneous one (eps_th = integral of alpha from T_ref to T).
class Material
{
public:
  static Teuchos::ParameterList valid_parameters();
  /// `validated_params` has been through kiln::validated() against valid_parameters() (it may
  /// hold other entries, such as a Materials entry's "Blocks"); `where` names the block in
  /// messages ("in.xml: Kiln/Material").
  Material(const Teuchos::ParameterList &validated_params, const std::string &where);
  /// Aluminium of the spec.
  Material() = default;

  /// @name Properties at a temperature T [K]
  /// @{
  double density(double T) const { return density_.value(T); } ///< rho [kg/m^3]
  /// rho(T) itself (its derivative for the Jacobian of the body force rho(T) g).
  const TemperatureFunction &density_function() const { return density_; }
  double specific_heat(double T) const { return specific_heat_.value(T); } ///< c [J/(kg K)]
  /// rho c [J/(m^3 K)]
  double heat_capacity(double T) const { return density_.value(T) * specific_heat_.value(T); }
  /// d(rho c)/dT [J/(m^3 K^2)]
  double d_heat_capacity_d_T(double T) const;
  /// H(T) = ∫ rho c dT [J/m^3], the heat equation's conserved quantity (doc/heat.md).
  Enthalpy enthalpy() const { return Enthalpy(density_, specific_heat_); }
  /// k(T) [W/(m K)] and its derivative.
  const ConductivityModel &conductivity() const { return conductivity_; }
  double lame_lambda(double T) const;         ///< lambda [Pa]
  double d_lame_lambda_d_T(double T) const;   ///< d lambda/dT [Pa/K]
  double shear_modulus(double T) const;       ///< G (Lame mu) [Pa]
  double d_shear_modulus_d_T(double T) const; ///< dG/dT [Pa/K]
  double youngs_modulus(double T) const;      ///< E [Pa]
  double poissons_ratio(double T) const;      ///< nu [-]
  /// alpha, the secant linear thermal expansion coefficient from T_ref [1/K]
  double thermal_expansion(double T) const { return thermal_expansion_.value(T); }
  /// eps_th = alpha(T) (T - T_ref), the thermal strain in each direction [-]
  double thermal_strain(double T) const;
  /// d eps_th/dT = alpha'(T) (T - T_ref) + alpha(T) [1/K]
  double d_thermal_strain_d_T(double T) const;
  /// @}

  /// T_ref, the stress-free temperature [K] (a number, not a function of T: the temperature
  /// the secant coefficient is measured from).
  double reference_temperature() const { return reference_temperature_; }

  /// The mechanical constitutive model of the material (its "Model" sublist, doc/materials.md):
  /// without one, linear elasticity from the material's constants (a LinearElasticModel if
  /// they are numbers, the kernels' fast path; else a MaterialElasticModel of E(T), nu(T),
  /// alpha(T)); with one, the registry's model of its "Type", whose elastic constants not
  /// given in it are the material's (which must then be numbers: an InputError otherwise).
  std::shared_ptr<const ConstitutiveModel> mechanical_model() const;
  /// Whether the elastic constants and the expansion do not depend on T.
  bool elastically_constant() const;

  /// Whether no property depends on T.
  bool is_constant() const { return temperature_dependent_properties().empty(); }
  /// The input names of the properties that depend on T ("Young's Modulus", ...), in input
  /// order; the conductivity is "Conductivity".
  std::vector<std::string> temperature_dependent_properties() const;

  /// @name Values of properties that do not depend on T
  /// For the kernels that take constants today. Each throws std::logic_error (a bug: the
  /// caller must check is_constant() or temperature_dependent_properties()) if its property
  /// depends on T.
  /// @{
  double density() const;
  double specific_heat() const;
  double heat_capacity() const { return density() * specific_heat(); }
  double lame_lambda() const;
  double shear_modulus() const;
  double youngs_modulus() const;
  double poissons_ratio() const;
  double thermal_expansion() const;
  /// @}

private:
  void set_elasticity(const Teuchos::ParameterList &p, const std::string &where);
  void check_poissons_ratio(const std::string &where) const;
  void check_bulk_modulus(const std::string &where) const;
  /// The temperatures at which the pair (lambda, G) or (E, nu) was checked: the union of the
  /// two functions' checked temperatures, or {T_ref} if both are constant.
  std::vector<double> elastic_check_temperatures() const;
  /// Above this nu (lambda > 49 G) a valid material is nearly incompressible: warn.
  static constexpr double max_compressible_poissons_ratio = 0.49;
  void warn_if_nearly_incompressible(const std::string &where) const;

  TemperatureFunction density_ = TemperatureFunction::constant(2.7e3);
  TemperatureFunction specific_heat_ = TemperatureFunction::constant(9.0e2);
  ConductivityModel conductivity_ = ConductivityModel::constant(2.4e2);
  /// true: first_ = E, second_ = nu; false: first_ = lambda, second_ = G.
  bool given_E_nu_ = false;
  TemperatureFunction first_ = TemperatureFunction::constant(5.2e10);
  TemperatureFunction second_ = TemperatureFunction::constant(2.6e10);
  TemperatureFunction thermal_expansion_ = TemperatureFunction::constant(2.2e-5);
  double reference_temperature_ = 298.0;
  /// The "Model" sublist as validated, whether the input gave it, and the material's place in
  /// messages.
  Teuchos::ParameterList model_;
  bool model_given_ = false;
  std::string where_;
};
} // namespace kiln
