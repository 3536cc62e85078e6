#pragma once
#include "physics/materials/constitutive_model.hpp"
#include "physics/materials/material.hpp"

namespace kiln
{
/// Isotropic linear thermo-elasticity with a Material's temperature-dependent constants
/// (doc/materials.md): at the point's T,
///   σ = λ(T) tr(ε − ε_th) I + 2G(T) (ε − ε_th),   ε_th = α(T) (T − T_ref) I (secant),
///   ∂σ/∂ε = λ(T) I⊗I + 2G(T) 𝕀,
///   ∂σ/∂T = λ'(T) tr(ε − ε_th) I + 2G'(T) (ε − ε_th) − (3λ + 2G) ε_th'(T) I.
/// No state; not constant_linear() (a material whose elastic constants are numbers uses
/// LinearElasticModel, the kernels' fast path).
class MaterialElasticModel final : public ConstitutiveModel
{
public:
  explicit MaterialElasticModel(const Material &material) : material_(material) {}
  double thermal_strain(double temperature) const override;
  void evaluate(const PointInput &in, const double *old_state, double *new_state,
                PointResponse &out) const override;

private:
  Material material_;
};
} // namespace kiln
