#pragma once
#include "physics/materials/constitutive_model.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>

namespace kiln
{
/// Isotropic linear thermo-elasticity with constant constants (doc/materials.md):
///   σ = λ tr(ε − ε_th) I + 2G (ε − ε_th),   ε_th = α (T − T_ref) I,
///   ∂σ/∂ε = λ I⊗I + 2G 𝕀 (tangent[3][3] = 2G: tensor shear strains),
///   ∂σ/∂T = −(3λ + 2G) α I.
/// No state. The viscoplastic models use it for their elastic part (elastic_stress() etc.).
class LinearElasticModel final : public ConstitutiveModel
{
public:
  static std::string description();
  static Teuchos::ParameterList valid_parameters();
  /// From a validated list; `where` names it in messages ("in.xml: Kiln/Materials/steel").
  LinearElasticModel(const Teuchos::ParameterList &params, const std::string &where);
  LinearElasticModel(double lambda, double G, double alpha, double T_ref);

  void evaluate(const PointInput &in, const double *old_state, double *new_state,
                PointResponse &out) const override;
  bool constant_linear() const override { return true; }

  double lame_lambda() const { return lambda_; }
  double shear_modulus() const { return G_; }
  double bulk_modulus() const { return lambda_ + 2.0 * G_ / 3.0; }
  double thermal_expansion() const { return alpha_; }
  double reference_temperature() const { return T_ref_; }
  double thermal_strain(double temperature) const override
  {
    return alpha_ * (temperature - T_ref_);
  }

  /// ε − ε_th at temperature T.
  Voigt mechanical_strain(const Voigt &strain, double T) const;
  /// λ tr(ε_e) I + 2G ε_e.
  Voigt elastic_stress(const Voigt &elastic_strain) const;
  /// λ I⊗I + 2G 𝕀 in Kiln's Voigt convention.
  VoigtMatrix elastic_tangent() const;
  /// The same in isotropic form: λ_t = λ, μ_t = G, γ = 0.
  IsotropicTangent isotropic_tangent() const;
  /// −(3λ + 2G) α I [Pa/K].
  Voigt thermal_stress_derivative() const;

private:
  double lambda_;
  double G_;
  double alpha_;
  double T_ref_;
};
} // namespace kiln
