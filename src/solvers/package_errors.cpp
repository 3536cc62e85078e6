#include "solvers/package_errors.hpp"

#include "base/errors.hpp"

#include <cctype>
#include <exception>

namespace kiln
{
namespace internal
{
namespace
{
/// Erases from `text` every block that starts with `begin` and ends with the
/// first `end` after it (inclusive).
void erase_blocks(std::string &text, const std::string &begin, const std::string &end)
{
  for (std::size_t at = text.find(begin); at != std::string::npos; at = text.find(begin, at))
  {
    const std::size_t stop = text.find(end, at + begin.size());
    text.erase(at, stop == std::string::npos ? std::string::npos : stop + end.size() - at);
  }
}
} // namespace

std::string package_message(std::string message)
{
  const std::string test = "Throw test that evaluated to true: ";
  for (std::size_t at = message.find(test); at != std::string::npos; at = message.find(test))
  {
    const std::size_t number = message.rfind("\n\nThrow number = ", at);
    const std::size_t line = number == std::string::npos || number == 0
                                 ? std::string::npos
                                 : message.rfind('\n', number - 1);
    const std::size_t begin = number == std::string::npos ? at
                              : line == std::string::npos ? 0
                                                          : line + 1;
    const std::size_t end = message.find("\n\n", at);
    message.erase(begin, end == std::string::npos ? std::string::npos : end + 2 - begin);
  }
  erase_blocks(message, "Throw number = ", "\n");
  erase_blocks(message, "The valid parameters and types are:", "\n  }\n");
  for (std::size_t at = message.find("\n\n\n"); at != std::string::npos;
       at = message.find("\n\n\n"))
    message.erase(at, 1);
  while (!message.empty() && std::isspace(static_cast<unsigned char>(message.back())))
    message.pop_back();
  return message;
}

void as_input_error(const Teuchos::Comm<int> &comm, const std::string &where,
                    const std::function<void()> &f)
{
  bool ok = true;
  std::string message;
  try
  {
    f();
  }
  catch (const std::exception &e)
  {
    ok = false;
    message = package_message(e.what());
  }
  check_collectively(comm, ok, where, message);
}
} // namespace internal
} // namespace kiln
