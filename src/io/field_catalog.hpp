#pragma once
/// The one description of every field Kiln writes: its name, where it lives, its components
/// and unit (doc/output-format.md). The writers label their datasets and variables from it.
#include <string>
#include <vector>

namespace kiln
{
/// The components of a symmetric tensor as Kiln writes them: ParaView's order, so that its
/// labels XX YY ZZ XY YZ XZ name them right. Shear strains are tensor components (eps_xy,
/// not gamma_xy = 2 eps_xy).
inline const std::vector<std::string> &tensor_components()
{
  static const std::vector<std::string> names = {"xx", "yy", "zz", "xy", "yz", "xz"};
  return names;
}

struct FieldDescription
{
  std::string name;
  bool on_nodes;                       ///< else on cells
  std::vector<std::string> components; ///< empty for a scalar
  std::string unit;                    ///< "-" for a number
  std::string meaning;
  int n_components() const { return components.empty() ? 1 : static_cast<int>(components.size()); }
};

/// Every field Kiln writes, in the order of doc/output-format.md.
const std::vector<FieldDescription> &field_catalog();
/// The description of the field `name`, or nullptr if it is not one of Kiln's.
const FieldDescription *describe_field(const std::string &name);
} // namespace kiln
