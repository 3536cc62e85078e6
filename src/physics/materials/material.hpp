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

private:
  double density_ = 2.7e3;
  double specific_heat_ = 9.0e2;
  ConductivityModel conductivity_ = ConductivityModel::constant(2.4e2);
};
} // namespace kiln
