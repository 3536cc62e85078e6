#pragma once
/// The element types' bases, one file each; FiniteElement::of (finite_element.cpp) registers
/// them, one line per type.
#include "elements/finite_element.hpp"

namespace kiln
{
const FiniteElement &hex8_element();
const FiniteElement &quad4_element();
} // namespace kiln
