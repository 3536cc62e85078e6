#include "base/log.hpp"

#include <Teuchos_oblackholestream.hpp>
#include <mpi.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>

#include <cstdlib>
#include <iostream>
#include <mutex>
#include <set>
#include <streambuf>

namespace kiln
{
namespace internal
{
void StatusLineBuffer::hide_status()
{
  if (shown_)
    target_ << "\r\033[K";
  shown_ = false;
}

void StatusLineBuffer::set_status(const std::string &line)
{
  if (!terminal_)
    return;
  if (!line_start_)
  {
    target_ << "\n"; // a partial ordinary line stays above
    line_start_ = true;
  }
  // Never wider than the terminal: a wrapped line cannot be rewritten by "\r" and leaves a
  // trail (the caller fits it first, fit_status_line; this is the last resort).
  const int width = terminal_columns();
  status_ = width > 1 && line.size() >= static_cast<std::size_t>(width)
                ? line.substr(0, static_cast<std::size_t>(width - 1))
                : line;
  target_ << "\r" << status_ << "\033[K";
  shown_ = true;
  target_.flush();
}

void StatusLineBuffer::end_status()
{
  if (shown_)
    target_ << "\n";
  shown_ = false;
  status_.clear();
  target_.flush();
}

StatusLineBuffer::int_type StatusLineBuffer::overflow(const int_type c)
{
  if (traits_type::eq_int_type(c, traits_type::eof()))
    return traits_type::not_eof(c);
  const char ch = traits_type::to_char_type(c);
  return xsputn(&ch, 1) == 1 ? c : traits_type::eof();
}

std::streamsize StatusLineBuffer::xsputn(const char *s, const std::streamsize n)
{
  if (n <= 0)
    return n;
  hide_status();
  target_.write(s, n);
  line_start_ = s[n - 1] == '\n';
  if (std::char_traits<char>::find(s, static_cast<std::size_t>(n), '\n') != nullptr)
  {
    if (line_start_ && !status_.empty())
    {
      target_ << "\r" << status_ << "\033[K";
      shown_ = true;
    }
    target_.flush();
  }
  return target_ ? n : 0;
}

int StatusLineBuffer::sync()
{
  target_.flush();
  return target_ ? 0 : -1;
}

namespace
{
int world_rank()
{
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  int rank = 0;
  if (initialized && !finalized)
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

/// Whether std::cout is a terminal the user looks at. Under an MPI launcher it is not known:
/// Open MPI gives every rank a pseudo-terminal whether mpirun's own output is a terminal or
/// a file, so a launched run counts as not on a terminal (one line per step).
bool stdout_is_terminal()
{
  for (const char *launcher : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(launcher) != nullptr)
      return false;
  return isatty(STDOUT_FILENO) == 1;
}

/// Decided when the program starts, before MPI_Init (which sets the variables of a launched
/// run in a singleton's environment too).
const bool started_on_terminal = stdout_is_terminal();

/// The one buffer of the rank-0 log (std::cout; a terminal or not).
StatusLineBuffer &log_buffer()
{
  static StatusLineBuffer buffer(std::cout, started_on_terminal);
  return buffer;
}
} // namespace
} // namespace internal

Teuchos::RCP<Teuchos::FancyOStream> rank0_stream(const Teuchos::Comm<int> &comm)
{
  static Teuchos::oblackholestream black_hole;
  static std::ostream line_flushing_cout(&internal::log_buffer());
  std::ostream &target =
      comm.getRank() == 0 ? line_flushing_cout : static_cast<std::ostream &>(black_hole);
  return Teuchos::fancyOStream(Teuchos::rcpFromRef(target));
}

bool log_is_terminal()
{
  return internal::log_buffer().terminal();
}

void show_status_line(const std::string &line)
{
  if (internal::world_rank() == 0)
    internal::log_buffer().set_status(line);
}

void end_status_line()
{
  if (internal::world_rank() == 0)
    internal::log_buffer().end_status();
}

std::string fit_status_line(const std::vector<StatusField> &fields, const int width)
{
  const std::size_t room =
      width > 1 ? static_cast<std::size_t>(width - 1) : std::string::npos; // columns usable
  const auto joined = [](const std::vector<std::string> &texts)
  {
    std::string line;
    for (const std::string &t : texts)
      line += (line.empty() ? "" : ", ") + t;
    return line;
  };
  std::vector<std::string> full, shortened;
  for (const StatusField &f : fields)
  {
    full.push_back(f.text);
    shortened.push_back(f.short_text.empty() ? f.text : f.short_text);
  }
  std::string line = joined(full);
  if (line.size() <= room)
    return line;
  // Drop the fields of lowest priority (the later one first among equals) from the short forms.
  std::vector<std::size_t> order(fields.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](const std::size_t a, const std::size_t b)
                   {
                     return fields[a].priority < fields[b].priority ||
                            (fields[a].priority == fields[b].priority && a > b);
                   });
  std::vector<bool> kept(fields.size(), true);
  for (std::size_t k = 0;; ++k)
  {
    std::vector<std::string> texts;
    for (std::size_t i = 0; i < fields.size(); ++i)
      if (kept[i])
        texts.push_back(shortened[i]);
    line = joined(texts);
    if (line.size() <= room || texts.size() <= 1)
      break;
    kept[order[k]] = false;
  }
  return line.size() <= room ? line : line.substr(0, room);
}

int terminal_columns()
{
  struct winsize size = {};
  if (ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0)
    return size.ws_col;
  if (const char *columns = std::getenv("COLUMNS"))
  {
    const int n = std::atoi(columns);
    if (n > 0)
      return n;
  }
  return 80;
}

bool warn_once(const std::string &message)
{
  static std::mutex mutex;
  static std::set<std::string> printed;
  const std::lock_guard<std::mutex> lock(mutex);
  if (!printed.insert(message).second || internal::world_rank() != 0)
    return false;
  // Through the log's buffer, so a status line on a terminal stays below it.
  static std::ostream log(&internal::log_buffer());
  log << "kiln: warning: " << message << "\n";
  return true;
}
} // namespace kiln
