// Tests app/run_observer (through Simulation::run): what a run writes besides its fields.
// The closing contact box to 60 s with output at listed times, every 20 s and every 4 steps:
// - the output steps are exactly those times and steps;
// - BASE.history.csv has one row per step from step 0, the same as /history in the .h5;
// - a BASE.gap-NNNNNN.csv per output step, the same as /gap/steps/NNNNNN, the gap closed at
//   the end (every pair in contact, pressure > 0);
// - every CSV header is "NAME [UNIT]", and the closed gap's pressure is positive (compression)
//   in every output: the gap tables, the contact_pressure field of /steps and /gap, and the
//   history's normal_force;
// - the gap surface (/gap: 25 points, 16 quadrilaterals, a 4 cm square in the gap's plane) is
//   a grid of the XDMF file, which checks;
// - the run's metadata and status are in the .h5, and the lock is gone after the run.
// A run stopped by an error finishes its results with the error as their status.
// KILN_TEST_NP: 1 2
#include "app/output_schedule.hpp"
#include "app/simulation.hpp"
#include "base/errors.hpp"
#include "cmake/xdmf_check.hpp"
#include "io/history_csv.hpp"
#include "io/input_reader.hpp"
#include "support/results_files.hpp"
#include "support/simulation_runs.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_Tuple.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <kiln/version.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

using testing::HasSubstr;
using testing::StartsWith;

namespace
{
using kiln_test::inputs;

/// A CSV file: its header's names (without the units), units and rows, each value read with
/// strtod.
struct Table
{
  std::vector<std::string> names;
  std::vector<std::string> units;
  std::vector<std::vector<double>> rows;
  std::vector<double> column(const std::string &name) const
  {
    const auto at = std::find(names.begin(), names.end(), name) - names.begin();
    std::vector<double> values;
    for (const auto &row : rows)
      values.push_back(row.at(static_cast<std::size_t>(at)));
    return values;
  }
};

Table read_csv(const std::string &path)
{
  Table table;
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::string line, cell;
  std::getline(in, line);
  for (std::istringstream header(line); std::getline(header, cell, ',');)
  {
    // "NAME [UNIT]": every column says its unit.
    const std::size_t open = cell.find(" [");
    EXPECT_TRUE(open != std::string::npos && cell.back() == ']')
        << path << ": the header \"" << cell << "\" has no unit";
    table.names.push_back(cell.substr(0, open));
    table.units.push_back(
        open == std::string::npos ? "" : cell.substr(open + 2, cell.size() - open - 3));
  }
  while (std::getline(in, line))
  {
    std::vector<double> row;
    for (std::istringstream values(line); std::getline(values, cell, ',');)
      row.push_back(std::strtod(cell.c_str(), nullptr));
    EXPECT_EQ(row.size(), table.names.size()) << path << ": " << line;
    table.rows.push_back(row);
  }
  return table;
}

std::string gap_table(const std::string &base, const int step)
{
  char name[32];
  std::snprintf(name, sizeof name, ".gap-%06d.csv", step);
  return base + name;
}

bool same_value(const double a, const double b)
{
  return a == b || (std::isnan(a) && std::isnan(b));
}
} // namespace

