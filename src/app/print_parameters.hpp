#pragma once
/// kiln --print-parameters: the valid input tree with its defaults and documentation.
#include <Teuchos_ParameterList.hpp>

#include <ostream>
#include <string>

namespace kiln
{
/// A default as a user writes it in an input: a double in its shortest exact form ("0.04",
/// "273.15", "1e-06"), an array as {a, b, c}, a bool as true or false.
std::string parameter_value_text(const Teuchos::ParameterEntry &entry);

/// Prints `list` in the layout of Teuchos' ParameterList::print with types and documentation
/// (each parameter "name : type = value" with its doc and requirement lines below it, then
/// each sublist "name -> " with its doc and content one space further in), `indent` spaces in,
/// with every value as parameter_value_text() writes it.
void print_parameters(const Teuchos::ParameterList &list, std::ostream &out, int indent = 2);
} // namespace kiln
