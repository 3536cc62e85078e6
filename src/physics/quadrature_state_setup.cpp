#include "physics/quadrature_state_setup.hpp"

#include "base/errors.hpp"

namespace kiln
{
namespace internal
{
/// "a, b, c".
std::string comma_separated(const std::vector<std::string> &names)
{
  std::string all;
  for (const std::string &name : names)
    all += (all.empty() ? "" : ", ") + name;
  return all;
}
} // namespace internal

std::unique_ptr<QuadratureState>
make_quadrature_state(const std::vector<const ConstitutiveModel *> &models,
                      const std::vector<int> &owned_cells,
                      const std::function<const ConstitutiveModel *(int cell)> &model_of,
                      const std::function<int(int cell)> &n_points_of, const std::string &where)
{
  std::vector<std::string> names;
  for (const ConstitutiveModel *model : models)
  {
    if (model == nullptr || model->n_state() == 0)
      continue;
    const std::vector<std::string> these = model->state_names();
    KILN_ASSERT(static_cast<int>(these.size()) == model->n_state(),
                "a model names each of its state components");
    KILN_CHECK_INPUT(names.empty() || these == names, where,
                     "the models with state keep different components ("
                         << internal::comma_separated(names) << "; "
                         << internal::comma_separated(these)
                         << "): a run holds one kind of state at its quadrature points; give "
                            "every block with such a model the same model");
    names = these;
  }
  if (names.empty())
    return nullptr;
  std::vector<int> n_points(owned_cells.size(), 0);
  for (std::size_t c = 0; c < owned_cells.size(); ++c)
  {
    const ConstitutiveModel *model = model_of(owned_cells[c]);
    if (model != nullptr && model->n_state() > 0)
      n_points[c] = n_points_of(owned_cells[c]);
  }
  auto state = std::make_unique<QuadratureState>(names, owned_cells, n_points);
  for (int c = 0; c < state->n_cells(); ++c)
    for (int q = 0; q < state->n_points(c); ++q)
      model_of(owned_cells[c])->initial_state(state->current(c, q));
  state->commit();
  return state;
}
} // namespace kiln
