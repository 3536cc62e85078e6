#pragma once
/// The "Thermal" block: heat conduction's kernels and conditions.
#include "discretization/dof_manager.hpp"
#include "mesh/mesh.hpp"
#include "physics/boundary_condition.hpp"
#include "physics/heat/block_heat_conduction_kernel.hpp"
#include "physics/kernel.hpp"
#include "physics/materials/material.hpp"
#include "physics/materials/material_map.hpp"

#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace kiln
{
/// Transient heat conduction (doc/heat.md): the conduction kernel of every cell (each block's
/// material's rho(T), c(T) and k(T)), the
/// conductance across the gap (constant or following the contact state), the thermal
/// boundary conditions (thermal_conditions()) and the initial temperature.
class ThermalPhysics
{
public:
  /// The "Thermal" block: Initial Temperature, Gap Conductance, Boundary Conditions.
  static Teuchos::ParameterList valid_parameters();

  /// `thermal` has been validated against valid_parameters(); `where` names it ("in.xml:
  /// Kiln/Thermal"). Checks the block against the mesh and the layout. With `materials`, each
  /// block's cells take its material; without, every cell takes `material`.
  ThermalPhysics(const Teuchos::ParameterList &thermal, const Material &material, const Mesh &mesh,
                 const DofLayout &layout, const InteriorFaceCheck &interior,
                 const std::string &where, const MaterialMap *materials = nullptr);

  /// The initial temperature [K] where no formula is given (Initial Temperature).
  double initial_temperature() const { return initial_temperature_; }
  /// The initial temperature at x [m] (reference position) [K]: Initial Temperature, or the
  /// formula of Initial Temperature Expression.
  double initial_temperature(const Point &x) const
  {
    return initial_field_ ? (*initial_field_)(x[0], x[1], x[2], 0.0) : initial_temperature_;
  }
  /// The largest k at the initial temperature over the materials [W/(m K)], the scale of the
  /// heat rows.
  double conductivity_scale() const;
  const BlockHeatConductionKernel &conduction() const { return conduction_; }
  /// Whether a material's rho c depends on T: the capacity term reads the past temperatures.
  bool needs_temperature_history() const { return conduction_.needs_temperature_history(); }
  /// The kernels of every cell (a new cell kernel of the heat equation is added here).
  std::vector<const CellKernel *> cell_kernels() const { return {&conduction_}; }
  /// The terms across the gap, or nullptr if the mesh has none.
  const InterfaceKernel *gap_kernel() const { return gap_.get(); }
  const std::vector<std::unique_ptr<BoundaryCondition>> &conditions() const { return conditions_; }

private:
  double initial_temperature_;
  std::shared_ptr<const Expression> initial_field_; ///< Initial Temperature Expression, or none
  BlockHeatConductionKernel conduction_;
  std::unique_ptr<InterfaceKernel> gap_;
  std::vector<std::unique_ptr<BoundaryCondition>> conditions_;
};
} // namespace kiln
