#pragma once
/// Private to src/solvers: exceptions of the Trilinos packages (NOX, Stratimikos, Belos,
/// MueLu, Ifpack2) as Kiln input errors.
#include <functional>
#include <string>

namespace Teuchos
{
template <typename Ordinal> class Comm;
}

namespace kiln
{
namespace internal
{
/// The message of a Trilinos exception without what TEUCHOS_TEST_FOR_EXCEPTION
/// puts before it (file, line, throw number, the test), and without Teuchos'
/// list of every valid MueLu parameter (MueLu adds "Did you mean ...?").
std::string package_message(std::string message);

/// Runs `f` (collective); an exception becomes the same InputError on every rank,
/// "<where>: <the package's message>", e.g. where = "Solver/Linear Solver".
void as_input_error(const Teuchos::Comm<int> &comm, const std::string &where,
                    const std::function<void()> &f);
} // namespace internal
} // namespace kiln
