// Tests base/log: the rank-0 stream writes through to std::cout and flushes at each end of
// line (a killed batch run keeps its log), warn_once prints a warning once on rank 0, and on a
// terminal a status line stays below the log, rewritten in place.
// KILN_TEST_NP: 1 2
#include "base/log.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <iostream>
#include <sstream>

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
