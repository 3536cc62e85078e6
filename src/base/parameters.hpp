#pragma once
/// Parameter helpers. Every configurable class declares
///   static Teuchos::ParameterList valid_parameters();
/// next to its constructor, each entry with a default, a doc string that states
/// the unit, and a validator where the value has a range or a set of choices.
/// The constructor reads a list that kiln::validated() has checked.

#include <Teuchos_ParameterEntryValidator.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <string>
#include <vector>

namespace kiln
{
/// Checks `user` against `valid` recursively and returns a copy with defaults set.
/// Unknown names (with the closest valid name), wrong types and values rejected
/// by a validator throw InputError naming `where` (the input file) and the
/// parameter path, e.g. `in.xml: Kiln/Mesh/Box/"Cells"`.
/// `path` is the path of `user` in the input ("Kiln/Mesh").
Teuchos::ParameterList validated(const Teuchos::ParameterList &user,
                                 const Teuchos::ParameterList &valid, const std::string &where,
                                 const std::string &path);

/// Declares sublist `name` of `parent` whose content is handed as is to a
/// Trilinos package (NOX, Stratimikos, MueLu): kiln::validated() does not look inside; it is
/// checked against the packages' names (src/solvers/solver_parameter_checks.hpp). `defaults`
/// are Kiln's defaults.
void set_pass_through_sublist(Teuchos::ParameterList &parent, const std::string &name,
                              const std::string &package, const std::string &doc,
                              const Teuchos::ParameterList &defaults);

/// Whether `name` was set in the input of a list returned by validated() (false for a
/// value filled in from its default; for a sublist, whether it holds a value from the
/// input).
bool given_in_input(const Teuchos::ParameterList &list, const std::string &name);

/// Declares sublist `name` of `parent` holding any number of sublists named by
/// the user (one per boundary condition, say), each validated against `each`
/// and given its defaults. The valid tree shows `each` as "<any name>".
void set_named_sublists(Teuchos::ParameterList &parent, const std::string &name,
                        const std::string &doc, const Teuchos::ParameterList &each);

/// Declares sublist `name` of `parent`, validated against `each` (which has a "Type" whose
/// default is "Constant", and a "Value"), that the input may also give as a plain number:
/// <Parameter name="Density" type="double" value="2700"/> stands for the sublist with Type
/// "Constant" and Value 2700; the number is checked against `each`'s "Value" (its type and
/// validator). validated() returns the sublist form, so readers see one shape.
void set_number_or_sublist(Teuchos::ParameterList &parent, const std::string &name,
                           const std::string &doc, const Teuchos::ParameterList &each);

/// `where: path/"name"`, the way every message names a parameter.
std::string parameter_path(const std::string &where, const std::string &path,
                           const std::string &name);

/// The candidate closest to `name` (edit distance, case-insensitive), or "" if
/// none is reasonably close.
std::string closest_name(const std::string &name, const std::vector<std::string> &candidates);

/// Number validators: value > 0, value >= 0, lo <= value <= hi.
Teuchos::RCP<const Teuchos::ParameterEntryValidator> positive_double_validator();
Teuchos::RCP<const Teuchos::ParameterEntryValidator> nonnegative_double_validator();
Teuchos::RCP<const Teuchos::ParameterEntryValidator> double_range_validator(double lo, double hi);
Teuchos::RCP<const Teuchos::ParameterEntryValidator> positive_int_validator();
Teuchos::RCP<const Teuchos::ParameterEntryValidator> nonnegative_int_validator();
/// For arrays: every entry > 0 and exactly `size` entries (size 0: any size >= 1).
Teuchos::RCP<const Teuchos::ParameterEntryValidator> positive_double_array_validator(int size);
Teuchos::RCP<const Teuchos::ParameterEntryValidator> positive_int_array_validator(int size);
Teuchos::RCP<const Teuchos::ParameterEntryValidator> double_array_validator(int size);
/// A string from a fixed set; the message lists the choices.
Teuchos::RCP<const Teuchos::ParameterEntryValidator>
choice_validator(const std::vector<std::string> &choices);
} // namespace kiln
