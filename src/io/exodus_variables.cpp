#include "io/exodus_variables.hpp"

#include "io/collective_checks.hpp"
#include "io/field_catalog.hpp"

#include <algorithm>
#include <set>

namespace kiln
{
namespace internal
{
std::vector<std::string> ExodusVariables::names(const std::string &name, const int n_components)
{
  if (n_components == 1)
    return {name};
  // A field of the catalog names its components; others: x y z for 3, the tensor
  // components for 6, numbers otherwise.
  const FieldDescription *known = describe_field(name);
  std::vector<std::string> components =
      known != nullptr && known->n_components() == n_components ? known->components
      : n_components == 3 ? std::vector<std::string>{"x", "y", "z"}
      : n_components == 6 ? tensor_components()
                          : std::vector<std::string>{};
  std::vector<std::string> result;
  for (int k = 0; k < n_components; ++k)
    result.push_back(name + "_" + (components.empty() ? std::to_string(k) : components[k]));
  return result;
}

std::vector<int> ExodusVariables::components(const int n_components)
{
  // The fields come in the order of their names (tensors in tensor_components() order).
  std::vector<int> result;
  for (int k = 0; k < n_components; ++k)
    result.push_back(k);
  return result;
}

void ExodusVariables::define(const std::vector<FieldSpec> &fields)
{
  fields_ = fields;
  defined_ = true;
}

std::vector<std::string> ExodusVariables::names_of(const Center center) const
{
  std::vector<std::string> result;
  for (const auto &f : fields_)
    if (f.center == center)
      for (const auto &v : names(f.name, f.n_components))
        result.push_back(v);
  return result;
}

const FieldSpec *ExodusVariables::find(const std::string &name) const
{
  for (const auto &f : fields_)
    if (f.name == name)
      return &f;
  return nullptr;
}

int ExodusVariables::first_index(const FieldSpec &field) const
{
  int index = 1;
  for (const auto &f : fields_)
  {
    if (f.name == field.name)
      return index;
    if (f.center == field.center)
      index += f.n_components;
  }
  return -1;
}

void ExodusVariables::check_field(const FieldSpec &field,
                                  const std::vector<FieldSpec> &step_fields) const
{
  const std::string what = std::string(kind_of(field.center)) + " field \"" + field.name + "\"";
  if (defined_)
  {
    const FieldSpec *declared = find(field.name);
    check_usage(declared != nullptr && declared->center == field.center &&
                    declared->n_components == field.n_components,
                "field declared in the first step",
                what + " with " + std::to_string(field.n_components) +
                    " components does not match the fields of the first step; Exodus defines "
                    "its variables once, so every step must write the fields of the first step");
    return;
  }
  // First step: the names must fit and must not clash with variables of earlier fields.
  std::set<std::string> taken;
  for (const auto &f : step_fields)
    if (f.center == field.center)
      for (const auto &v : names(f.name, f.n_components))
        taken.insert(v);
  for (const auto &v : names(field.name, field.n_components))
  {
    check_usage(static_cast<int>(v.size()) <= max_name_length, "name length",
                "Exodus variable \"" + v + "\" of " + what + " is longer than " +
                    std::to_string(max_name_length) + " characters");
    check_usage(taken.count(v) == 0, "unique variable names",
                "Exodus variable \"" + v + "\" of " + what +
                    " is also a variable of an earlier field of this step");
  }
}

std::string ExodusVariables::missing_from(const std::vector<FieldSpec> &step_fields) const
{
  std::string missing;
  for (const auto &f : fields_)
    if (std::none_of(step_fields.begin(), step_fields.end(),
                     [&](const FieldSpec &s) { return s.name == f.name; }))
      missing += (missing.empty() ? "\"" : ", \"") + f.name + "\"";
  return missing;
}
} // namespace internal
} // namespace kiln
