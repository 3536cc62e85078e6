// Tests io/history_csv: the header names every column, numbers are written in their shortest
// exact form and read back bit for bit, rows are appended as they come (rank 0 writes), and a
// restart keeps the rows up to its step and drops the later ones, or starts anew (and says
// why) without the earlier file or with one of other columns; with a running path it keeps
// the earlier file whole and writes beside it until finish().
// KILN_TEST_NP: 1 2
#include "io/history_csv.hpp"

#include "support/results_files.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

using testing::HasSubstr;

namespace
{
MPI_Comm raw(const Teuchos::Comm<int> &comm)
{
  return *dynamic_cast<const Teuchos::MpiComm<int> &>(comm).getRawMpiComm();
}

/// The row of step `step`: every column a value that needs all 17 digits, one NaN.
std::vector<double> row_of(const int step)
{
  std::vector<double> row(kiln::history_columns().size());
  row[0] = step;
  for (std::size_t c = 1; c < row.size(); ++c)
    row[c] = (step + 1) * (0.1 + 1.0 / (3.0 + static_cast<double>(c)));
  row[10] = std::numeric_limits<double>::quiet_NaN();
  return row;
}

std::vector<std::string> lines_of(const std::string &path)
{
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

bool same_row(const std::vector<double> &a, const std::vector<double> &b)
{
  if (a.size() != b.size())
    return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(a[i] == b[i] || (std::isnan(a[i]) && std::isnan(b[i]))))
      return false;
  return true;
}
} // namespace

TEST(HistoryCsv, NumbersAsWrittenAndReadBack)
{
  EXPECT_EQ(kiln::history_number(0.04), "0.04");
  EXPECT_EQ(kiln::history_number(53.0), "53");
  EXPECT_EQ(kiln::history_number(1e-6), "1e-06");
  EXPECT_EQ(kiln::history_number(-2.288e7), "-22880000");
  EXPECT_EQ(kiln::history_number(std::nan("")), "nan");
  const double third = 1.0 / 3.0;
  EXPECT_EQ(std::strtod(kiln::history_number(third).c_str(), nullptr), third);
}

TEST(HistoryCsv, RowsAppendedAndContinuedAfterARestart)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string path = kiln_test::temporary_base("history_csv", *comm) + ".history.csv";
  {
    kiln::HistoryCsv history(raw(*comm), path);
    for (int step = 0; step <= 5; ++step)
      history.append(row_of(step));
  }
  comm->barrier();
  const std::vector<std::string> written = lines_of(path);
  ASSERT_EQ(written.size(), 7u);
  EXPECT_EQ(written[0], "step [-],time [s],dt [s],newton_iterations [-],linear_iterations [-],"
                        "T_min [K],T_max [K],T_mean [K],thermal_energy [J],"
                        "max_displacement [m],min_gap [m],max_gap [m],active_pairs [-],"
                        "contact_area [m^2],normal_force [N],wall_time [s]");
  EXPECT_EQ(written[1].substr(0, 2), "0,");
  EXPECT_THAT(written[3], HasSubstr(",nan,"));
  comm->barrier();

  // A restart after step 3: rows 0-3 kept (every rank gets them), 4 and 5 dropped.
  {
    kiln::HistoryCsv history(raw(*comm), path, 3);
    EXPECT_EQ(history.warning(), "");
    ASSERT_EQ(history.kept_rows().size(), 4u);
    for (int step = 0; step <= 3; ++step)
      EXPECT_TRUE(same_row(history.kept_rows()[step], row_of(step))) << step;
    history.append(row_of(4));
  }
  comm->barrier();
  const std::vector<std::string> continued = lines_of(path);
  ASSERT_EQ(continued.size(), 6u);
  for (std::size_t i = 0; i < continued.size(); ++i)
    EXPECT_EQ(continued[i], written[i]) << "line " << i;
  comm->barrier();

  // The same columns without their units (Kiln before changelog 0032): the rows are kept and
  // the header gets the units.
  if (comm->getRank() == 0)
  {
    std::ofstream legacy(path);
    legacy << "step,time,dt,newton_iterations,linear_iterations,T_min,T_max,T_mean,"
              "thermal_energy,max_displacement,min_gap,max_gap,active_pairs,contact_area,"
              "normal_force,wall_time\n";
    for (std::size_t i = 1; i < written.size(); ++i)
      legacy << written[i] << "\n";
  }
  comm->barrier();
  {
    const kiln::HistoryCsv history(raw(*comm), path, 3);
    EXPECT_EQ(history.warning(), "");
    EXPECT_EQ(history.kept_rows().size(), 4u);
  }
  comm->barrier();
  EXPECT_EQ(lines_of(path).front(), written.front());
  comm->barrier();

  // Other columns (an older file): kept aside, the history starts anew.
  if (comm->getRank() == 0)
    std::ofstream(path) << "time,T\n0,288\n";
  comm->barrier();
  {
    const kiln::HistoryCsv history(raw(*comm), path, 3);
    EXPECT_THAT(history.warning(), HasSubstr(path +
                                             " has other columns than this Kiln writes; "
                                             "it is kept as " +
                                             path + ".old"));
    EXPECT_TRUE(history.kept_rows().empty());
  }
  comm->barrier();
  EXPECT_EQ(lines_of(path).size(), 1u);
  EXPECT_TRUE(std::filesystem::exists(path + ".old"));
  comm->barrier();

  // No earlier file.
  if (comm->getRank() == 0)
    std::filesystem::remove(path);
  comm->barrier();
  {
    const kiln::HistoryCsv history(raw(*comm), path, 7);
    EXPECT_THAT(history.warning(),
                HasSubstr("(the earlier run's history) is missing; the history starts at the "
                          "restart, step 7"));
  }
  comm->barrier();
  if (comm->getRank() == 0)
  {
    std::filesystem::remove(path);
    std::filesystem::remove(path + ".old");
  }
}