TEST(RunObserver, OutputsHistoryAndGapTables)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = kiln_test::temporary_base("run_observer", *comm) + "/box";
  const std::string deck = inputs + "contact-box-close.xml";
  Teuchos::ParameterList input = kiln::read_input(deck, *comm);
  input.sublist("Output")
      .set("Times", Teuchos::Array<double>(Teuchos::tuple(0.0, 53.0, 60.0)))
      .set("Interval", 20.0)
      .set("Every Steps", 4)
      .set("File Base", base);
  input.sublist("Checkpoint").set("At End", false);
  {
    kiln::Simulation sim(input, deck, comm);
    EXPECT_EQ(sim.run(), kiln::Simulation::Ending::finished);
  }
  comm->barrier();
  if (comm->getRank() != 0)
    return;
  const std::string h5 = base + ".h5";
  EXPECT_FALSE(std::filesystem::exists(base + ".lock")) << "the lock is released";

  // One history row per step, from the start.
  const Table history = read_csv(base + ".history.csv");
  ASSERT_GE(history.rows.size(), 10u);
  std::vector<std::string> names, units;
  for (const auto &c : kiln::history_columns())
  {
    names.push_back(c.name);
    units.push_back(c.unit);
  }
  EXPECT_EQ(history.names, names);
  EXPECT_EQ(history.units, units);
  const std::vector<double> steps = history.column("step"), times = history.column("time");
  for (std::size_t i = 0; i < steps.size(); ++i)
    EXPECT_EQ(steps[i], static_cast<double>(i));
  EXPECT_EQ(times.front(), 0.0);
  EXPECT_EQ(times.back(), 60.0);
  EXPECT_EQ(history.column("active_pairs").front(), 0.0);
  EXPECT_EQ(history.column("active_pairs").back(), 25.0);
  EXPECT_NEAR(history.column("min_gap").back(), 0.0, 1e-12); // u ~ 2e-5 m
  EXPECT_GT(history.column("normal_force").back(), 0.0);
  EXPECT_EQ(history.column("contact_area").front(), 0.0);
  EXPECT_NEAR(history.column("contact_area").back(), 0.0016, 1e-15);
  for (const double n : history.column("newton_iterations"))
    EXPECT_LE(n, 20.0);
  // /history holds the same rows, value for value.
  for (const std::string &name : names)
  {
    const std::vector<double> stored = kiln_test::read_dataset(h5, "/history/" + name);
    const std::vector<double> written = history.column(name);
    ASSERT_EQ(stored.size(), written.size()) << name;
    for (std::size_t i = 0; i < stored.size(); ++i)
      EXPECT_PRED2(same_value, stored[i], written[i]) << name << " row " << i;
  }

  // The output steps: the start, 20, 40, 53, 60 s and every 4th step.
  std::vector<double> expected = {0.0, 20.0, 40.0, 53.0, 60.0};
  for (std::size_t i = 4; i < steps.size(); i += 4)
    expected.push_back(times[i]);
  std::sort(expected.begin(), expected.end());
  expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
  std::vector<double> written;
  for (int s = 0;; ++s)
  {
    char group[32];
    std::snprintf(group, sizeof group, "/steps/%06d", s);
    const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const bool exists = H5Lexists(file, group, H5P_DEFAULT) > 0;
    H5Fclose(file);
    if (!exists)
      break;
    double time = 0.0;
    kiln_test::read_step(h5, "temperature", s, time);
    written.push_back(time);
  }
  EXPECT_EQ(written, expected);

  // A gap table per output step, the values of /gap/steps/NNNNNN.
  EXPECT_FALSE(std::filesystem::exists(gap_table(base, static_cast<int>(written.size()))));
  for (int s = 0; s < static_cast<int>(written.size()); ++s)
  {
    const Table gap = read_csv(gap_table(base, s));
    ASSERT_EQ(gap.rows.size(), 25u) << s;
    char group[32];
    std::snprintf(group, sizeof group, "/gap/steps/%06d/", s);
    const auto opening = kiln_test::read_dataset(h5, std::string(group) + "gap_opening");
    const auto pressure = kiln_test::read_dataset(h5, std::string(group) + "contact_pressure");
    const auto flux = kiln_test::read_dataset(h5, std::string(group) + "gap_heat_flux");
    for (std::size_t p = 0; p < 25; ++p)
    {
      EXPECT_EQ(gap.column("time")[p], written[static_cast<std::size_t>(s)]);
      EXPECT_EQ(gap.column("gap_opening")[p], opening[p]);
      EXPECT_EQ(gap.column("contact_pressure")[p], pressure[p]);
      EXPECT_EQ(gap.column("gap_heat_flux")[p], flux[p]);
    }
  }
  const Table last = read_csv(gap_table(base, static_cast<int>(written.size()) - 1));
  EXPECT_EQ(last.names,
            (std::vector<std::string>{"time", "pair", "x", "y", "z", "s", "t", "gap_opening",
                                      "contact_pressure", "gap_heat_flux", "contact_active",
                                      "temperature_a", "temperature_b", "area"}));
  EXPECT_EQ(last.units, (std::vector<std::string>{"s", "-", "m", "m", "m", "m", "m", "m", "Pa",
                                                  "W/m^2", "-", "K", "K", "m^2"}));
  // The closed gap in compression: a positive pressure in the volume's field (NaN off the
  // gap), the gap surface's and the table's, and a positive normal force in the history.
  {
    double time = 0.0;
    const int s_last = static_cast<int>(written.size()) - 1;
    const auto volume = kiln_test::read_step(h5, "contact_pressure", s_last, time);
    int n_gap = 0;
    for (const double p : volume)
      if (!std::isnan(p))
      {
        EXPECT_GT(p, 0.0);
        ++n_gap;
      }
    EXPECT_EQ(n_gap, 50); // the 25 pairs' two nodes
    char group[32];
    std::snprintf(group, sizeof group, "/gap/steps/%06d/", s_last);
    for (const double p : kiln_test::read_dataset(h5, std::string(group) + "contact_pressure"))
      EXPECT_GT(p, 0.0);
    EXPECT_GT(history.column("normal_force").back(), 0.0);
  }
  for (std::size_t p = 0; p < 25; ++p)
  {
    EXPECT_EQ(last.column("contact_active")[p], 1.0);
    EXPECT_GT(last.column("contact_pressure")[p], 0.0);
    EXPECT_NEAR(last.column("temperature_a")[p], last.column("temperature_b")[p], 1e-6);
  }
  // The in-plane coordinates follow the rows of faces of the 4 cm square, from its centre:
  // lengths in the plane, as in 3-D.
  const auto s_of = last.column("s"), t_of = last.column("t");
  for (const auto &c : {s_of, t_of})
  {
    EXPECT_NEAR(*std::max_element(c.begin(), c.end()), 0.02, 1e-12);
    EXPECT_NEAR(*std::min_element(c.begin(), c.end()), -0.02, 1e-12);
  }
  const auto x = last.column("x"), y = last.column("y"), z = last.column("z");
  for (std::size_t i = 0; i < 25; ++i)
    for (std::size_t j = 0; j < 25; ++j)
      EXPECT_NEAR(std::hypot(s_of[i] - s_of[j], t_of[i] - t_of[j]),
                  std::sqrt((x[i] - x[j]) * (x[i] - x[j]) + (y[i] - y[j]) * (y[i] - y[j]) +
                            (z[i] - z[j]) * (z[i] - z[j])),
                  1e-12);

  // The gap surface and its XDMF grid.
  EXPECT_EQ(kiln_test::read_dataset(h5, "/gap/coordinates").size(), 75u);
  const auto quads = kiln_test::read_dataset(h5, "/gap/connectivity");
  EXPECT_EQ(quads.size(), 64u);
  for (const double q : quads)
    EXPECT_TRUE(q >= 0.0 && q < 25.0);
  EXPECT_EQ(kiln::check_xdmf(base + ".xmf"), "");
  std::ifstream xmf(base + ".xmf");
  const std::string index((std::istreambuf_iterator<char>(xmf)), std::istreambuf_iterator<char>());
  EXPECT_THAT(index, HasSubstr("<Grid Name=\"gap\" GridType=\"Collection\""));
  EXPECT_THAT(index, HasSubstr("TopologyType=\"Quadrilateral\" NumberOfElements=\"16\""));

  // The run's metadata.
  EXPECT_EQ(kiln_test::read_text_attribute(h5, "/", "kiln_version"), kiln::version_string);
  EXPECT_THAT(kiln_test::read_text_attribute(h5, "/", "created"), StartsWith("20"));
  EXPECT_EQ(kiln_test::read_text_attribute(h5, "/", "input_path"), deck);
  EXPECT_EQ(kiln_test::read_text_attribute(h5, "/", "status"), "complete");
  EXPECT_EQ(kiln_test::read_text_attribute(h5, "/history/time", "unit"), "s");
  std::filesystem::remove_all(std::filesystem::path(base).parent_path());
}

TEST(RunObserver, ErrorFinishesTheResults)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = kiln_test::temporary_base("run_observer_error", *comm) + "/run";
  const std::string deck =
      std::string(KILN_SOURCE_DIR) + "/tests/input_errors/step_below_minimum.xml";
  Teuchos::ParameterList input = kiln::read_input(deck, *comm);
  input.sublist("Output").set("File Base", base);
  {
    kiln::Simulation sim(input, deck, comm);
    EXPECT_THROW(sim.run(), kiln::RunError);
  }
  comm->barrier();
  if (comm->getRank() != 0)
    return;
  EXPECT_FALSE(std::filesystem::exists(base + ".running.h5"));
  EXPECT_FALSE(std::filesystem::exists(base + ".lock"));
  EXPECT_THAT(kiln_test::read_text_attribute(base + ".h5", "/", "status"),
              StartsWith("stopped by an error at t = 0 s: "));
  EXPECT_EQ(read_csv(base + ".history.csv").rows.size(), 1u);
  std::filesystem::remove_all(std::filesystem::path(base).parent_path());
}
