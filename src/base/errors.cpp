#include "base/errors.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_CommHelpers.hpp>

#include <regex>
#include <sstream>
#include <vector>

namespace kiln
{
namespace internal
{
void throw_input_error(const std::string &where, const std::string &message)
{
  throw InputError(where.empty() ? message : where + ": " + message);
}

void throw_internal_error(const char *file, const int line, const char *condition,
                          const std::string &message)
{
  std::ostringstream s;
  s << "internal error at " << file << ":" << line << ": (" << condition << ") " << message;
  throw InternalError(s.str());
}
} // namespace internal

std::string one_line_library_message(const std::string &what)
{
  // "./packages/teuchos/.../Teuchos_XMLObject.cpp:137:", Teuchos' source location.
  static const std::regex location(R"(^\S*\.(cpp|hpp|cc|h|c):[0-9]+:\s*)");
  std::istringstream lines(what);
  std::string line, result;
  while (std::getline(lines, line))
  {
    line = std::regex_replace(line, location, "");
    const auto first = line.find_first_not_of(" \t\r");
    const auto last = line.find_last_not_of(" \t\r");
    if (first == std::string::npos)
      continue;
    line = line.substr(first, last - first + 1);
    if (line.rfind("Throw number =", 0) == 0 ||
        line.rfind("Throw test that evaluated to true:", 0) == 0)
      continue;
    result += (result.empty() ? "" : "; ") + line;
  }
  return result;
}

namespace
{
/// The message of the lowest rank where `local_ok` is false, on every rank; "" and false if
/// it is true everywhere. Collective.
bool first_failure(const Teuchos::Comm<int> &comm, const bool local_ok, const std::string &message,
                   std::string &first)
{
  const int rank = comm.getRank();
  const int my_failed_rank = local_ok ? comm.getSize() : rank;
  int first_failed = comm.getSize();
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, my_failed_rank, Teuchos::outArg(first_failed));
  if (first_failed == comm.getSize())
    return false;
  // Send the failing rank's message to everyone so all ranks throw the same text.
  int length = rank == first_failed ? static_cast<int>(message.size()) : 0;
  Teuchos::broadcast(comm, first_failed, Teuchos::outArg(length));
  std::vector<char> text(message.begin(), message.end());
  text.resize(length);
  if (length > 0)
    Teuchos::broadcast(comm, first_failed, length, text.data());
  first.assign(text.begin(), text.end());
  return true;
}
} // namespace

void check_collectively(const Teuchos::Comm<int> &comm, const bool local_ok,
                        const std::string &where, const std::string &message)
{
  std::string first;
  if (first_failure(comm, local_ok, message, first))
    internal::throw_input_error(where, first);
}

void check_run_collectively(const Teuchos::Comm<int> &comm, const bool local_ok,
                            const std::string &message)
{
  std::string first;
  if (first_failure(comm, local_ok, message, first))
    throw RunError(first);
}

void check_run_collectively(const Teuchos::Comm<int> &comm, const bool local_ok,
                            const std::string &message, const bool step_failure)
{
  // 1 where every failure is a step failure (or none): one reduction more than a RunError.
  const int step_here = local_ok || step_failure ? 1 : 0;
  int all_steps = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, step_here, Teuchos::outArg(all_steps));
  // With a failure that is not a step failure, the message of the lowest such rank.
  std::string first;
  if (!first_failure(comm, all_steps == 1 ? local_ok : local_ok || step_failure, message, first))
    return;
  if (all_steps == 1)
    throw StepFailure(first);
  throw RunError(first);
}

void check_write_collectively(const Teuchos::Comm<int> &comm, const bool local_ok,
                              const std::string &where, const std::string &message)
{
  std::string first;
  if (first_failure(comm, local_ok, message, first))
    throw WriteError(where.empty() ? first : where + ": " + first);
}
} // namespace kiln
