#pragma once
/// The "Mechanics" block: quasi-static thermo-elasticity's kernel and conditions.
#include "discretization/dof_manager.hpp"
#include "mesh/mesh.hpp"
#include "physics/boundary_condition.hpp"
#include "physics/materials/material.hpp"
#include "physics/materials/material_map.hpp"
#include "physics/mechanics/block_elasticity_kernel.hpp"
#include "physics/mechanics/elasticity_kernel.hpp"
#include "physics/mechanics/gravity_kernel.hpp"

#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <string>
#include <vector>

namespace kiln
{
/// Small-strain thermo-elasticity (doc/mechanics.md): the elasticity kernel of every cell with
/// the body force rho g + f (a material's rho(T) g, if its density depends on T and Gravity is
/// not zero, in a GravityKernel of its own), and the mechanical boundary conditions
/// (mechanical_conditions()). The "Contact" sublist is the interface's (interface_parameters()).
class MechanicalPhysics
{
public:
  /// The "Mechanics" block: Body Force, Gravity, Boundary Conditions, Contact.
  static Teuchos::ParameterList valid_parameters();

  /// `mechanics` has been validated against valid_parameters(); `where` names it ("in.xml:
  /// Kiln/Mechanics").
  /// With `materials`, each block's cells take its material's mechanical_model() (and body
  /// force); without, every cell `material`'s constants.
  MechanicalPhysics(const Teuchos::ParameterList &mechanics, const Material &material,
                    const Mesh &mesh, const InteriorFaceCheck &interior, const std::string &where,
                    const MaterialMap *materials = nullptr);

  /// The kernel of the first material (of every cell with one material).
  const ElasticityKernel &elasticity() const { return elasticity_.kernels().front(); }
  /// The kernels of each block.
  const BlockElasticityKernel &block_elasticity() const { return elasticity_; }
  BlockElasticityKernel &block_elasticity() { return elasticity_; }
  /// The kernels of every cell (a new cell kernel of the mechanics is added here).
  std::vector<const CellKernel *> cell_kernels() const;
  const std::vector<std::unique_ptr<BoundaryCondition>> &conditions() const { return conditions_; }

private:
  BlockElasticityKernel elasticity_;
  /// rho(T) g of the materials whose density depends on T (null: none, or no gravity).
  std::unique_ptr<GravityKernel> gravity_;
  std::vector<std::unique_ptr<BoundaryCondition>> conditions_;
};
} // namespace kiln
