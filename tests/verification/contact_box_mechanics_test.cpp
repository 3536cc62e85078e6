// The mechanics of the contact box against the analytic open-gap state of
// ../shared/spec/contact-box.md, and the elastic-cube benchmark:
// - uniform temperature, open gap (contact on, as by default): every cell's stress, strain and
//   thermal strain, every node's displacement and the gap opening at every gap node (read back
//   from the HDF5 output) are the spec's uniform state to 1e-9 relative, and every gap node is
//   out of contact (contact_active 0, contact_pressure 0; NaN off the gap), on the generated
//   rotated box, on the Cubit mesh rotated-cube.exo and on another rotation, size, cell count and
//   material; the spec's table (7 digits) agrees to 1e-6;
// - inputs/contact-box-open.xml as it is ends at 150 s in that state, to the accuracy its
//   temperature (not quite uniform at 150 s) allows;
// - inputs/elastic-cube.xml with 20^3 cells: the largest displacement component is 5.82106;
// - np 1 and np 2 give the same contact-box-open states at every output time.
// KILN_TEST_NP: 1 2
#include "io/input_reader.hpp"
#include "support/contact_box.hpp"
#include "support/parallel.hpp"
#include "support/results_files.hpp"
#include "support/simulation_runs.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace
{
using namespace kiln_test;
using kiln::Point;

/// The spec's material (lambda 5.2e10, G 2.6e10, alpha 2.2e-5, T_ref 298) at 288 K, phi 45,
/// theta -30, half width 2 cm, by the formulas.
UniformState spec_open_gap_state()
{
  return open_gap_state(spec_E, spec_nu, spec_alpha, 288.0 - spec_T_ref, 0.02, 45.0, -30.0);
}

/// The "open, dT = -10" column of the spec's table (7 significant digits). The thermal
/// strain (alpha dT) and the displacement field are not in the table: the formula's.
UniformState spec_table_open_gap_state()
{
  UniformState s = spec_open_gap_state(); // A and the box-frame strains
  s.stress = {7.626667e6, 1.906667e6, 5.72e6, 3.813333e6, 6.604887e6, 3.302444e6};
  s.strain = {-1.466667e-4, -2.566667e-4, -1.833333e-4, 7.333333e-5, 1.270171e-4, 6.350853e-5};
  s.thermal_strain = {-2.2e-4, -2.2e-4, -2.2e-4, 0.0, 0.0, 0.0};
  s.gap_opening = 1.173333e-5;
  return s;
}

/// Runs the input (a Thermo-Elasticity deck whose results go to `base`) and checks the
/// final state: the temperature T at every node to within T_tolerance [K], and against
/// each reference the cell stress, strain and thermal strain, the node displacements and
/// the gap opening of the output file at every gap node.
void run_and_check_open_gap(const std::string &label, const Teuchos::ParameterList &input,
                            const std::string &base, const double T, const double T_tolerance,
                            const std::vector<Reference> &references)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  std::size_t n_gap_pairs = 0;
  {
    kiln::Simulation sim(input, label, comm);
    sim.run();
    kiln::CoupledProblem &problem = sim.problem();
    const kiln::Mesh &mesh = sim.mesh();
    n_gap_pairs = mesh.gap_pairs.size();
    EXPECT_GT(n_gap_pairs, 0u) << label;

    const auto temperatures = problem.node_temperatures(sim.solution());
    double T_deviation = 0.0;
    for (const double t : temperatures)
      T_deviation = std::max(T_deviation, std::abs(t - T));
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, T_deviation, Teuchos::outArg(T_deviation));
    rank0_out() << label << ": max |T - " << T << "| = " << T_deviation << " K\n";
    EXPECT_LE(T_deviation, T_tolerance) << label;

    const auto cells = problem.cell_averages(sim.solution());
    const auto u = problem.node_displacements(sim.solution());
    const auto &owned_cells = sim.dofs().owned_cells();
    const auto &owned_nodes = sim.dofs().owned_nodes();
    int n_checked[2] = {static_cast<int>(cells.size()), static_cast<int>(u.size())};
    int n_total[2] = {0, 0};
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 2, n_checked, n_total);
    EXPECT_EQ(n_total[0], mesh.n_cells()) << label;
    EXPECT_EQ(n_total[1], mesh.n_nodes()) << label;

    for (const Reference &ref : references)
    {
      const double tol = ref.tolerance;
      Deviation stress, strain, thermal_strain;
      for (std::size_t i = 0; i < cells.size(); ++i)
        for (int k = 0; k < 6; ++k)
        {
          EXPECT_TRUE(
              stress.check(cells[i].stress[k], ref.state.stress[k], tol, zero_stress_tolerance))
              << label << " vs " << ref.name << ": cell " << owned_cells[i] << " stress "
              << voigt_name[k] << " = " << cells[i].stress[k] << ", expected "
              << ref.state.stress[k];
          EXPECT_TRUE(
              strain.check(cells[i].strain[k], ref.state.strain[k], tol, zero_strain_tolerance))
              << label << " vs " << ref.name << ": cell " << owned_cells[i] << " strain "
              << voigt_name[k] << " = " << cells[i].strain[k] << ", expected "
              << ref.state.strain[k];
          EXPECT_TRUE(thermal_strain.check(cells[i].thermal_strain[k], ref.state.thermal_strain[k],
                                           tol, zero_strain_tolerance))
              << label << " vs " << ref.name << ": cell " << owned_cells[i] << " thermal strain "
              << voigt_name[k] << " = " << cells[i].thermal_strain[k] << ", expected "
              << ref.state.thermal_strain[k];
        }
      // Displacements vary from 0 at the fixed corner: tolerance relative to the largest.
      const auto u_exact = exact_displacements(mesh, ref.state);
      double u_scale = 0.0;
      for (const Point &v : u_exact)
        for (const double vd : v)
          u_scale = std::max(u_scale, std::abs(vd));
      double u_error = 0.0;
      for (std::size_t i = 0; i < u.size(); ++i)
        for (int d = 0; d < 3; ++d)
        {
          const double e = std::abs(u[i][d] - u_exact[owned_nodes[i]][d]);
          u_error = std::max(u_error, e);
          EXPECT_LE(e, tol * u_scale)
              << label << " vs " << ref.name << ": node " << owned_nodes[i] << " u_" << d << " = "
              << u[i][d] << ", expected " << u_exact[owned_nodes[i]][d];
        }
      stress.reduce(*comm);
      strain.reduce(*comm);
      thermal_strain.reduce(*comm);
      Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, u_error, Teuchos::outArg(u_error));
      rank0_out() << label << " vs " << ref.name << " (tolerance " << tol
                  << "): max relative deviation of stress " << stress.relative << ", strain "
                  << strain.relative << ", thermal strain " << thermal_strain.relative
                  << " (absolute where 0: " << thermal_strain.absolute_at_zero
                  << "); max |u - u_exact| / max |u_exact| = " << u_error / u_scale << "\n";
    }
  } // the Simulation closes its output file here

  comm->barrier();
  if (comm->getRank() == 0)
  {
    double time = -1.0;
    const auto opening = read_last_step(base + ".h5", "gap_opening", time);
    std::size_t n_gap_nodes = 0;
    for (const double g : opening)
      n_gap_nodes += std::isnan(g) ? 0 : 1;
    EXPECT_EQ(n_gap_nodes, 2 * n_gap_pairs) << label << ": gap nodes in the output";
    for (const Reference &ref : references)
    {
      Deviation gap;
      for (std::size_t n = 0; n < opening.size(); ++n)
      {
        if (!std::isnan(opening[n]))
        {
          EXPECT_TRUE(gap.check(opening[n], ref.state.gap_opening, ref.tolerance, 0.0))
              << label << " vs " << ref.name << ": node " << n << " gap opening " << opening[n]
              << " m, expected " << ref.state.gap_opening;
        }
      }
      rank0_out() << label << " vs " << ref.name << ": output at t = " << time << " s, "
                  << n_gap_nodes << " gap nodes, max relative deviation of the gap opening "
                  << gap.relative << "\n";
    }
    // Contact is on (the default): every pair is open, without traction; NaN off the gap.
    const auto traction = read_last_step(base + ".h5", "contact_pressure", time);
    const auto active = read_last_step(base + ".h5", "contact_active", time);
    ASSERT_EQ(traction.size(), opening.size()) << label;
    ASSERT_EQ(active.size(), opening.size()) << label;
    for (std::size_t n = 0; n < opening.size(); ++n)
    {
      if (std::isnan(opening[n]))
      {
        EXPECT_TRUE(std::isnan(traction[n])) << label << ": node " << n << " off the gap";
        EXPECT_TRUE(std::isnan(active[n])) << label << ": node " << n << " off the gap";
      }
      else
      {
        EXPECT_EQ(traction[n], 0.0) << label << ": gap node " << n << " normal traction";
        EXPECT_EQ(active[n], 0.0) << label << ": gap node " << n << " contact_active";
      }
    }
  }
  remove_results(base, *comm);
}
} // namespace

