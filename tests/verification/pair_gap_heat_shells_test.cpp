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
// KILN_TEST_NP: 1 2
#include "mesh/exodus_io.hpp"
#include "support/results_files.hpp"
#include "support/simulation_runs.hpp"
#include "support/two_body_mesh.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
const double r_a = 1.5, r_1 = 2.0, r_2 = 2.05, r_b = 2.5;
const double Q_exact = 1976.198005, T1_exact = 571.574163, T2_exact = 319.608917;

const std::string deck = R"xml(<ParameterList name="Kiln">
  <Parameter name="Physics" type="string" value="Thermo-Elasticity"/>
  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="Exodus"/>
    <Parameter name="Gap Side Set" type="int" value="0"/>
    <ParameterList name="Exodus">
      <Parameter name="File" type="string" value="@FILE@"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Material">
    <Parameter name="Thermal Expansion" type="double" value="0"/>
    <Parameter name="Conductivity" type="double" value="20"/>
  </ParameterList>
  <ParameterList name="Thermal">
    <ParameterList name="Boundary Conditions">
      <ParameterList name="inner">
        <Parameter name="Type" type="string" value="Temperature"/>
        <Parameter name="Side Sets" type="Array(int)" value="{3}"/>
        <ParameterList name="Temperature">
          <Parameter name="Value" type="double" value="600"/>
        </ParameterList>
      </ParameterList>
      <ParameterList name="outer">
        <Parameter name="Type" type="string" value="Temperature"/>
        <Parameter name="Side Sets" type="Array(int)" value="{4}"/>
        <ParameterList name="Temperature">
          <Parameter name="Value" type="double" value="300"/>
        </ParameterList>
      </ParameterList>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Mechanics">
    <ParameterList name="Boundary Conditions">
      <ParameterList name="held">
        <Parameter name="Type" type="string" value="Displacement"/>
        <Parameter name="Side Sets" type="Array(int)" value="{3, 4}"/>
        <Parameter name="Components" type="Array(string)" value="{x, y, z}"/>
      </ParameterList>
    </ParameterList>
    <ParameterList name="Contact">
      <ParameterList name="Pairs">
        <ParameterList name="gap">
          <Parameter name="Primary Side Set" type="int" value="2"/>
          <Parameter name="Secondary Side Set" type="int" value="1"/>
          <Parameter name="Search Distance" type="double" value="0.1"/>
          <ParameterList name="Heat Transfer">
            <Parameter name="Gas Conductivity" type="double" value="0.2"/>
            <Parameter name="Jump Distance" type="double" value="1e-3"/>
          </ParameterList>
        </ParameterList>
      </ParameterList>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Time Stepping">
    <Parameter name="Method" type="string" value="Steady"/>
  </ParameterList>
</ParameterList>)xml";

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
  const std::string file = base + ".exo";
  if (comm->getRank() == 0)
    kiln::write_exodus_mesh(shells(n_angle, n_radial), file);
  comm->barrier();
  std::string xml = deck;
  kiln_test::replace(xml, "@FILE@", file);
  Figures f;
  {
    const auto sim = kiln_test::make_simulation(xml, comm);
    kiln::CoupledProblem &problem = sim->problem();
    kiln_test::Vector x(problem.solution_map());
    problem.initial_condition(0.0, x);
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
  if (comm->getRank() == 0)
    std::remove(file.c_str());
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
