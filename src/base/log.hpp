#pragma once
/// Rank-0 output (deal.II ConditionalOStream, step-40) and warnings.
#include <Teuchos_Comm.hpp>
#include <Teuchos_FancyOStream.hpp>
#include <Teuchos_RCP.hpp>

#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

namespace kiln
{
namespace internal
{
/// The rank-0 log's buffer: forwards every character to `target` (std::cout: looked up at
/// each write, so a temporary rdbuf() swap still applies) and flushes it at each '\n'. On a
/// terminal it can keep a status line at the bottom: set_status() draws it in place of the
/// last one ("\r", the text, erase to the end of the line: ESC [K), and ordinary text erases
/// it first and draws it again after its line ends, so the log scrolls above it.
class StatusLineBuffer final : public std::streambuf
{
public:
  StatusLineBuffer(std::ostream &target, bool terminal) : target_(target), terminal_(terminal) {}
  bool terminal() const { return terminal_; }
  /// Shows `line` (one line, no '\n') as the status line; nothing if not a terminal.
  void set_status(const std::string &line);
  /// Leaves the status line shown as an ordinary line of the log and ends it.
  void end_status();

protected:
  int_type overflow(int_type c) override;
  std::streamsize xsputn(const char *s, std::streamsize n) override;
  int sync() override;

private:
  /// Erases the status line if it is shown (before ordinary text).
  void hide_status();

  std::ostream &target_;
  bool terminal_;
  std::string status_;     ///< the status line ("" : none)
  bool shown_ = false;     ///< the status line is on the screen
  bool line_start_ = true; ///< ordinary text is at the start of a line
};
} // namespace internal

/// std::cout on rank 0, a black hole elsewhere. The rank-0 stream flushes at every end of
/// line: with stdout redirected to a file (a batch job, mpirun) the C library would
/// otherwise buffer whole blocks, and a run killed by a time limit would leave an empty
/// or truncated log.
Teuchos::RCP<Teuchos::FancyOStream> rank0_stream(const Teuchos::Comm<int> &comm);

/// Whether rank 0's std::cout is a terminal: not a file or a pipe, and not under an MPI
/// launcher (mpirun gives the ranks a pseudo-terminal even when its output is a file).
bool log_is_terminal();
/// On a terminal, shows `line` at the bottom of the rank-0 log, rewritten in place by the next
/// call (the log's other lines scroll above it); elsewhere does nothing (the caller prints
/// ordinary lines instead). Call on any rank: only rank 0 of MPI_COMM_WORLD draws.
void show_status_line(const std::string &line);
/// Leaves the last status line as an ordinary line (before a summary or an error message).
void end_status_line();

/// One field of a status line: its text, a shorter form of it ("": none) and its priority
/// (when the line does not fit, the field of the lowest priority is dropped first).
struct StatusField
{
  std::string text;
  std::string short_text;
  int priority = 0;
};
/// The fields joined by ", " in `width - 1` columns at most (a line of the terminal's full
/// width would wrap on some terminals): all in full if they fit; else each in its short form;
/// else without the fields of lowest priority, one at a time, until the rest fits; the one
/// field left is cut. A `width` below 2 means no limit.
std::string fit_status_line(const std::vector<StatusField> &fields, int width);
/// The width of rank 0's terminal in columns, asked at each call (so a resized window counts
/// at the next line): ioctl(TIOCGWINSZ) on stdout, else $COLUMNS, else 80.
int terminal_columns();

/// Prints "kiln: warning: <message>" on std::cout, on rank 0 of MPI_COMM_WORLD only (every
/// rank may call it: inputs are replicated) and once per distinct message in a process.
/// For input that is valid but likely to make the run fail or mislead (say, a nearly
/// incompressible material); the message says what will happen and what to do.
/// Returns whether this call printed it.
bool warn_once(const std::string &message);
} // namespace kiln
