#pragma once
/// The elasticity of a mesh with a material per element block.
#include "discretization/quadrature_state.hpp"
#include "mesh/mesh.hpp"
#include "physics/kernel.hpp"
#include "physics/kernel_of_block.hpp"
#include "physics/mechanics/elasticity_kernel.hpp"

#include <map>
#include <vector>

namespace kiln
{
/// One ElasticityKernel per material, each cell evaluated by its block's (mesh.block_id[c]):
/// the constant linear-elastic blocks by the Hooke fast path, the others by the general
/// path through their ConstitutiveModel, which reads the cell's state at t_n and writes that
/// at t_{n+1} in the QuadratureState (CellState::cell_local: the cell's index among the
/// owned cells) with the step's Δt (set_time_step()).
class BlockElasticityKernel final : public CellKernel
{
public:
  /// `kernels[i]` is material i's; `kernel_of_block` maps every block id of the mesh to one.
  BlockElasticityKernel(const Mesh &mesh, std::vector<ElasticityKernel> kernels,
                        std::map<int, int> kernel_of_block);
  void evaluate(const CellState &state, LocalSystem &local) const override;
  /// Whether every block's kernel has a constant Jacobian (the fast path).
  bool constant_jacobian() const override;

  /// The kernel of the cell `cell` (global index).
  const ElasticityKernel &of_cell(int cell) const;
  /// The kernels, one per material.
  const std::vector<ElasticityKernel> &kernels() const { return kernels_; }
  /// The state the models read and write (null: none) and Δt = t_{n+1} − t_n [s] of the
  /// step being solved (0: a first or steady solve without an accepted step before).
  void set_state(QuadratureState *state) { state_ = state; }
  void set_time_step(const double time_step) { time_step_ = time_step; }
  /// The point history of owned cell `cell_local` (its state, if it has some, and Δt).
  ElasticityKernel::PointHistory history(int cell_local) const;
  /// For output: the history whose old state is the cell's committed state (the last
  /// accepted step's end; an evaluation after the acceptance, at Δt = 0, rewrites only the
  /// state being computed), for ElasticityKernel::point_averages().
  ElasticityKernel::PointHistory output_history(int cell_local) const;

private:
  std::vector<ElasticityKernel> kernels_;
  KernelOfBlock kernel_of_block_;
  QuadratureState *state_ = nullptr;
  double time_step_ = 0.0;
};
} // namespace kiln
