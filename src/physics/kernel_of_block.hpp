#pragma once
/// Which of a block kernel's kernels (one per material) evaluates a cell.
#include "base/errors.hpp"
#include "mesh/mesh.hpp"

#include <map>
#include <utility>

namespace kiln
{
/// The index of the kernel of each cell by its element block (mesh.block_id): the one look-up
/// of BlockElasticityKernel and BlockHeatConductionKernel. With one kernel every cell takes
/// it, without a look-up (the path of one material for every block).
class KernelOfBlock
{
public:
  /// `kernel_of_block` maps every block id of the mesh to one of `n_kernels` kernels (it may
  /// be empty with one kernel).
  KernelOfBlock(const Mesh &mesh, std::map<int, int> kernel_of_block, const int n_kernels)
      : mesh_(mesh), kernel_of_block_(std::move(kernel_of_block)), n_kernels_(n_kernels)
  {
    KILN_ASSERT(n_kernels_ > 0, "a block kernel without kernels");
  }
  /// The kernel index of the cell `cell` (global index).
  int of_cell(const int cell) const
  {
    if (n_kernels_ == 1)
      return 0;
    const auto it = kernel_of_block_.find(mesh_.block_id[cell]);
    KILN_ASSERT(it != kernel_of_block_.end(), "block " << mesh_.block_id[cell] << " has no kernel");
    return it->second;
  }

private:
  const Mesh &mesh_;
  std::map<int, int> kernel_of_block_;
  int n_kernels_;
};
} // namespace kiln
