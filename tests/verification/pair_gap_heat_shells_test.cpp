// The heat across the gas gap of a contact pair in a whole run (issue 30, step 6; doc/heat.md
// "Concentric cylinders with a gas gap: the steady solution"): two cylindrical shell arcs about
// the z axis meshed apart (1 rad, 1 m high), the inner one on [1.5, 2] m, the outer one on
// [2.05, 2.5] m, k = 20 W/(m K), T = 600 K on r = 1.5 and 300 K on r = 2.5, insulated elsewhere;
// the pair "gap" (Mechanics/Contact/Pairs) with the inner shell's outer face the secondary side
// and Heat Transfer/Gas Conductivity 0.2 W/(m K), Jump Distance 1e-3 m; no thermal expansion,
// both shells held at their fixed faces, so the gap stays 5 cm open. A steady thermo-elastic
// run (Mesh from an Exodus file this test writes). The heat flow across the pair
// (CoupledProblem::pair_heat_flow) against the analytic Q = 1976.198005 W, and the mean
// temperatures of the two gap faces' nodes against T_1 = 571.574163 K and T_2 = 319.608917 K
// (jump 251.965246 K), on 8 x 2, 16 x 4 and 32 x 8 cells (angle x radius) in the inner shell,
// 3/2 as many around the outer one: the error of Q falls by about 4 per level (second order,
// as unit_mortar_gap_heat's ConcentricShellsSteadyState on the same meshes: 2.29e-2, 5.92e-3,
// 1.49e-3). The same on 1 and 2 ranks.
// The field gap_heat_flux on the pair's secondary surface (a whole run to HDF5, XDMF, the CSV
// table and Exodus, 16 x 4 cells): at every node of r = r_1, no NaN, the analytic flux
// q = Q / (r_1 * 1 rad * 1 m) within 1e-2 (measured 5.8e-3 at most, as Q's error on this mesh), the
// same in the four outputs, and its sum weighted by the nodes' areas (/pair_gap/area) the history's
// heat_flow_gap to 1e-12.
// KILN_TEST_NP: 1 2
#include "app/simulation.hpp"
#include "support/parameter_lists.hpp"
#include "support/results_files.hpp"
#include "support/simulation_runs.hpp"
#include "support/two_body_mesh.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <exodusII.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace
{
const double r_a = 1.5, r_1 = 2.0, r_2 = 2.05, r_b = 2.5;
const double Q_exact = 1976.198005, T1_exact = 571.574163, T2_exact = 319.608917;

/// The shells' deck on the Exodus file `mesh_file`.
Teuchos::ParameterList deck(const std::string &mesh_file)
{
  using namespace kiln_test;
  Teuchos::ParameterList input = steady_deck("Thermo-Elasticity", exodus_mesh(mesh_file));
  input.sublist("Material").set("Thermal Expansion", 0.0).set("Conductivity", 20.0);
  thermal_conditions(input).set("inner", temperature({3}, 600.0));
  thermal_conditions(input).set("outer", temperature({4}, 300.0));
  mechanical_conditions(input).set("held", displacement({3, 4}, {"x", "y", "z"}));
  Teuchos::ParameterList &gap = contact_pairs(input).set("gap", contact_pair(2, 1)).sublist("gap");
  gap.set("Search Distance", 0.1);
  gap.sublist("Heat Transfer").set("Gas Conductivity", 0.2).set("Jump Distance", 1e-3);
  return input;
}

/// The two shells, n_angle x 1 x n_radial cells in the inner one, 3/2 as many around the outer.
kiln::Mesh shells(const int n_angle, const int n_radial)
{
  const auto shell = [](const double r0, const double r1)
  {
    return [r0, r1](const double a, const double z, const double r)
    {
      const double radius = r0 + (r1 - r0) * r;
      return kiln::Point{radius * std::cos(a), radius * std::sin(a), z};
    };
  };
  kiln::Mesh mesh;
  kiln_test::add_body(mesh, {n_angle, 1, n_radial}, shell(r_a, r_1), 1, 3, 1);
  kiln_test::add_body(mesh, {n_angle + n_angle / 2, 1, n_radial}, shell(r_2, r_b), 2, 2, 4);
  return mesh;
}

struct Figures
{
  double Q = 0.0;  ///< [W]
  double T1 = 0.0; ///< mean over the nodes of r = r_1 [K]
  double T2 = 0.0; ///< mean over the nodes of r = r_2 [K]
};

Figures run(const int n_angle, const int n_radial)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base =
      kiln_test::temporary_base("pair_gap_heat_shells_" + std::to_string(n_angle), *comm);
  const std::string file = kiln_test::write_mesh_file(shells(n_angle, n_radial), base, *comm);
  Figures f;
  {
    const auto sim = kiln_test::make_simulation(deck(file), comm);
    kiln::CoupledProblem &problem = sim->problem();
    kiln_test::Vector x = kiln_test::initial_state(*sim);
    const auto stats = kiln_test::run_from(*sim, x, {0.0});
    EXPECT_GE(stats.steps, 0);
    const std::vector<double> flow = problem.pair_heat_flow(x);
    EXPECT_EQ(flow.size(), 1u);
    f.Q = flow.at(0);
    // The history's heat_flow_<pair> column (StateSummary::pairs) is the same figure.
    const kiln::StateSummary summary = problem.summary(x);
    EXPECT_EQ(summary.pairs.size(), 1u);
    EXPECT_DOUBLE_EQ(summary.pairs.at(0).heat_flow, f.Q);
    const std::vector<double> T = kiln_test::all_node_values(*sim, x);
    int n1 = 0, n2 = 0;
    for (int n = 0; n < sim->mesh().n_nodes(); ++n)
    {
      const kiln::Point &X = sim->mesh().coordinates[n];
      const double r = std::hypot(X[0], X[1]);
      if (std::abs(r - r_1) < 1e-9)
      {
        f.T1 += T[n];
        ++n1;
      }
      if (std::abs(r - r_2) < 1e-9)
      {
        f.T2 += T[n];
        ++n2;
      }
    }
    f.T1 /= n1;
    f.T2 /= n2;
  }
  kiln_test::remove_results(base, *comm);
  return f;
}
} // namespace