TEST(ContactBoxMechanics, SpecTableIsTheOpenGapFormula)
{
  // The table has 7 significant digits: it and the formulas agree to its precision.
  const UniformState formula = spec_open_gap_state(), table = spec_table_open_gap_state();
  for (int k = 0; k < 6; ++k)
  {
    EXPECT_NEAR(formula.stress[k], table.stress[k], 1e-6 * std::abs(table.stress[k]))
        << "stress " << voigt_name[k];
    EXPECT_NEAR(formula.strain[k], table.strain[k], 1e-6 * std::abs(table.strain[k]))
        << "strain " << voigt_name[k];
    EXPECT_NEAR(formula.thermal_strain[k], table.thermal_strain[k], 1e-18) << "thermal strain";
  }
  EXPECT_NEAR(formula.gap_opening, table.gap_opening, 1e-6 * table.gap_opening);
}

TEST(ContactBoxMechanics, OpenGapUniformStateOnGeneratedBox)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = temporary_base("mechanics_generated", *comm);
  const std::string &mesh = generated_box_mesh;
  run_and_check_open_gap("generated box", uniform_temperature_deck(mesh, spec_material, 288, base),
                         base, 288, 1e-9 * 288,
                         {{"formula", spec_open_gap_state(), 1e-9},
                          {"spec table", spec_table_open_gap_state(), 1e-6}});
}

