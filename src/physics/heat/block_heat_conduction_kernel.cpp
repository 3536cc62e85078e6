#include "physics/heat/block_heat_conduction_kernel.hpp"

#include "base/errors.hpp"

#include <algorithm>

namespace kiln
{
BlockHeatConductionKernel::BlockHeatConductionKernel(const Mesh &mesh,
                                                     std::vector<HeatConductionKernel> kernels,
                                                     std::map<int, int> kernel_of_block)
    : kernels_(std::move(kernels)),
      kernel_of_block_(mesh, std::move(kernel_of_block), static_cast<int>(kernels_.size()))
{
}

const HeatConductionKernel &BlockHeatConductionKernel::of_cell(const int cell) const
{
  return kernels_[kernel_of_block_.of_cell(cell)];
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
