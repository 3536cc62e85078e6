#include "discretization/quadrature_state.hpp"

#include "base/errors.hpp"

#include <algorithm>
#include <utility>

namespace kiln
{
QuadratureState::QuadratureState(std::vector<std::string> names, std::vector<int> cells,
                                 const std::vector<int> &n_points)
    : names_(std::move(names)), cells_(std::move(cells)), offsets_(cells_.size() + 1, 0)
{
  KILN_ASSERT(n_points.size() == cells_.size(), "one number of points per owned cell");
  for (std::size_t k = 0; k < names_.size(); ++k)
    KILN_ASSERT(std::count(names_.begin(), names_.end(), names_[k]) == 1,
                "the state components have distinct names");
  for (std::size_t c = 0; c < cells_.size(); ++c)
  {
    KILN_ASSERT(n_points[c] >= 0, "a cell has no negative number of points");
    offsets_[c + 1] = offsets_[c] + n_points[c];
  }
  old_.assign(static_cast<std::size_t>(offsets_.back()) * names_.size(), 0.0);
  current_ = old_;
}

std::vector<double> QuadratureState::old_component(const int k) const
{
  KILN_ASSERT(k >= 0 && k < n_state(), "a component of the state");
  std::vector<double> values(static_cast<std::size_t>(n_points()));
  for (std::size_t p = 0; p < values.size(); ++p)
    values[p] = old_[p * names_.size() + static_cast<std::size_t>(k)];
  return values;
}

void QuadratureState::set_component(const int k, const std::vector<double> &values)
{
  KILN_ASSERT(k >= 0 && k < n_state(), "a component of the state");
  KILN_ASSERT(values.size() == static_cast<std::size_t>(n_points()), "a value per owned point");
  for (std::size_t p = 0; p < values.size(); ++p)
    old_[p * names_.size() + static_cast<std::size_t>(k)] =
        current_[p * names_.size() + static_cast<std::size_t>(k)] = values[p];
}
} // namespace kiln
