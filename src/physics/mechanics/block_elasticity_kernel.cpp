#include "physics/mechanics/block_elasticity_kernel.hpp"

#include "base/errors.hpp"

#include <algorithm>

namespace kiln
{
BlockElasticityKernel::BlockElasticityKernel(const Mesh &mesh,
                                             std::vector<ElasticityKernel> kernels,
                                             std::map<int, int> kernel_of_block)
    : kernels_(std::move(kernels)),
      kernel_of_block_(mesh, std::move(kernel_of_block), static_cast<int>(kernels_.size()))
{
}

const ElasticityKernel &BlockElasticityKernel::of_cell(const int cell) const
{
  return kernels_[kernel_of_block_.of_cell(cell)];
}

bool BlockElasticityKernel::constant_jacobian() const
{
  return std::all_of(kernels_.begin(), kernels_.end(),
                     [](const ElasticityKernel &k) { return k.constant_jacobian(); });
}

ElasticityKernel::PointHistory BlockElasticityKernel::history(const int cell_local) const
{
  ElasticityKernel::PointHistory history;
  history.time_step = time_step_;
  if (state_ != nullptr && cell_local >= 0 && state_->n_points(cell_local) > 0)
  {
    history.old_state = state_->old(cell_local, 0);
    history.new_state = state_->current(cell_local, 0);
  }
  return history;
}

ElasticityKernel::PointHistory BlockElasticityKernel::output_history(const int cell_local) const
{
  ElasticityKernel::PointHistory history;
  if (state_ != nullptr && cell_local >= 0 && state_->n_points(cell_local) > 0)
    history.old_state = state_->old(cell_local, 0);
  return history;
}

void BlockElasticityKernel::evaluate(const CellState &state, LocalSystem &local) const
{
  KILN_ASSERT(state.cell >= 0, "a cell state without its cell");
  const ElasticityKernel &kernel = of_cell(state.cell);
  if (!kernel.general())
  {
    kernel.evaluate(state, local);
    return;
  }
  ElasticityKernel::PointHistory point_history = history(state.cell_local);
  if (state.history.T_old != nullptr) // T at t_n (else T itself: no accepted state yet)
    point_history.T_old = {state.history.T_old, state.T.size()};
  kernel.evaluate(state.fe, state.u, state.T, point_history, kernel.body_force(), state.slots.u,
                  state.slots.T, local);
}
} // namespace kiln
