#pragma once
/// The "Mechanics" block: quasi-static thermo-elasticity's kernel and conditions.
#include "discretization/dof_manager.hpp"
#include "mesh/mesh.hpp"
#include "physics/boundary_condition.hpp"
#include "physics/materials/material.hpp"
#include "physics/mechanics/elasticity_kernel.hpp"

#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <string>
#include <vector>

namespace kiln
{
/// Small-strain thermo-elasticity (doc/mechanics.md): the elasticity kernel of every cell with
/// the body force rho g + f, and the mechanical boundary conditions
/// (mechanical_conditions()). The "Contact" sublist is the interface's (interface_parameters()).
class MechanicalPhysics
{
public:
  /// The "Mechanics" block: Body Force, Gravity, Boundary Conditions, Contact.
  static Teuchos::ParameterList valid_parameters();

  /// `mechanics` has been validated against valid_parameters(); `where` names it ("in.xml:
  /// Kiln/Mechanics").
  MechanicalPhysics(const Teuchos::ParameterList &mechanics, const Material &material,
                    const Mesh &mesh, const InteriorFaceCheck &interior, const std::string &where);

  const ElasticityKernel &elasticity() const { return elasticity_; }
  /// The kernels of every cell (a new cell kernel of the mechanics is added here).
  std::vector<const CellKernel *> cell_kernels() const { return {&elasticity_}; }
  /// lambda + 2G [Pa], the scale of the force rows.
  double modulus() const { return elasticity_.lambda() + 2.0 * elasticity_.shear_modulus(); }
  const std::vector<std::unique_ptr<BoundaryCondition>> &conditions() const { return conditions_; }

private:
  ElasticityKernel elasticity_;
  std::vector<std::unique_ptr<BoundaryCondition>> conditions_;
};
} // namespace kiln
