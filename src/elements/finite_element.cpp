#include "elements/finite_element.hpp"

#include "base/errors.hpp"

#include <string>
#include <vector>

namespace kiln
{
const ReferenceValues &ReferenceValues::of(const CellType type)
{
  static const std::vector<ReferenceValues> tables = []
  {
    std::vector<ReferenceValues> all;
    for (int t = 0; t < n_cell_types; ++t)
    {
      ReferenceValues v;
      // A type without a basis keeps an empty table; reinit() asserts on it.
      if (const FiniteElement *element = FiniteElement::find(static_cast<CellType>(t)))
      {
        const FiniteElement &fe = *element;
        const Quadrature &rule = fe.quadrature();
        v.n_shape = fe.n_shape();
        v.n_qpoints = rule.size();
        v.shape.resize(static_cast<std::size_t>(v.n_shape) * v.n_qpoints);
        v.grad.resize(v.shape.size());
        for (int q = 0; q < v.n_qpoints; ++q)
        {
          fe.values(rule.points[q], v.shape.data() + q * v.n_shape);
          fe.gradients(rule.points[q], v.grad.data() + q * v.n_shape);
        }
        v.weights = rule.weights;
      }
      all.push_back(std::move(v));
    }
    return all;
  }();
  return tables[static_cast<std::size_t>(type)];
}
} // namespace kiln
