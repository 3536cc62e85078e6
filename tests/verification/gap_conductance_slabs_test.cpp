// Steady conduction through two slabs joined by a gap conductance (the contact-box mesh
// shape, rotated, split at side set 10): T1 on face 1, T2 on face 2, insulated elsewhere.
// The flux is q = (T1 - T2) / (L/k + 1/h) and the jump across the gap q/h; the temperature
// is linear in each slab, which Q1 represents exactly, so the computed jump at every gap
// node pair matches the analytic one to the solver tolerance (1e-10 relative).
// KILN_TEST_NP: 1 2
#include "support/simulation_runs.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

namespace
{
const std::string deck = R"xml(<ParameterList name="Kiln">
  <ParameterList name="Mesh">
    <Parameter name="Gap Side Set" type="int" value="10"/>
    <ParameterList name="Box">
      <Parameter name="Size" type="Array(double)" value="{0.04, 0.02, 0.01}"/>
      <Parameter name="Cells" type="Array(int)" value="{6, 3, 2}"/>
      <Parameter name="Phi" type="double" value="45"/>
      <Parameter name="Theta" type="double" value="-30"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Thermal">
    <Parameter name="Gap Conductance" type="double" value="1.0e4"/>
    <ParameterList name="Boundary Conditions">
      <ParameterList name="hot">
        <Parameter name="Type" type="string" value="Temperature"/>
        <Parameter name="Side Sets" type="Array(int)" value="{1}"/>
        <ParameterList name="Temperature">
          <Parameter name="Value" type="double" value="310"/>
        </ParameterList>
      </ParameterList>
      <ParameterList name="cold">
        <Parameter name="Type" type="string" value="Temperature"/>
        <Parameter name="Side Sets" type="Array(int)" value="{2}"/>
        <ParameterList name="Temperature">
          <Parameter name="Value" type="double" value="290"/>
        </ParameterList>
      </ParameterList>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Time Stepping">
    <Parameter name="Method" type="string" value="Steady"/>
  </ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Absolute Tolerance" type="double" value="1e-11"/>
    <Parameter name="Relative Tolerance" type="double" value="1e-14"/>
  </ParameterList>
</ParameterList>)xml";
} // namespace

TEST(GapConductance, TwoSlabJumpMatchesAnalytic)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto sim = kiln_test::make_simulation(deck, comm);
  kiln::CoupledProblem &problem = sim->problem();
  kiln_test::Vector x(problem.solution_map());
  problem.initial_condition(0.0, x);
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
