#pragma once
/// Reads a Teuchos XML input file: rank 0 reads the text, every rank parses
/// the same text, so every rank raises the same error for a bad file.
#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>

#include <string>

namespace kiln
{
/// The unvalidated parameter list in `path`. Throws InputError naming the file
/// when it cannot be read, is not well-formed XML, or holds a number that
/// does not parse completely (Teuchos reads value="70GPa" as 70; Kiln does not).
Teuchos::ParameterList read_input(const std::string &path, const Teuchos::Comm<int> &comm);

/// The same for XML text; `where` names it in messages.
Teuchos::ParameterList parse_input(const std::string &xml, const std::string &where);
} // namespace kiln