namespace
{
/// The names of `columns`.
std::vector<std::string> names(const std::vector<kiln::HistoryColumn> &columns)
{
  std::vector<std::string> out;
  for (const auto &c : columns)
    out.push_back(c.name);
  return out;
}
} // namespace

// A mesh with one gap (or none) keeps the columns of history_columns() (gold files and tools
// read them by name); with several, a block of six columns per gap follows them, named after
// the gap's side set.
TEST(HistoryCsv, ColumnsPerGapOnlyWithSeveralGaps)
{
  const std::vector<std::string> base = names(kiln::history_columns());
  EXPECT_EQ(names(kiln::history_columns(std::vector<int>{})), base);
  EXPECT_EQ(names(kiln::history_columns(std::vector<int>{10})), base);
  const std::vector<std::string> two = names(kiln::history_columns(std::vector<int>{10, 12}));
  ASSERT_EQ(two.size(), base.size() + 12);
  EXPECT_TRUE(std::equal(base.begin(), base.end(), two.begin()));
  const std::vector<std::string> block = {"min_gap_gap12",      "max_gap_gap12",
                                          "active_pairs_gap12", "contact_area_gap12",
                                          "normal_force_gap12", "gap_heat_flow_gap12"};
  EXPECT_EQ(kiln::gap_history_columns(12), block);
  EXPECT_TRUE(std::equal(block.begin(), block.end(), two.end() - 6));
  EXPECT_EQ(two[base.size()], "min_gap_gap10");
  // A CSV with these columns: the header names them, a restart reads its rows back.
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string path = kiln_test::temporary_base("history_csv_gaps", *comm) + ".history.csv";
  std::vector<double> row(two.size(), 1.5);
  row[0] = 0.0;
  {
    kiln::HistoryCsv history(raw(*comm), path, kiln::history_columns(std::vector<int>{10, 12}));
    history.append(row);
  }
  kiln::HistoryCsv again(raw(*comm), path, 0, kiln::history_columns(std::vector<int>{10, 12}));
  EXPECT_EQ(again.warning(), "");
  ASSERT_EQ(again.kept_rows().size(), 1u);
  EXPECT_EQ(again.kept_rows()[0], row);
}

