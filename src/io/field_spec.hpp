#pragma once
/// Private to src/io: one field of an output step, as the results writers record it.
#include <string>

namespace kiln
{
namespace internal
{
/// Where a field's values live.
enum class Center
{
  node,
  cell
};

/// "node" or "cell", for messages and function names.
inline const char *kind_of(const Center center)
{
  return center == Center::node ? "node" : "cell";
}

/// A field's name, where it lives and its number of values per node or cell.
struct FieldSpec
{
  std::string name;
  Center center = Center::node;
  int n_components = 1;
};
} // namespace internal
} // namespace kiln
