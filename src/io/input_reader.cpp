#include "io/input_reader.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "io/input_tree_check.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_StringInputSource.hpp>
#include <Teuchos_XMLObject.hpp>
#include <Teuchos_XMLParameterListReader.hpp>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

namespace kiln
{
namespace internal
{
namespace
{
/// The XML tree of `xml`, or an InputError with the parser's message on one line.
Teuchos::XMLObject parse_xml(const std::string &xml, const std::string &where)
{
  try
  {
    return Teuchos::StringInputSource(xml).getObject();
  }
  catch (const std::exception &e)
  {
    std::string message = one_line_library_message(e.what());
    const auto line = message.find("XML parse error");
    if (line != std::string::npos)
      message = message.substr(line);
    throw InputError(where + ": not a well-formed XML file: " + message);
  }
}
} // namespace

std::string read_input_text(const std::string &path, std::string &text)
{
  // open(2) rather than std::ifstream: its errno names the reason (not found, permission
  // denied, not a directory), O_NONBLOCK keeps a FIFO without a writer from blocking the
  // open, and poll(2) bounds the wait for a pipe or device that never sends anything.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0)
  {
    const int error = errno;
    return std::string("cannot open the input file (") + std::strerror(error) +
           (error == ENOENT || error == ENOTDIR ? "); check the path"
            : error == EACCES                   ? "); check that it is readable by this user"
                                                : "); check the path and the file");
  }
  struct stat info = {};
  ::fstat(fd, &info);
  if (S_ISDIR(info.st_mode))
  {
    ::close(fd);
    return "is a directory, not an input file; give the path of the XML input";
  }
  const bool regular = S_ISREG(info.st_mode);
  if (regular && static_cast<std::size_t>(info.st_size) > max_input_bytes)
  {
    ::close(fd);
    return "the file holds " + std::to_string(info.st_size) + " bytes, more than the " +
           std::to_string(max_input_bytes) +
           " an input may have (a Kiln input is a few kB of XML): check that this is the "
           "input file and not a mesh or a result";
  }
  // Every kind of file is read up to one byte past the limit, so that /dev/zero or a
  // pipe that never ends stops there and is reported by parse_input's size check.
  std::string problem;
  std::vector<char> chunk(65536);
  const auto deadline = std::chrono::steady_clock::now() + input_wait;
  while (text.size() <= max_input_bytes)
  {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    pollfd ready = {fd, POLLIN, 0};
    const int polled = ::poll(&ready, 1, static_cast<int>(std::max<long long>(0, left.count())));
    if (polled < 0 && errno == EINTR)
      continue;
    if (polled == 0)
    {
      problem =
          std::string(S_ISFIFO(info.st_mode) ? "is a FIFO (named pipe)" : "is not a regular file") +
          " and sent no end of file within " + std::to_string(input_wait.count()) + " s (" +
          std::to_string(text.size()) +
          " bytes read); give the path of the XML input file, or start the program "
          "that writes the pipe before Kiln";
      break;
    }
    const std::size_t want = std::min(chunk.size(), max_input_bytes + 1 - text.size());
    const ssize_t got = ::read(fd, chunk.data(), want);
    if (got < 0 && (errno == EAGAIN || errno == EINTR))
      continue;
    if (got < 0)
    {
      problem = std::string("cannot read the input file (") + std::strerror(errno) + ")";
      break;
    }
    if (got == 0)
      break;
    text.append(chunk.data(), static_cast<std::size_t>(got));
  }
  ::close(fd);
  return problem;
}
} // namespace internal

Teuchos::ParameterList parse_input(const std::string &xml, const std::string &where)
{
  internal::check_text(xml, where);
  const std::vector<internal::StartTag> tags = internal::scan_start_tags(xml, where);
  KILN_CHECK_INPUT(!tags.empty(), where,
                   "the file holds no XML element (only text or comments); a Kiln input is an "
                   "XML file whose root is <ParameterList name=\"Kiln\">: see inputs/ for "
                   "examples");
  const Teuchos::XMLObject root = internal::parse_xml(xml, where);
  internal::check_tree(root, tags, where);
  try
  {
    Teuchos::XMLParameterListReader reader;
    reader.setAllowsDuplicateSublists(false);
    return reader.toParameterList(root);
  }
  catch (const std::exception &e)
  {
    throw InputError(where +
                     ": cannot read the parameter list: " + one_line_library_message(e.what()));
  }
}

Teuchos::ParameterList read_input(const std::string &path, const Teuchos::Comm<int> &comm)
{
  std::string text;
  std::string problem;
  if (comm.getRank() == 0)
    problem = internal::read_input_text(path, text);
  check_collectively(comm, problem.empty(), path, problem);
  int length = static_cast<int>(std::min(text.size(), max_input_bytes + 1));
  Teuchos::broadcast(comm, 0, Teuchos::outArg(length));
  text.resize(length);
  if (length > 0)
    Teuchos::broadcast(comm, 0, length, text.data());
  return parse_input(text, path);
}
} // namespace kiln
