// Tests Kiln/Output/"Format" (app/simulation): a run with "HDF5 and Exodus" writes both files,
// with the same times and the same nodal values, the time history as global variables equal to
// the history CSV's row of each output step, and the side sets and node sets named;
// "Exodus" alone writes no .h5.
// KILN_TEST_NP: 1 2
#include "app/simulation.hpp"
#include "io/history_csv.hpp"
#include "io/input_reader.hpp"
#include "support/results_files.hpp"
#include "support/simulation_runs.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_Tuple.hpp>
#include <exodusII.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using kiln_test::inputs;

/// Runs the closing contact box to 50 s with output at 0 and 50 s in `format`; with `restart`
/// (the checkpoint of such a run), continues it to 53 s with output at 0, 50 and 53 s.
void run(const std::string &base, const std::string &format, const std::string &restart = "")
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string deck = inputs + "contact-box-close.xml";
  Teuchos::ParameterList input = kiln::read_input(deck, *comm);
  Teuchos::ParameterList &output = input.sublist("Output");
  output.set("Times", restart.empty() ? Teuchos::Array<double>(Teuchos::tuple(0.0, 50.0))
                                      : Teuchos::Array<double>(Teuchos::tuple(0.0, 50.0, 53.0)));
  output.set("File Base", base);
  output.set("Format", format);
  kiln::Simulation sim(input, deck, comm);
  if (!restart.empty())
    sim.set_restart(restart);
  sim.run();
}
/// The `n` names of the variables (`variables`) or objects of `type` in the open file `exo`.
std::vector<std::string> exodus_names(const int exo, const ex_entity_type type, const int n,
                                      const bool variables)
{
  std::vector<std::vector<char>> storage(n, std::vector<char>(MAX_STR_LENGTH + 1, '\0'));
  std::vector<char *> pointers;
  for (auto &s : storage)
    pointers.push_back(s.data());
  if (variables)
    EXPECT_GE(ex_get_variable_names(exo, type, n, pointers.data()), 0);
  else
    EXPECT_GE(ex_get_names(exo, type, pointers.data()), 0);
  return std::vector<std::string>(pointers.begin(), pointers.end());
}

/// The rows of a history CSV (the header skipped), as the text of each value.
std::vector<std::vector<std::string>> csv_rows(const std::string &path)
{
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line))
  {
    std::istringstream cells(line);
    std::vector<std::string> row;
    for (std::string cell; std::getline(cells, cell, ',');)
      row.push_back(cell);
    rows.push_back(row);
  }
  return rows;
}

/// The time history's columns are the global variables, and each output step's values are the
/// history CSV's row of its step (written from the same doubles, so the text is equal); the
/// box's faces and the gap name the side sets and node sets.
void check_globals_and_set_names(const int exo, const std::string &base)
{
  const auto &columns = kiln::history_columns();
  const int n_globals = static_cast<int>(columns.size());
  int n_vars = 0;
  ex_get_variable_param(exo, EX_GLOBAL, &n_vars);
  ASSERT_EQ(n_vars, n_globals);
  const std::vector<std::string> names = exodus_names(exo, EX_GLOBAL, n_globals, true);
  for (int k = 0; k < n_globals; ++k)
    EXPECT_EQ(names[k], columns[k].name);
  const auto rows = csv_rows(base + ".history.csv");
  const int n_steps = static_cast<int>(ex_inquire_int(exo, EX_INQ_TIME));
  for (int step = 1; step <= n_steps; ++step)
  {
    std::vector<double> globals(n_globals);
    ASSERT_GE(ex_get_var(exo, step, EX_GLOBAL, 1, 0, n_globals, globals.data()), 0);
    std::vector<std::string> expected;
    for (const auto &row : rows)
      if (row.front() == kiln::history_number(globals.front()))
        expected = row;
    ASSERT_EQ(static_cast<int>(expected.size()), n_globals) << "output step " << step;
    for (int k = 0; k < n_globals; ++k)
      EXPECT_EQ(kiln::history_number(globals[k]), expected[k])
          << columns[k].name << ", output step " << step;
  }
  const std::vector<std::string> set_names = {"x_min", "x_max", "y_min", "y_max",
                                              "z_min", "z_max", "gap"};
  EXPECT_EQ(exodus_names(exo, EX_SIDE_SET, 7, false), set_names);
  EXPECT_EQ(exodus_names(exo, EX_NODE_SET, 7, false), set_names);
}
} // namespace

