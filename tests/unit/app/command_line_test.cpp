// Tests app/command_line: --timers asks for the timer table of a run or a check, and is
// refused with the other modes.
#include "app/command_line.hpp"

#include "support/parameter_lists.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using kiln::CommandLine;
using kiln::parse_command_line;
using testing::HasSubstr;

TEST(CommandLine, Timers)
{
  EXPECT_FALSE(parse_command_line({"in.xml"}).timers);
  EXPECT_TRUE(parse_command_line({"in.xml", "--timers"}).timers);
  const CommandLine check = parse_command_line({"--timers", "--check", "in.xml"});
  EXPECT_TRUE(check.timers);
  EXPECT_EQ(check.mode, CommandLine::Mode::check);
  EXPECT_THAT(kiln_test::input_error_message(
                  [] {
                    parse_command_line({"--timers", "--version"});
                  }),
              HasSubstr("command line: --timers prints the timers of a run or a check; it cannot "
                        "be combined with this mode; run kiln --help"));
  EXPECT_THAT(kiln::usage(), HasSubstr("--timers"));
}
