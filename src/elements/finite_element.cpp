#include "elements/finite_element.hpp"

#include "base/errors.hpp"
#include "elements/element_types.hpp"

#include <string>
#include <vector>

namespace kiln
{
namespace
{
/// Every element type's basis: one line per type.
std::vector<const FiniteElement *> registered_elements()
{
  return {&hex8_element(), &quad4_element()};
}
} // namespace

const FiniteElement &FiniteElement::of(const CellType type)
{
  const FiniteElement *element = find(type);
  if (element == nullptr)
    throw InternalError("no finite element for element type " + ReferenceCell::of(type).name());
  return *element;
}

const FiniteElement *FiniteElement::find(const CellType type)
{
  static const std::vector<const FiniteElement *> by_type = []
  {
    std::vector<const FiniteElement *> table;
    for (const FiniteElement *element : registered_elements())
    {
      const auto index = static_cast<std::size_t>(element->type());
      if (table.size() <= index)
        table.resize(index + 1, nullptr);
      table[index] = element;
    }
    return table;
  }();
  const auto index = static_cast<std::size_t>(type);
  return index < by_type.size() ? by_type[index] : nullptr;
}
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