TEST(OutputFormat, HdfAndExodusHoldTheSameSteps)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = "output_format_np" + std::to_string(comm->getSize()) + "/both";
  run(base, "HDF5 and Exodus");
  if (comm->getRank() != 0)
    return;
  ASSERT_TRUE(std::filesystem::exists(base + ".h5"));
  ASSERT_TRUE(std::filesystem::exists(base + ".xmf"));
  int cpu_ws = 8, io_ws = 0;
  float version = 0;
  const int exo = ex_open((base + ".exo").c_str(), EX_READ, &cpu_ws, &io_ws, &version);
  ASSERT_GE(exo, 0);
  ASSERT_EQ(ex_inquire_int(exo, EX_INQ_TIME), 2);
  std::vector<double> times(2);
  ex_get_all_times(exo, times.data());
  EXPECT_EQ(times[0], 0.0);
  EXPECT_EQ(times[1], 50.0);
  const int n_nodes = static_cast<int>(ex_inquire_int(exo, EX_INQ_NODES));
  int n_vars = 0;
  ex_get_variable_param(exo, EX_NODAL, &n_vars);
  std::vector<std::vector<char>> storage(n_vars, std::vector<char>(MAX_STR_LENGTH + 1));
  std::vector<char *> names;
  for (auto &s : storage)
    names.push_back(s.data());
  ex_get_variable_names(exo, EX_NODAL, n_vars, names.data());
  int found = 0;
  for (int v = 0; v < n_vars; ++v)
  {
    const std::string name = names[v];
    std::string field = name;
    int component = 0, n_components = 1;
    if (name.rfind("displacement_", 0) == 0)
    {
      field = "displacement";
      component = name.back() - 'x';
      n_components = 3;
    }
    for (const int step : {0, 1})
    {
      double time = 0.0;
      const std::vector<double> h5 = kiln_test::read_step(base + ".h5", field, step, time);
      ASSERT_EQ(static_cast<int>(h5.size()), n_components * n_nodes) << name;
      std::vector<double> values(n_nodes);
      ex_get_var(exo, step + 1, EX_NODAL, v + 1, 1, n_nodes, values.data());
      for (int n = 0; n < n_nodes; ++n)
      {
        const double expected = h5[n_components * n + component];
        if (std::isnan(expected))
          EXPECT_TRUE(std::isnan(values[n])) << name << " node " << n;
        else
          EXPECT_EQ(values[n], expected) << name << " node " << n << " step " << step;
      }
    }
    ++found;
  }
  // temperature, displacement_x/y/z, gap_opening, contact_pressure, contact_active,
  // gap_heat_flux
  EXPECT_EQ(found, 8);
  ex_get_variable_param(exo, EX_ELEM_BLOCK, &n_vars);
  // stress, strain, thermal_strain: 6 named components each; von_mises_stress, pressure;
  // principal_stress_1, _2, _3
  EXPECT_EQ(n_vars, 23);
  check_globals_and_set_names(exo, base);
  ex_close(exo);
}

TEST(OutputFormat, ExodusAloneWritesNoHdf)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = "output_format_np" + std::to_string(comm->getSize()) + "/exodus";
  run(base, "Exodus");
  if (comm->getRank() != 0)
    return;
  EXPECT_TRUE(std::filesystem::exists(base + ".exo"));
  EXPECT_FALSE(std::filesystem::exists(base + ".h5"));
  EXPECT_FALSE(std::filesystem::exists(base + ".xmf"));
}

/// Makes the results file `h5` as Kiln wrote it before changelog 0032: every
/// /steps/NNNNNN/contact_pressure becomes gap_normal_traction, negated.
void make_legacy_traction(const std::string &h5)
{
  const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  for (int s = 0;; ++s)
  {
    char name[64];
    std::snprintf(name, sizeof name, "/steps/%06d/contact_pressure", s);
    if (H5Lexists(file, "/steps", H5P_DEFAULT) <= 0 ||
        H5Oexists_by_name(file, name, H5P_DEFAULT) <= 0)
      break;
    const hid_t set = H5Dopen2(file, name, H5P_DEFAULT);
    const hid_t space = H5Dget_space(set);
    std::vector<double> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
    H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Dclose(set);
    for (double &v : values)
      v = -v;
    H5Ldelete(file, name, H5P_DEFAULT);
    std::snprintf(name, sizeof name, "/steps/%06d/gap_normal_traction", s);
    const hid_t legacy =
        H5Dcreate2(file, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(legacy, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Dclose(legacy);
    H5Sclose(space);
  }
  H5Fclose(file);
}

// A continued run's Exodus file holds the earlier run's steps (replayed from its HDF5 file
// before the history rows are read) with their global variables, then its own.
TEST(OutputFormat, ExodusContinuedByARestartKeepsTheGlobalVariables)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = "output_format_np" + std::to_string(comm->getSize()) + "/restart";
  run(base, "HDF5 and Exodus");
  run(base, "HDF5 and Exodus", base + ".checkpoint.h5");
  if (comm->getRank() != 0)
    return;
  int cpu_ws = 8, io_ws = 0;
  float version = 0;
  const int exo = ex_open((base + ".exo").c_str(), EX_READ, &cpu_ws, &io_ws, &version);
  ASSERT_GE(exo, 0);
  ASSERT_EQ(ex_inquire_int(exo, EX_INQ_TIME), 3);
  check_globals_and_set_names(exo, base);
  ex_close(exo);
}

// Results written before changelog 0032 (minus the pressure as gap_normal_traction) continue
// as contact_pressure: one field through the series, in the HDF5 and the Exodus file.
TEST(OutputFormat, RestartContinuesLegacyTractionAsContactPressure)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = "output_format_np" + std::to_string(comm->getSize()) + "/legacy";
  run(base, "HDF5 and Exodus");
  if (comm->getRank() == 0)
    make_legacy_traction(base + ".h5");
  comm->barrier();
  run(base, "HDF5 and Exodus", base + ".checkpoint.h5");
  if (comm->getRank() != 0)
    return;
  for (const int step : {0, 1, 2})
  {
    double time = 0.0;
    const std::vector<double> p =
        kiln_test::read_step(base + ".h5", "contact_pressure", step, time);
    ASSERT_FALSE(p.empty()) << "step " << step;
    for (const double v : p)
    {
      if (!std::isnan(v))
      {
        EXPECT_GE(v, 0.0) << "step " << step;
      }
    }
  }
  int cpu_ws = 8, io_ws = 0;
  float version = 0;
  const int exo = ex_open((base + ".exo").c_str(), EX_READ, &cpu_ws, &io_ws, &version);
  ASSERT_GE(exo, 0);
  EXPECT_EQ(ex_inquire_int(exo, EX_INQ_TIME), 3);
  ex_close(exo);
}
