#pragma once
/// Private to src/solvers: the names NOX 13.2 reads in the sublists of its list that have no
/// validator in NOX, with the types and defaults NOX reads them with (the data of
/// check_nox_parameters(), solver_parameter_checks.hpp).
#include <Teuchos_ParameterList.hpp>

#include <string>

namespace kiln
{
namespace internal
{
/// The doc string of the entries NOX writes into its list (output values): accepted in an
/// input, but not offered in messages.
inline const std::string written_by_nox = "written by NOX";

/// The names NOX 13.2 reads in the sublists that have no validator in NOX, with the types and
/// defaults NOX reads them with; an empty sublist is not checked. The choices ("Method") carry
/// a validator with their valid values.
Teuchos::ParameterList nox_known_parameters();
} // namespace internal
} // namespace kiln