TEST(PairGapHeat, ConcentricShellsGasGapConverges)
{
  std::vector<double> error_Q, error_jump;
  for (const auto &[n_angle, n_radial] : {std::pair{8, 2}, std::pair{16, 4}, std::pair{32, 8}})
  {
    const Figures f = run(n_angle, n_radial);
    error_Q.push_back(std::abs(f.Q - Q_exact) / Q_exact);
    const double jump_exact = T1_exact - T2_exact;
    error_jump.push_back(std::abs((f.T1 - f.T2) - jump_exact) / jump_exact);
    std::printf("%2d x %d cells: Q = %.6f W (error %.3e), T_1 = %.6f K, T_2 = %.6f K, jump %.6f K "
                "(error %.3e)\n",
                n_angle, n_radial, f.Q, error_Q.back(), f.T1, f.T2, f.T1 - f.T2, error_jump.back());
  }
  // Second order: a factor of about 4 per level (the faceted gap's error dominates).
  for (std::size_t k = 1; k < error_Q.size(); ++k)
  {
    EXPECT_GT(error_Q[k - 1] / error_Q[k], 3.5) << "level " << k;
    EXPECT_GT(error_jump[k - 1] / error_jump[k], 3.0) << "level " << k;
  }
  EXPECT_LT(error_Q.back(), 2e-3);
  EXPECT_LT(error_jump.back(), 2e-3);
}