TEST(HistoryCsv, ARestartWithARunningPathKeepsTheEarlierHistoryWhole)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = kiln_test::temporary_base("history_csv_running", *comm);
  const std::string path = base + ".history.csv";
  const std::string running = base + ".running.history.csv";
  {
    kiln::HistoryCsv history(raw(*comm), path);
    for (int step = 0; step <= 5; ++step)
      history.append(row_of(step));
  }
  comm->barrier();
  const std::vector<std::string> written = lines_of(path);
  comm->barrier();

  // A restart after step 3 would drop rows 4 and 5: the earlier file stays whole, this
  // history (rows 0-3 and its own) goes to the running path, and kept_end() is the time of
  // the earlier file's last row (every rank).
  {
    kiln::HistoryCsv history(raw(*comm), path, 3, kiln::history_columns(), running);
    EXPECT_EQ(history.warning(), "");
    EXPECT_EQ(history.path(), running);
    EXPECT_EQ(history.kept_end(), row_of(5)[1]);
    ASSERT_EQ(history.kept_rows().size(), 4u);
    history.append(row_of(4));
    comm->barrier();
    EXPECT_EQ(lines_of(path), written);
    EXPECT_EQ(lines_of(running).size(), 6u);
  }
  comm->barrier();

  // Cut off before finish(): the next restart continues the running file (its rows up to
  // the step), the earlier file still kept whole.
  {
    kiln::HistoryCsv history(raw(*comm), path, 4, kiln::history_columns(), running);
    EXPECT_EQ(history.warning(), "");
    EXPECT_EQ(history.path(), running);
    EXPECT_EQ(history.kept_end(), row_of(5)[1]);
    EXPECT_EQ(history.kept_rows().size(), 5u);
    history.append(row_of(5));
    history.append(row_of(6));
    // Passed the earlier history: finish() puts it in place of the earlier file.
    history.finish(path);
    EXPECT_EQ(history.path(), path);
  }
  comm->barrier();
  EXPECT_FALSE(std::filesystem::exists(running));
  EXPECT_EQ(lines_of(path).size(), 8u);
  comm->barrier();

  // Nothing after the step: written in place, as without a running path.
  {
    kiln::HistoryCsv history(raw(*comm), path, 6, kiln::history_columns(), running);
    EXPECT_EQ(history.path(), path);
    EXPECT_EQ(history.kept_end(), -std::numeric_limits<double>::infinity());
    history.finish(base + ".restarted.history.csv");
    EXPECT_EQ(history.path(), path);
  }
  comm->barrier();
  EXPECT_FALSE(std::filesystem::exists(base + ".restarted.history.csv"));
  comm->barrier();
  if (comm->getRank() == 0)
    std::filesystem::remove(path);
}

// Contact pairs (Mechanics/Contact/Pairs): a block of two columns per pair after the gaps',
// named after the pair, in the input's order; without pairs nothing moves.
TEST(HistoryCsv, ColumnsPerContactPair)
{
  const std::vector<std::string> base = names(kiln::history_columns());
  EXPECT_EQ(names(kiln::history_columns(std::vector<int>{10}, {})), base);
  const std::vector<std::string> pairs =
      names(kiln::history_columns(std::vector<int>{}, {"cut", "lid"}));
  ASSERT_EQ(pairs.size(), base.size() + 6);
  EXPECT_TRUE(std::equal(base.begin(), base.end(), pairs.begin()));
  const std::vector<std::string> tail = {"normal_force_cut", "contact_area_cut", "heat_flow_cut",
                                         "normal_force_lid", "contact_area_lid", "heat_flow_lid"};
  EXPECT_TRUE(std::equal(tail.begin(), tail.end(), pairs.end() - 6));
  EXPECT_EQ(kiln::pair_history_columns("cut"),
            (std::vector<std::string>{"normal_force_cut", "contact_area_cut", "heat_flow_cut"}));
  // After the gaps' blocks.
  const std::vector<std::string> both =
      names(kiln::history_columns(std::vector<int>{10, 12}, {"cut"}));
  ASSERT_EQ(both.size(), base.size() + 12 + 3);
  EXPECT_EQ(both[base.size() + 12], "normal_force_cut");
  const auto columns = kiln::history_columns(std::vector<int>{}, {"cut"});
  EXPECT_EQ(columns[base.size()].unit, "N");
  EXPECT_EQ(columns[base.size() + 1].unit, "m^2");
  EXPECT_EQ(columns[base.size() + 2].unit, "W");
}
