// The contact conductance of a closed contact pair in a whole run (issue 30, item 3; doc/contact.md
// "Heat across a pair"): two blocks meshed apart, body 1 on [0, 1]^2 x [0, 1] m with 3 x 3 x 3
// cells and body 2 on [0, 1]^2 x [1, 2] m with 4 x 2 x 5 cells (the touching faces do not
// match), the pair "cut" with body 2's bottom the secondary side; E = 200 GPa, nu = 0.3, no
// thermal expansion, k = 20 W/(m K); body 1's bottom held at u_z = 0 and 400 K, body 2's top
// pushed down by 2e-5 m and held at 300 K, sides free ("Free Motions" "Minimum Norm"). A steady
// thermo-elastic run. The pair's Heat Transfer is the contact conductance alone, "Gap Pressure
// Coefficient" h_p = 1e-3 W/(m^2 K Pa): the uniaxial stress P = E 2e-5 / 2 = 2e6 Pa in both
// blocks, so h = h_p P = 2000 W/(m^2 K) and, in series with the blocks, q = 100 K / (2/k + 1/h)
// = 995.024876 W/m^2 and the temperature jump q/h = 0.497512 K. The discrete solution is exact
// (uniform stress, temperature linear in each block; the mortar pairing passes the patch test):
// the temperature of every node, the jump, the heat flow across the pair (its history's
// heat_flow_cut, secondary to primary: -q A) and its normal force against the closed forms to
// 1e-9 (measured 6.7e-13 at np 1, 4.7e-13 at np 2: the Newton tolerance's level; the figure is
// the tightest the solve allows, not a bound of the method).
// With the term off (h_p = 0, and the pair's "Conductance" 2000 W/(m^2 K) in its place) the
// same figures: the contact term and a constant conductance of the same value agree.
// KILN_TEST_NP: 1 2
#include "support/parameter_lists.hpp"
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
constexpr double youngs = 2.0e11, push = 2.0e-5, k = 20.0, h_p = 1.0e-3;
constexpr double T_bottom = 400.0, T_top = 300.0;

/// The two blocks' deck on the Exodus file `mesh_file`, the pair "cut" with the Heat Transfer
/// list `heat`.
Teuchos::ParameterList deck(const std::string &mesh_file, const Teuchos::ParameterList &heat)
{
  using namespace kiln_test;
  Teuchos::ParameterList input = steady_deck("Thermo-Elasticity", exodus_mesh(mesh_file));
  input.set("Material", young(youngs, 0.3));
  input.sublist("Material").set("Thermal Expansion", 0.0).set("Conductivity", k);
  thermal_conditions(input).set("bottom", temperature({3}, T_bottom));
  thermal_conditions(input).set("top", temperature({4}, T_top));
  input.sublist("Mechanics").set("Free Motions", "Minimum Norm");
  mechanical_conditions(input).set("bottom", displacement({3}, {"z"}));
  mechanical_conditions(input).set("top", displacement({4}, {"z"}, -push));
  contact_pairs(input).set("cut", contact_pair(1, 2)).sublist("cut").set("Heat Transfer", heat);
  return input;
}

/// The two blocks: body 1 (block 1, bottom side set 3, top 1), body 2 (block 2, bottom 2, top 4).
kiln::Mesh blocks()
{
  const auto box = [](const double z0)
  {
    return [z0](const double a, const double b, const double c) {
      return kiln::Point{a, b, z0 + c};
    };
  };
  kiln::Mesh mesh;
  kiln_test::add_body(mesh, {3, 3, 3}, box(0.0), 1, 3, 1);
  kiln_test::add_body(mesh, {4, 2, 5}, box(1.0), 2, 2, 4);
  return mesh;
}

/// Runs the deck with the Heat Transfer list `heat`; the largest relative error of the nodes'
/// temperatures, the heat flow and the normal force against the closed forms.
double run(const std::string &label, const Teuchos::ParameterList &heat)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = kiln_test::temporary_base("pair_contact_conductance", *comm);
  const std::string file = kiln_test::write_mesh_file(blocks(), base, *comm);
  const double P = youngs * push / 2.0; // uniaxial stress over the two blocks' 2 m
  const double h = h_p * P;
  const double q = (T_bottom - T_top) / (2.0 / k + 1.0 / h);
  double worst = 0.0;
  {
    const auto sim = kiln_test::make_simulation(deck(file, heat), comm);
    kiln::CoupledProblem &problem = sim->problem();
    kiln_test::Vector x = kiln_test::initial_state(*sim);
    kiln_test::run_from(*sim, x, {0.0});
    const std::vector<double> T = kiln_test::all_node_values(*sim, x);
    double jump_1 = 0.0, jump_2 = 0.0; // the mean temperatures of the two faces at z = 1
    int n_1 = 0, n_2 = 0;
    for (int n = 0; n < sim->mesh().n_nodes(); ++n)
    {
      const kiln::Point &X = sim->mesh().coordinates[n];
      const bool upper = n >= 4 * 4 * 4; // body 2's nodes follow body 1's 4 x 4 x 4
      const double expected =
          upper ? T_bottom - q / k - q / h - q * (X[2] - 1.0) / k : T_bottom - q * X[2] / k;
      worst = std::max(worst, std::abs(T[n] - expected) / (T_bottom - T_top));
      if (std::abs(X[2] - 1.0) < 1e-12)
        (upper ? jump_2 : jump_1) += T[n], ++(upper ? n_2 : n_1);
    }
    const double jump = jump_1 / n_1 - jump_2 / n_2;
    worst = std::max(worst, std::abs(jump - q / h) / (q / h));
    const double flow = problem.pair_heat_flow(x).at(0);
    // From the secondary (body 2, cooler) to the primary side: -q A.
    worst = std::max(worst, std::abs(flow + q) / q);
    const kiln::StateSummary summary = problem.summary(x);
    const double force = summary.pairs.at(0).normal_force;
    worst = std::max(worst, std::abs(force - P) / P);
    if (comm->getRank() == 0)
      std::printf("%s (np %d): jump %.9f K (q/h %.9f K), heat flow %.9f W (-q A %.9f W), normal "
                  "force %.6f N (P A %.6f N); largest relative error %.3e\n",
                  label.c_str(), comm->getSize(), jump, q / h, flow, -q, force, P, worst);
  }
  kiln_test::remove_results(base, *comm);
  return worst;
}
} // namespace

TEST(PairContactConductance, ClosedPairJumpIsFluxOverConductance)
{
  Teuchos::ParameterList heat;
  heat.set("Gap Pressure Coefficient", h_p);
  EXPECT_LT(run("contact conductance h_p P", heat), 1e-9);
}

TEST(PairContactConductance, SameAsAConstantConductanceOfTheSameValue)
{
  Teuchos::ParameterList heat;
  heat.set("Conductance", 2000.0);
  EXPECT_LT(run("constant conductance 2000", heat), 1e-9);
}
