#pragma once
/// The material of the body: the properties every physics kernel reads.
#include "physics/materials/conductivity_model.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>

namespace kiln
{
/// One material for the whole mesh (SI units). Defaults are the contact-box spec's
/// aluminium, so that a deck that leaves a property out is still physical; the
/// input reference lists them.
///
/// Isotropic linear thermo-elasticity: the input gives one pair of elastic constants,
/// (E, nu) or (lambda, G); the other pair follows from
///   lambda = E nu / ((1 + nu)(1 - 2 nu)),  G = E / (2 (1 + nu)),
///   E = G (3 lambda + 2 G) / (lambda + G),  nu = lambda / (2 (lambda + G)).
/// The thermal strain is alpha (T - T_ref) I, zero at the stress-free temperature T_ref.
class Material
{
public:
  static Teuchos::ParameterList valid_parameters();
  /// `validated_params` has been through kiln::validated() against valid_parameters();
  /// `where` names the block in messages ("in.xml: Kiln/Material").
  Material(const Teuchos::ParameterList &validated_params, const std::string &where);
  /// Aluminium of the spec.
  Material() = default;

  double density() const { return density_; }             ///< rho [kg/m^3]
  double specific_heat() const { return specific_heat_; } ///< c [J/(kg K)]
  /// rho c [J/(m^3 K)]
  double heat_capacity() const { return density_ * specific_heat_; }
  const ConductivityModel &conductivity() const { return conductivity_; }

  double lame_lambda() const { return lame_lambda_; }       ///< lambda [Pa]
  double shear_modulus() const { return shear_modulus_; }   ///< G (Lame mu) [Pa]
  double youngs_modulus() const { return youngs_modulus_; } ///< E [Pa]
  double poissons_ratio() const { return poissons_ratio_; } ///< nu [-]
  /// alpha, the linear thermal expansion coefficient [1/K]
  double thermal_expansion() const { return thermal_expansion_; }
  /// T_ref, the stress-free temperature [K]
  double reference_temperature() const { return reference_temperature_; }

private:
  static double youngs_modulus_of(const double lambda, const double G)
  {
    return G * (3.0 * lambda + 2.0 * G) / (lambda + G);
  }
  static double poissons_ratio_of(const double lambda, const double G)
  {
    return lambda / (2.0 * (lambda + G));
  }
  void set_elasticity(const Teuchos::ParameterList &p, const std::string &where);
  /// Above this nu (lambda > 49 G) a valid material is nearly incompressible: warn.
  static constexpr double max_compressible_poissons_ratio = 0.49;
  void warn_if_nearly_incompressible(const std::string &where, const std::string &name,
                                     double value) const;

  double density_ = 2.7e3;
  double specific_heat_ = 9.0e2;
  ConductivityModel conductivity_ = ConductivityModel::constant(2.4e2);
  double lame_lambda_ = 5.2e10;
  double shear_modulus_ = 2.6e10;
  double youngs_modulus_ = youngs_modulus_of(lame_lambda_, shear_modulus_);
  double poissons_ratio_ = poissons_ratio_of(lame_lambda_, shear_modulus_);
  double thermal_expansion_ = 2.2e-5;
  double reference_temperature_ = 298.0;
};
} // namespace kiln
