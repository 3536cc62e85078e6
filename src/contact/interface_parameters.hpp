#pragma once
/// The "Contact" sublist of "Mechanics": the gap interface's kind and parameters.
#include <Teuchos_ParameterList.hpp>

#include <string>

namespace kiln
{
/// "Enabled", "Kind" (interface_kinds()), "Complementarity Scale" and every kind's own
/// parameters.
Teuchos::ParameterList interface_parameters();
/// Throws InputError (naming `path`) if the validated sublist `contact` gives a parameter of
/// another kind than its "Kind".
void check_interface_parameters(const Teuchos::ParameterList &contact, const std::string &path);
} // namespace kiln
