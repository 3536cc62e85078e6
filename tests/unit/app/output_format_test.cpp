// Tests Kiln/Output/"Format" (app/simulation): a run with "HDF5 and Exodus" writes both files,
// with the same times and the same nodal values; "Exodus" alone writes no .h5.
// KILN_TEST_NP: 1 2
#include "app/simulation.hpp"
#include "io/input_reader.hpp"
#include "support/results_files.hpp"
#include "support/simulation_runs.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_Tuple.hpp>
#include <exodusII.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace
{
using kiln_test::inputs;

/// Runs the closing contact box to 50 s with output at 0 and 50 s in `format`.
void run(const std::string &base, const std::string &format)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string deck = inputs + "contact-box-close.xml";
  Teuchos::ParameterList input = kiln::read_input(deck, *comm);
  Teuchos::ParameterList &output = input.sublist("Output");
  output.set("Times", Teuchos::Array<double>(Teuchos::tuple(0.0, 50.0)));
  output.set("File Base", base);
  output.set("Format", format);
  kiln::Simulation sim(input, deck, comm);
  sim.run();
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
  // temperature, displacement_x/y/z, gap_opening, gap_normal_traction, contact_active,
  // gap_heat_flux
  EXPECT_EQ(found, 8);
  ex_get_variable_param(exo, EX_ELEM_BLOCK, &n_vars);
  // stress, strain, thermal_strain: 6 named components each; von_mises_stress, pressure;
  // principal_stress_1, _2, _3
  EXPECT_EQ(n_vars, 23);
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
