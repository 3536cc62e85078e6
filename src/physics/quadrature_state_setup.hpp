#pragma once
/// The QuadratureState of a run from its constitutive models (issue 31).
#include "discretization/quadrature_state.hpp"
#include "physics/materials/constitutive_model.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace kiln
{
/// The state at the quadrature points of the owned cells `owned_cells` (global indices,
/// DofManager::owned_cells()), or null if none of `models` (every model of the run, the same
/// on every rank) has state: a run without one keeps no storage and does nothing more. The
/// components are those of the models with state (ConstitutiveModel::state_names()), which
/// must all have the same ones (an InputError naming `where` otherwise: one state layout per
/// run). A cell has `n_points_of(cell)` points if its model `model_of(cell)` (null: none) has
/// state, else none; every point starts from the model's initial_state(), committed.
std::unique_ptr<QuadratureState>
make_quadrature_state(const std::vector<const ConstitutiveModel *> &models,
                      const std::vector<int> &owned_cells,
                      const std::function<const ConstitutiveModel *(int cell)> &model_of,
                      const std::function<int(int cell)> &n_points_of, const std::string &where);
} // namespace kiln
