// Steady conduction through two slabs joined by a gap conductance (the contact-box mesh
// shape, rotated, split at side set 10): T1 on face 1, T2 on face 2, insulated elsewhere.
// The flux is q = (T1 - T2) / (L/k + 1/h) and the jump across the gap q/h; the temperature
// is linear in each slab, which Q1 represents exactly, so the computed jump at every gap
// node pair matches the analytic one to the solver tolerance (1e-10 relative).
// KILN_TEST_NP: 1 2
#include "support/parameter_lists.hpp"
#include "support/simulation_runs.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

namespace
{
/// The contact box's shape on 6 x 3 x 2 cells, split at side set 10 with h = 1e4 W/(m^2 K),
/// 310 K on face 1 and 290 K on face 2; Newton to 1e-11 absolute, 1e-14 relative.
Teuchos::ParameterList deck()
{
  Teuchos::ParameterList mesh = kiln_test::box_mesh({0.04, 0.02, 0.01}, {6, 3, 2}, 10);
  mesh.sublist("Box").set("Phi", 45.0).set("Theta", -30.0);
  Teuchos::ParameterList input = kiln_test::steady_deck("", mesh);
  input.sublist("Thermal").set("Gap Conductance", 1.0e4);
  kiln_test::thermal_conditions(input).set("hot", kiln_test::temperature({1}, 310.0));
  kiln_test::thermal_conditions(input).set("cold", kiln_test::temperature({2}, 290.0));
  input.set("Solver", kiln_test::newton_tolerances(1e-11, 1e-14));
  return input;
}
} // namespace

TEST(GapConductance, TwoSlabJumpMatchesAnalytic)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto sim = kiln_test::make_simulation(deck(), comm);
  kiln_test::Vector x = kiln_test::initial_state(*sim);
  const auto stats = kiln_test::run_from(*sim, x, {1.0});
  ASSERT_EQ(stats.steps, 1);

  // Material defaults: aluminium, k = 240 W/(m K).
  const double k = 240.0, h = 1.0e4, L = 0.04;
  const double q = (310.0 - 290.0) / (L / k + 1.0 / h);
  const double jump = q / h;
  const std::vector<double> T = kiln_test::all_node_values(*sim, x);
  ASSERT_EQ(sim->mesh().gap_pairs.size(), 12u);
  for (const auto &pair : sim->mesh().gap_pairs)
  {
    // Side a is block 1 (x' < 0), next to the hot face 1.
    EXPECT_NEAR(T[pair.node_a] - T[pair.node_b], jump, 1e-10 * jump)
        << "pair " << pair.node_a << "-" << pair.node_b;
    // And each side is at its analytic temperature: 310 - q (L/2) / k on side a.
    EXPECT_NEAR(T[pair.node_a], 310.0 - q * (L / 2) / k, 1e-10 * 310.0);
  }
}
