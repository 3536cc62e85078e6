#pragma once
/// Private to src/io: the variables of an Exodus results file. Exodus defines its variables
/// once, before the first step: the fields written in the first step become the file's
/// variables, one per component, and every later step must write the same fields.
#include "io/field_spec.hpp"

#include <string>
#include <vector>

namespace kiln
{
namespace internal
{
class ExodusVariables
{
public:
  /// Longest variable, block or set name the results file can hold (Exodus fixes it when
  /// the file is defined, before the variables are known).
  static constexpr int max_name_length = 64;

  /// The variable names of a field: {name} for 1 component, name_x/_y/_z for 3,
  /// name_xx/_yy/_zz/_xy/_yz/_xz for 6 (a Voigt tensor), name_0 ... otherwise.
  static std::vector<std::string> names(const std::string &name, int n_components);
  /// The component of the field (0-based) each variable of names() holds: the fields come in
  /// the order their names give (tensors: xx yy zz xy yz xz, tensor_components()).
  static std::vector<int> components(int n_components);

  bool defined() const { return defined_; }
  /// Makes the fields of the first step the file's variables.
  void define(const std::vector<FieldSpec> &fields);
  const std::vector<FieldSpec> &fields() const { return fields_; }
  /// The variable names of every field of `center`, in order.
  std::vector<std::string> names_of(Center center) const;
  /// 1-based index of the first variable of `field` among its center's variables.
  int first_index(const FieldSpec &field) const;

  /// InternalError if `field` cannot be written after `step_fields` in a step: in the first
  /// step when a variable name is too long or is a variable of an earlier field of the step;
  /// in a later step when it is not a field of the first step.
  void check_field(const FieldSpec &field, const std::vector<FieldSpec> &step_fields) const;
  /// The names of the variables' fields missing from `step_fields`: "\"a\", \"b\"".
  std::string missing_from(const std::vector<FieldSpec> &step_fields) const;

private:
  /// The declared field with this name, or nullptr.
  const FieldSpec *find(const std::string &name) const;

  std::vector<FieldSpec> fields_;
  bool defined_ = false;
};
} // namespace internal
} // namespace kiln