// The unscaled system and MueLu's default near-null space (the study switches of
// doc/mechanics.md) reach the same state: NOX then works on x itself, not on x / c.
TEST(ContactBoxMechanics, OpenGapUniformStateUnscaledWithoutRigidBodyModes)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = temporary_base("mechanics_unscaled", *comm);
  const std::string &mesh = generated_box_mesh;
  Teuchos::ParameterList input = uniform_temperature_deck(mesh, spec_material, 288, base);
  input.sublist("Solver").set("Scale Unknowns", false).set("Near-Null Space", false);
  run_and_check_open_gap("unscaled, no rigid-body modes", input, base, 288, 1e-9 * 288,
                         {{"formula", spec_open_gap_state(), 1e-9}});
}

TEST(ContactBoxMechanics, OpenGapUniformStateOnCubitMesh)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = temporary_base("mechanics_cubit", *comm);
  const std::string &mesh = cubit_mesh;
  run_and_check_open_gap("rotated-cube.exo",
                         uniform_temperature_deck(mesh, spec_material, 288, base), base, 288,
                         1e-9 * 288,
                         {{"formula", spec_open_gap_state(), 1e-9},
                          {"spec table", spec_table_open_gap_state(), 1e-6}});
}

TEST(ContactBoxMechanics, OpenGapUniformStateOtherRotationSizeAndMaterial)
{
  // phi 20, theta 35, a 6 x 3 x 5 cm box of 6 x 2 x 4 cells moved off the origin; a steel-like
  // material given by E and nu, cooled by 40 K.
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = temporary_base("mechanics_other", *comm);
  const double E = 2.1e11, nu = 0.3, alpha = 1.2e-5, T_ref = 300, T = 260;
  const std::string mesh = R"xml(
    <Parameter name="Type" type="string" value="Box"/>
    <Parameter name="Gap Side Set" type="int" value="10"/>
    <ParameterList name="Box">
      <Parameter name="Size" type="Array(double)" value="{0.06, 0.03, 0.05}"/>
      <Parameter name="Cells" type="Array(int)" value="{6, 2, 4}"/>
      <Parameter name="Phi" type="double" value="20"/>
      <Parameter name="Theta" type="double" value="35"/>
      <Parameter name="Translation" type="Array(double)" value="{0.1, -0.2, 0.3}"/>
    </ParameterList>)xml";
  std::string material = R"xml(
    <Parameter name="Young's Modulus" type="double" value="E"/>
    <Parameter name="Poisson's Ratio" type="double" value="NU"/>
    <Parameter name="Thermal Expansion" type="double" value="ALPHA"/>
    <Parameter name="Reference Temperature" type="double" value="T_REF"/>)xml";
  kiln_test::replace(material, "\"E\"", '"' + number(E) + '"');
  kiln_test::replace(material, "NU", number(nu));
  kiln_test::replace(material, "ALPHA", number(alpha));
  kiln_test::replace(material, "T_REF", number(T_ref));
  run_and_check_open_gap(
      "phi 20, theta 35, 6x2x4", uniform_temperature_deck(mesh, material, T, base), base, T,
      1e-9 * T, {{"formula", open_gap_state(E, nu, alpha, T - T_ref, 0.03, 20, 35), 1e-9}});
}

