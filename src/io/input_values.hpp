#pragma once
/// The values of a Kiln input's parameters as written (before Teuchos converts them): numbers
/// in full, in decimal, finite and in range, arrays in braces, bools; the types Teuchos reads.
/// Used by the input reader's tree check (io/input_tree_check.hpp).
#include <string>
#include <vector>

namespace kiln::internal
{
/// `s` without leading and trailing blanks.
std::string trimmed(const std::string &s);
/// The types Kiln's parameters have (kiln --print-parameters).
const std::vector<std::string> &kiln_types();
/// Every type Teuchos reads (its ParameterEntryXMLConverterDB): the scalars, and arrays
/// and 2D arrays of all but char and bool.
bool is_known_type(const std::string &type);
/// The Kiln type a misspelled or foreign type name most likely means ("" if none).
std::string suggested_type(const std::string &type);
/// "a", "b", "c" (quoted, comma separated).
std::string quoted_list(const std::vector<std::string> &names);
/// Why `value` is not a `type` (one of is_known_type), with what to write instead; "" if it
/// is one.
std::string value_problem(const std::string &value, const std::string &type);
} // namespace kiln::internal
