// Tests app/output_schedule: the default File Base, the stop times and the outputs due at a
// time or after a step (listed times, every N steps, every interval, the start and the end),
// a restart's stop times, and the refused inputs: no output time, decreasing times, an
// interval that asks for too many outputs, a File Base that names a folder.
// KILN_TEST_NP: 1 2
#include "app/output_schedule.hpp"

#include "base/parameters.hpp"
#include "support/parameter_lists.hpp"
#include "support/results_files.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

using kiln_test::input_error_message;
using kiln_test::values;
using testing::ElementsAre;
using testing::HasSubstr;

namespace
{
kiln::OutputSchedule schedule(const Teuchos::ParameterList &user,
                              const std::string &input = "decks/box.xml")
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const Teuchos::ParameterList p =
      kiln::validated(user, kiln::OutputSchedule::valid_parameters(), input, "Kiln/Output");
  return kiln::OutputSchedule(p, input, *comm);
}
} // namespace

TEST(OutputSchedule, DefaultsWriteTheStartAlone)
{
  const kiln::OutputSchedule s = schedule(Teuchos::ParameterList("Output"));
  EXPECT_EQ(s.file_base(), "results/box");
  EXPECT_TRUE(s.writes_hdf5());
  EXPECT_FALSE(s.writes_exodus());
  EXPECT_EQ(s.results_files(), "results/box.h5 and results/box.xmf");
  EXPECT_EQ(s.history_path(), "results/box.history.csv");
  EXPECT_EQ(s.lock_path(), "results/box.lock");
  EXPECT_EQ(s.end_time(), 0.0);
  EXPECT_THAT(s.stop_times(0.0, true), ElementsAre(0.0));
  EXPECT_TRUE(s.due_at_time(0.0));
  EXPECT_FALSE(s.due_after_step(1));
}

TEST(OutputSchedule, TimesStepsAndInterval)
{
  Teuchos::ParameterList p("Output");
  p.set("Times", values({50.0, 53.0, 150.0}));
  p.set("Interval", 40.0);
  p.set("Every Steps", 3);
  p.set("Format", "HDF5 and Exodus");
  p.set("File Base", "out/run");
  const kiln::OutputSchedule s = schedule(p);
  EXPECT_EQ(s.results_files(false), "out/run.h5 and out/run.exo");
  EXPECT_EQ(s.end_time(), 150.0);
  // The start (always), the listed times and the multiples of the interval up to the end.
  EXPECT_THAT(s.stop_times(0.0, true), ElementsAre(0.0, 40.0, 50.0, 53.0, 80.0, 120.0, 150.0));
  // A restart at 53 s goes on after it.
  EXPECT_THAT(s.stop_times(53.0, false), ElementsAre(80.0, 120.0, 150.0));
  EXPECT_THAT(s.stop_times(53.0, true), ElementsAre(53.0, 80.0, 120.0, 150.0));
  for (const double t : {0.0, 40.0, 50.0, 53.0, 80.0, 120.0, 150.0})
    EXPECT_TRUE(s.due_at_time(t)) << t;
  EXPECT_TRUE(s.due_at_time(80.0 * (1.0 + 1e-14)));
  for (const double t : {1.0, 41.0, 79.0, 160.0})
    EXPECT_FALSE(s.due_at_time(t)) << t;
  EXPECT_FALSE(s.due_after_step(1));
  EXPECT_TRUE(s.due_after_step(3));
  EXPECT_TRUE(s.due_after_step(9));
  EXPECT_FALSE(s.due_after_step(10));
}

TEST(OutputSchedule, IntervalNotDividingTheEnd)
{
  Teuchos::ParameterList p("Output");
  p.set("Times", values({0.0, 10.0}));
  p.set("Interval", 3.0);
  EXPECT_THAT(schedule(p).stop_times(0.0, true), ElementsAre(0.0, 3.0, 6.0, 9.0, 10.0));
}

TEST(OutputSchedule, RefusedTimes)
{
  Teuchos::ParameterList empty("Output");
  empty.set("Times", values({}));
  EXPECT_THAT(input_error_message([&] { schedule(empty); }),
              HasSubstr("decks/box.xml: Kiln/Output/\"Times\": is empty; give at least one "
                        "output time (the last is the end of the run)"));
  Teuchos::ParameterList decreasing("Output");
  decreasing.set("Times", values({0.0, 10.0, 5.0}));
  EXPECT_THAT(input_error_message([&] { schedule(decreasing); }),
              HasSubstr("output times must be >= 0 and increasing; entry 3 is 5"));
  Teuchos::ParameterList fine("Output");
  fine.set("Times", values({0.0, 1000.0}));
  fine.set("Interval", 1e-3);
  EXPECT_THAT(input_error_message([&] { schedule(fine); }),
              HasSubstr("Kiln/Output/\"Interval\": = 0.001 s gives 1e+06 output times up to the "
                        "end, 1000 s; at most 100000 are allowed: give a larger interval"));
}

TEST(OutputSchedule, FileBaseMustNotBeAFolder)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  Teuchos::ParameterList slash("Output");
  slash.set("File Base", "results/");
  EXPECT_THAT(input_error_message([&] { schedule(slash); }),
              HasSubstr("decks/box.xml: Kiln/Output/\"File Base\": = \"results/\" ends in '/', "
                        "so it names a folder; give the results' path without extension, a "
                        "file name in that folder, e.g. \"results/run\" for results/run.h5"));
  const std::string folder = kiln_test::temporary_base("output_schedule_folder", *comm);
  if (comm->getRank() == 0)
    std::filesystem::create_directories(folder);
  comm->barrier();
  Teuchos::ParameterList existing("Output");
  existing.set("File Base", folder);
  EXPECT_THAT(input_error_message([&] { schedule(existing); }),
              HasSubstr("Kiln/Output/\"File Base\": = \"" + folder +
                        "\" is an existing folder; File Base is the results' path without "
                        "extension, a file name: give one inside it, e.g. \"" +
                        folder + "/run\""));
  comm->barrier();
  if (comm->getRank() == 0)
    std::filesystem::remove_all(folder);
}

// The UTF-8 check of File Base's name (the XDMF index is UTF-8 XML): ASCII and UTF-8 pass, a
// Latin-1 letter, a cut-off sequence and an overlong lead byte are found at their index.
TEST(OutputSchedule, FirstNonUtf8Byte)
{
  using kiln::internal::first_non_utf8_byte;
  EXPECT_EQ(first_non_utf8_byte("steel&al"), std::string::npos);
  EXPECT_EQ(first_non_utf8_byte("acier-\xc3\xa9t\xc3\xa9"), std::string::npos);
  EXPECT_EQ(first_non_utf8_byte("\xe2\x82\xac and \xf0\x9f\x94\xa5"), std::string::npos);
  EXPECT_EQ(first_non_utf8_byte("acier-\xe9t\xe9"), 6U);
  EXPECT_EQ(first_non_utf8_byte("ab\xc3"), 2U);
  EXPECT_EQ(first_non_utf8_byte("\xc0\xaf"), 0U);
}