namespace
{
/// The nodal variable `name` of an Exodus results file at step `step` (1-based), per node.
std::vector<double> exodus_node_variable(const std::string &path, const std::string &name,
                                         const int step)
{
  int cpu_ws = 8, io_ws = 0;
  float version = 0;
  const int exo = ex_open(path.c_str(), EX_READ, &cpu_ws, &io_ws, &version);
  EXPECT_GE(exo, 0) << path;
  if (exo < 0)
    return {};
  const auto n_nodes = static_cast<int>(ex_inquire_int(exo, EX_INQ_NODES));
  int n_vars = 0;
  ex_get_variable_param(exo, EX_NODAL, &n_vars);
  std::vector<std::vector<char>> storage(n_vars, std::vector<char>(MAX_STR_LENGTH + 1));
  std::vector<char *> names;
  for (auto &s : storage)
    names.push_back(s.data());
  ex_get_variable_names(exo, EX_NODAL, n_vars, names.data());
  std::vector<double> values;
  for (int v = 0; v < n_vars; ++v)
    if (name == names[v])
    {
      values.resize(n_nodes);
      ex_get_var(exo, step, EX_NODAL, v + 1, 1, n_nodes, values.data());
    }
  ex_close(exo);
  EXPECT_FALSE(values.empty()) << path << ": no nodal variable " << name;
  return values;
}
} // namespace

TEST(PairGapHeat, ConcentricShellsGapHeatFluxOutput)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = kiln_test::temporary_base("pair_gap_heat_flux", *comm);
  const std::string file = kiln_test::write_mesh_file(shells(16, 4), base, *comm);
  Teuchos::ParameterList input = deck(file);
  input.sublist("Output").set("File Base", base).set("Format", "HDF5 and Exodus");
  {
    kiln::Simulation sim(input, "pair_gap_heat_flux.xml", comm);
    sim.run();
  }
  comm->barrier();
  if (comm->getRank() == 0)
  {
    const std::string h5 = base + ".h5";
    const std::vector<double> nodes = kiln_test::read_dataset(h5, "/pair_gap/node_a");
    const std::vector<double> area = kiln_test::read_dataset(h5, "/pair_gap/area");
    const std::vector<double> flux =
        kiln_test::read_dataset(h5, "/pair_gap/steps/000000/gap_heat_flux");
    double time = 0.0;
    const std::vector<double> node_flux = kiln_test::read_step(h5, "gap_heat_flux", 0, time);
    const std::vector<double> csv =
        kiln_test::csv_column(base + ".pair_gap-000000.csv", "gap_heat_flux");
    const std::vector<double> exodus = exodus_node_variable(base + ".exo", "gap_heat_flux", 1);
    const std::vector<double> Q = kiln_test::read_dataset(h5, "/history/heat_flow_gap");
    ASSERT_EQ(nodes.size(), 17u * 2u) << "the nodes of r = r_1";
    ASSERT_EQ(flux.size(), nodes.size());
    ASSERT_EQ(area.size(), nodes.size());
    ASSERT_EQ(csv.size(), nodes.size());
    ASSERT_FALSE(Q.empty());
    const double q_exact = Q_exact / r_1; // over 1 rad and 1 m
    double sum = 0.0, worst = 0.0;
    for (std::size_t p = 0; p < nodes.size(); ++p)
    {
      const auto n = static_cast<std::size_t>(nodes[p]);
      ASSERT_FALSE(std::isnan(flux[p])) << "node " << n;
      worst = std::max(worst, std::abs(flux[p] - q_exact) / q_exact);
      sum += flux[p] * area[p];
      EXPECT_EQ(node_flux.at(n), flux[p]) << "the node field at node " << n;
      EXPECT_EQ(csv[p], flux[p]) << "the CSV table at node " << n;
      EXPECT_EQ(exodus.at(n), flux[p]) << "Exodus at node " << n;
    }
    std::printf("gap_heat_flux on pair_gap (16 x 4 cells): |q - Q/(r_1 1 rad 1 m)| / q up to "
                "%.3e; sum of q A %.9f W, heat_flow_gap %.9f W\n",
                worst, sum, Q.back());
    EXPECT_LT(worst, 1e-2);
    EXPECT_NEAR(sum, Q.back(), 1e-12 * Q.back());
    std::ifstream xmf(base + ".xmf");
    const std::string xdmf((std::istreambuf_iterator<char>(xmf)), std::istreambuf_iterator<char>());
    EXPECT_NE(xdmf.find("/pair_gap/steps/000000/gap_heat_flux"), std::string::npos)
        << "the XDMF grid's attribute";
  }
  kiln_test::remove_results(base, *comm);
}
