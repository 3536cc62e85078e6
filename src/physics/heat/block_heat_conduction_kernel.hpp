#pragma once
/// Heat conduction on a mesh with a material per element block.
#include "mesh/mesh.hpp"
#include "physics/heat/heat_conduction_kernel.hpp"
#include "physics/kernel.hpp"
#include "physics/kernel_of_block.hpp"

#include <map>
#include <vector>

namespace kiln
{
/// One HeatConductionKernel per material, each cell evaluated by its block's (mesh.block_id[c]),
/// as BlockElasticityKernel does for the mechanics: rho, c and k of each cell are its block's
/// material's. With one material every cell takes it directly (a constant material keeps the
/// kernel's constant path: HeatConductionKernel, rho c Tdot).
class BlockHeatConductionKernel final : public CellKernel
{
public:
  /// `kernels[i]` is material i's; `kernel_of_block` maps every block id of the mesh to one.
  BlockHeatConductionKernel(const Mesh &mesh, std::vector<HeatConductionKernel> kernels,
                            std::map<int, int> kernel_of_block);
  void evaluate(const CellState &state, LocalSystem &local) const override;
  /// Whether every block's kernel has a constant Jacobian (constant k and rho c).
  bool constant_jacobian() const override;
  /// Whether a kernel reads the past temperatures (a rho c of T).
  bool needs_temperature_history() const;

  /// The kernel of the cell `cell` (global index).
  const HeatConductionKernel &of_cell(int cell) const;
  /// The kernels, one per material.
  const std::vector<HeatConductionKernel> &kernels() const { return kernels_; }

private:
  std::vector<HeatConductionKernel> kernels_;
  KernelOfBlock kernel_of_block_;
};
} // namespace kiln
