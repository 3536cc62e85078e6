#include "physics/heat/block_heat_conduction_kernel.hpp"

#include "base/errors.hpp"

#include <algorithm>

namespace kiln
{
BlockHeatConductionKernel::BlockHeatConductionKernel(const Mesh &mesh,
                                                     std::vector<HeatConductionKernel> kernels,
                                                     std::map<int, int> kernel_of_block)
    : mesh_(mesh), kernels_(std::move(kernels)), kernel_of_block_(std::move(kernel_of_block))
{
  KILN_ASSERT(!kernels_.empty(), "a block heat conduction kernel without kernels");
}

const HeatConductionKernel &BlockHeatConductionKernel::of_cell(const int cell) const
{
  if (kernels_.size() == 1)
    return kernels_.front();
  const auto it = kernel_of_block_.find(mesh_.block_id[cell]);
  KILN_ASSERT(it != kernel_of_block_.end(), "block " << mesh_.block_id[cell] << " has no kernel");
  return kernels_[it->second];
}

bool BlockHeatConductionKernel::constant_jacobian() const
{
  return std::all_of(kernels_.begin(), kernels_.end(),
                     [](const HeatConductionKernel &k) { return k.constant_jacobian(); });
}

bool BlockHeatConductionKernel::needs_temperature_history() const
{
  return std::any_of(kernels_.begin(), kernels_.end(),
                     [](const HeatConductionKernel &k) { return k.needs_temperature_history(); });
}

void BlockHeatConductionKernel::evaluate(const CellState &state, LocalSystem &local) const
{
  KILN_ASSERT(state.cell >= 0 || kernels_.size() == 1, "a cell state without its cell");
  of_cell(state.cell).evaluate(state, local);
}
} // namespace kiln