TEST(ContactBoxMechanics, OpenInputEndsInOpenGapState)
{
  // inputs/contact-box-open.xml as it is (results to a temporary path). At 150 s the
  // temperature is not quite uniform: the end faces reach 288 K at 100 s, and the time
  // integration error is controlled (Relative Error Tolerance 1e-3) on each step's change,
  // not on the distance to the steady state. Measured: max |T - 288| = 7.2e-7 K (np 1 and
  // 2). A temperature error dT_err gives stresses of order E alpha dT_err / (1 - nu) =
  // 1.6 Pa, which is 2.3e-7 (measured) of the smallest stress component (sigma'_yy =
  // 1.9e6 Pa); the strains and the gap opening deviate by 5e-8 to 9e-8. It is the
  // temperature that sets these: tightening the solver (Newton 1e-12, GMRES 1e-13) leaves
  // them unchanged, a Relative Error Tolerance of 1e-5 divides all of them by 10. So:
  // 3e-6 K for the temperature and 1e-6 relative for the rest, about 4 times the
  // measured deviations.
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string path = inputs + "contact-box-open.xml";
  Teuchos::ParameterList input = kiln::read_input(path, *comm);
  const std::string base = temporary_base("mechanics_open_input", *comm);
  input.sublist("Output").set("File Base", base);
  run_and_check_open_gap("contact-box-open.xml at 150 s", input, base, 288, 3e-6,
                         {{"formula", spec_open_gap_state(), 1e-6},
                          {"spec table", spec_table_open_gap_state(), 1e-6}});
}

