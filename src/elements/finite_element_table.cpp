/// FiniteElement::of(): the registration of the element types, one line each (style.md §9).
/// A new type: a file in elements/ with its make_<type>() and a line here.
#include "elements/elements.hpp"

#include "base/errors.hpp"

#include <array>
#include <string>

namespace kiln
{
const FiniteElement &FiniteElement::of(const CellType type)
{
  const FiniteElement *element = find(type);
  if (element == nullptr)
    throw InternalError("FiniteElement::of: no element for CellType " +
                        std::to_string(static_cast<int>(type)));
  return *element;
}

const FiniteElement *FiniteElement::find(const CellType type)
{
  using Maker = std::unique_ptr<FiniteElement> (*)();
  static const std::array<std::unique_ptr<FiniteElement>, n_cell_types> table = []
  {
    std::array<std::unique_ptr<FiniteElement>, n_cell_types> t;
    for (const Maker make :
         {elements::make_hex8, elements::make_tet4, elements::make_wedge6, elements::make_pyramid5,
          elements::make_tet10, elements::make_hex20, elements::make_hex27, elements::make_quad4,
          elements::make_tri3, elements::make_quad8, elements::make_quad9, elements::make_tri6})
    {
      std::unique_ptr<FiniteElement> fe = make();
      const auto i = static_cast<std::size_t>(fe->type());
      t.at(i) = std::move(fe);
    }
    return t;
  }();
  const auto i = static_cast<std::size_t>(type);
  return i < table.size() ? table[i].get() : nullptr;
}
} // namespace kiln
