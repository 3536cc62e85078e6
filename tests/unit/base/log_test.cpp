// Tests base/log: the rank-0 stream writes through to std::cout and flushes at each end of
// line (a killed batch run keeps its log), warn_once prints a warning once on rank 0, and on a
// terminal a status line stays below the log, rewritten in place.
// KILN_TEST_NP: 1 2
#include "base/log.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
/// Counts the flushes of the buffer it stands for.
class CountingBuffer final : public std::stringbuf
{
public:
  int flushes = 0;

protected:
  int sync() override
  {
    ++flushes;
    return std::stringbuf::sync();
  }
};

/// Sends std::cout to a CountingBuffer for its lifetime.
struct CaptureCout
{
  CountingBuffer buffer;
  std::streambuf *previous = std::cout.rdbuf(&buffer);
  ~CaptureCout() { std::cout.rdbuf(previous); }
};
} // namespace

TEST(Log, Rank0StreamFlushesEveryLine)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto out = kiln::rank0_stream(*comm);
  CaptureCout capture;
  *out << "half a line";
  const int flushes_before_newline = capture.buffer.flushes;
  *out << " and its end\n";
  if (comm->getRank() == 0)
  {
    EXPECT_EQ(capture.buffer.str(), "half a line and its end\n");
    EXPECT_GT(capture.buffer.flushes, flushes_before_newline);
  }
  else
    EXPECT_EQ(capture.buffer.str(), "");
}

TEST(Log, WarnOncePrintsOnceOnRankZero)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  CaptureCout capture;
  const bool first = kiln::warn_once("log_test: something odd");
  const bool second = kiln::warn_once("log_test: something odd");
  EXPECT_EQ(first, comm->getRank() == 0);
  EXPECT_FALSE(second);
  EXPECT_EQ(capture.buffer.str(),
            comm->getRank() == 0 ? "kiln: warning: log_test: something odd\n" : "");
}

TEST(Log, StatusLineOnATerminal)
{
  std::ostringstream screen;
  kiln::internal::StatusLineBuffer buffer(screen, true);
  std::ostream log(&buffer);
  log << "header\n";
  buffer.set_status("step 1");
  buffer.set_status("step 2");
  // An ordinary line erases the status line, is printed, and the status line comes back.
  log << "output: t = 1 s\n";
  buffer.set_status("step 3");
  buffer.end_status();
  log << "status: complete\n";
  EXPECT_EQ(screen.str(), "header\n"
                          "\rstep 1\033[K"
                          "\rstep 2\033[K"
                          "\r\033[Koutput: t = 1 s\n\rstep 2\033[K"
                          "\rstep 3\033[K"
                          "\n"
                          "status: complete\n");
}

TEST(Log, NoStatusLineElsewhere)
{
  std::ostringstream file;
  kiln::internal::StatusLineBuffer buffer(file, false);
  std::ostream log(&buffer);
  buffer.set_status("step 1");
  log << "step 1: t = 1 s\n";
  buffer.end_status();
  EXPECT_EQ(file.str(), "step 1: t = 1 s\n");
  EXPECT_FALSE(buffer.terminal());
}

TEST(Log, FitStatusLineShortensThenDropsByPriority)
{
  const std::vector<kiln::StatusField> fields = {{"step 12: t = 1.5 s", "", 100},
                                                 {"Newton 3 (41 linear)", "N 3/41", 40},
                                                 {"35% of 150 s", "35%", 60},
                                                 {"wall 12.5 s", "", 10},
                                                 {"1 min 05 s left", "", 50}};
  const std::string full =
      "step 12: t = 1.5 s, Newton 3 (41 linear), 35% of 150 s, wall 12.5 s, 1 min 05 s left";
  EXPECT_EQ(kiln::fit_status_line(fields, 200), full);
  EXPECT_EQ(kiln::fit_status_line(fields, static_cast<int>(full.size()) + 1), full);
  // One column less: the short forms.
  EXPECT_EQ(kiln::fit_status_line(fields, static_cast<int>(full.size())),
            "step 12: t = 1.5 s, N 3/41, 35%, wall 12.5 s, 1 min 05 s left");
  // Then the wall time goes, then the Newton iterations, then the time left, then the share.
  EXPECT_EQ(kiln::fit_status_line(fields, 50), "step 12: t = 1.5 s, N 3/41, 35%, 1 min 05 s left");
  EXPECT_EQ(kiln::fit_status_line(fields, 41), "step 12: t = 1.5 s, 35%, 1 min 05 s left");
  EXPECT_EQ(kiln::fit_status_line(fields, 30), "step 12: t = 1.5 s, 35%");
  EXPECT_EQ(kiln::fit_status_line(fields, 20), "step 12: t = 1.5 s");
  // The last field is cut: never more than width - 1 columns.
  EXPECT_EQ(kiln::fit_status_line(fields, 11), "step 12: t");
  for (int width = 2; width < 100; ++width)
    EXPECT_LE(kiln::fit_status_line(fields, width).size(), static_cast<std::size_t>(width - 1));
}

TEST(Log, TerminalColumnsFallsBackOnColumns)
{
  // ctest's output is not a terminal: the width is $COLUMNS, else 80.
  if (isatty(STDOUT_FILENO) == 1)
    GTEST_SKIP() << "stdout is a terminal: its own width counts";
  ::setenv("COLUMNS", "123", 1);
  EXPECT_EQ(kiln::terminal_columns(), 123);
  ::unsetenv("COLUMNS");
  EXPECT_EQ(kiln::terminal_columns(), 80);
}

TEST(Log, StatusLineNeverWiderThanTheTerminal)
{
  if (isatty(STDOUT_FILENO) == 1)
    GTEST_SKIP() << "stdout is a terminal: its own width counts";
  ::setenv("COLUMNS", "20", 1);
  std::ostringstream screen;
  kiln::internal::StatusLineBuffer buffer(screen, true);
  buffer.set_status(std::string(50, 'x'));
  ::unsetenv("COLUMNS");
  EXPECT_EQ(screen.str(), "\r" + std::string(19, 'x') + "\033[K");
}