TEST(ContactBoxMechanics, ElasticCubeMaximumDisplacement)
{
  // inputs/elastic-cube.xml with N = 20: max |u_i| = 5.82106 (6 digits, four other codes).
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string path = inputs + "elastic-cube.xml";
  Teuchos::ParameterList input = kiln::read_input(path, *comm);
  input.sublist("Mesh").sublist("Box").set("Cells", Teuchos::Array<int>(3, 20));
  kiln::Simulation sim(input, path, comm);
  sim.setup();
  kiln::CoupledProblem &problem = sim.problem();
  kiln_test::Vector x(problem.solution_map());
  problem.initial_condition(0.0, x);
  const kiln::TimeStepper::Statistics stats = run_from(sim, x, {0.0});
  double largest = 0.0;
  for (const Point &u : problem.node_displacements(x))
    for (const double ud : u)
      largest = std::max(largest, std::abs(ud));
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, largest, Teuchos::outArg(largest));
  rank0_out() << "elastic cube, 20^3 cells: max |u_i| = " << std::setprecision(10) << largest
              << std::setprecision(6) << ", " << stats.newton_iterations << " Newton and "
              << stats.linear_iterations << " CG iterations\n";
  EXPECT_LT(std::abs(largest - 5.82106), 6e-6);
  EXPECT_EQ(sim.mesh().n_nodes(), 21 * 21 * 21);
  // Ranges, not counts (style guide 7): one Newton step of a linear problem; MueLu-CG.
  EXPECT_GE(stats.newton_iterations, 1);
  EXPECT_LE(stats.newton_iterations, 2);
  EXPECT_GE(stats.linear_iterations, 1);
  EXPECT_LE(stats.linear_iterations, 40);
}

namespace
{
/// The displacement of every node (3 per node, global id order) at 50, 53 and 150 s of
/// inputs/contact-box-open.xml run on `comm` with tight solver tolerances.
std::vector<std::vector<double>>
open_box_displacements(const Teuchos::RCP<const Teuchos::Comm<int>> &comm)
{
  const std::string path = inputs + "contact-box-open.xml";
  Teuchos::ParameterList input = kiln::read_input(path, *comm);
  // |F| levels off at 1e-12 to 1e-11 by rounding (T_dot = a T + b cancels more as the step
  // shortens): an absolute tolerance of 1e-12 is below it; 1e-11 (as contact_box_contact)
  // changes u by far less than the 1e-9 compared.
  set_solver_tolerances(input, 1e-11, 1e-12, 1e-13);
  kiln::Simulation sim(input, path, comm);
  sim.setup();
  kiln::CoupledProblem &problem = sim.problem();
  kiln_test::Vector x(problem.solution_map());
  problem.initial_condition(0.0, x);
  std::vector<std::vector<double>> states;
  run_from(sim, x, {50.0, 53.0, 150.0},
           [&](double, int, double, const kiln_test::Vector &state)
           {
             const auto u = problem.node_displacements(state);
             const auto &owned = sim.dofs().owned_nodes();
             std::vector<double> local(3 * static_cast<std::size_t>(sim.mesh().n_nodes()), 0.0);
             std::vector<double> global(local.size(), 0.0);
             for (std::size_t i = 0; i < owned.size(); ++i)
               for (int d = 0; d < 3; ++d)
                 local[3 * owned[i] + d] = u[i][d];
             Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, static_cast<int>(local.size()),
                                local.data(), global.data());
             states.push_back(global);
           });
  return states;
}
} // namespace

TEST(ContactBoxMechanics, OneRankMatchesTwo)
{
  // np 1 against np 2 on the contact box while it is not uniform (50 and 53 s) and at the
  // end: the displacements agree to 1e-9 of the largest.
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  if (comm->getSize() != 2)
    GTEST_SKIP() << "runs at np 2 only";
  const auto two = open_box_displacements(comm);
  const auto one = open_box_displacements(comm->split(comm->getRank(), 0)); // each rank alone
  ASSERT_EQ(one.size(), 3u);
  ASSERT_EQ(two.size(), 3u);
  for (std::size_t k = 0; k < one.size(); ++k)
  {
    ASSERT_EQ(one[k].size(), two[k].size());
    double largest = 0.0, difference = 0.0;
    for (std::size_t i = 0; i < one[k].size(); ++i)
    {
      largest = std::max(largest, std::abs(one[k][i]));
      difference = std::max(difference, std::abs(one[k][i] - two[k][i]));
    }
    rank0_out() << "output " << k << ": max |u_np1 - u_np2| / max |u| = " << difference / largest
                << " (max |u| = " << largest << " m)\n";
    EXPECT_GT(largest, 0.0);
    EXPECT_LE(difference, 1e-9 * largest);
  }
}
