// Concentric cylindrical shells meshed apart, heated until they touch (issue 30, verification;
// doc/heat.md "Concentric cylinders heated until they touch"). The two shell arcs of
// verification_pair_gap_heat_shells (about the z axis, 1 rad, 1 m high; the inner one on
// [1.5, 2] m, the outer one on [2.05, 2.5] m, the pair "gap" with the inner shell's outer face
// the secondary side), thermal expansion on (alpha = 1e-4 /K, T_ref = 300 K, lambda = 1.2e11 Pa,
// mu = 8e10 Pa: nu = 0.3), rollers (Normal Displacement) on the planes angle 0 and 1 rad and on
// z = 0 and 1 of both shells: plane strain, every in-plane rigid motion held. No heat crosses
// the pair (no Heat Transfer): a steady run (Method "Steady", one solve per output time t) with
// T = 300 + t [K] on the inner shell's inner face and 300 K on the outer shell's outer face,
// so that each shell has its uniform temperature: the inner one 300 + dT, dT = t.
// While open, the inner shell expands freely: u = (1 + nu) alpha dT (x, y, 0), linear, so the
// discretization holds it exactly, and the opening of every row j is g0_j - (1 + nu) alpha dT
// (n_j . X_j): n_j . X_j = r_1 at a node inside the arc (its normal, the mean of two facets',
// radial), r_1 cos(d/2) at the arc's ends (one facet's normal; d the facet angle), checked to
// 1e-9 of the gap at 0.5 and 0.97 dT*. The gap closes at dT* = (r_2 - r_1) / ((1 + nu) alpha r_1)
// = 192.307692 K by hand; row j at dT_j = g0_j / ((1 + nu) alpha n_j . X_j), off dT* by the
// faceted gap's error (the straight faces of the curved surfaces): max_j |dT_j / dT* - 1| =
// 3.165e-2, 7.901e-3, 1.974e-3 on 8 x 2, 16 x 4 and 32 x 8 cells (angle x radius) in the inner
// shell, 12, 24 and 48 x the same in the outer one: second order. Every row open below min_j
// dT_j and closed above max_j dT_j (0.97 and 1.03 dT* bracket them on the two finer meshes; on
// 8 x 2, 8 of 18 rows are closed at 1.03 dT*). Closed (dT = 1.5 dT*), the mean of the rows'
// contact pressures against Lamé's (plane strain, the inner shell under the pressure p on r_1,
// the outer one under p r_1 / r_2 on r_2, the radial displacements closing the gap r_2 - r_1):
// 3.292992e8 Pa, errors 5.31e-2, 1.30e-2, 3.16e-3: second order. The same digits on 1 and 2
// ranks. Kiln's default preconditioner: Direct on 8 x 2 and 16 x 4, MueLu on the whole
// system on 32 x 8 (5904 unknowns). Until 0095 MueLu failed here (the 32 x 8 mesh's first
// closed solve short of its tolerance at every Newton iteration; 16 x 4 with MueLu forced
// diverging while open): the temperature mode of its near-null space was (1, 0), far from J's
// near-null vector where the force rows' coupling to T is strong ((3 lambda + 2 mu) alpha = 5.2e7
// Pa/K against sqrt(k (lambda + 2 mu)) = 2.4e6); it now carries the free expansion, (1,
// alpha (x - centre)) (doc/solvers.md, "Strong thermal coupling"). MueLuGivesTheDirectStates
// forces MueLu on the two coarser meshes against Direct.
// KILN_TEST_NP: 1 2
#include "base/errors.hpp"
#include "support/parameter_lists.hpp"
#include "support/results_files.hpp"
#include "support/simulation_runs.hpp"
#include "support/two_body_mesh.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace
{
const double r_a = 1.5, r_1 = 2.0, r_2 = 2.05, r_b = 2.5;          // [m]
const double alpha = 1e-4, lambda = 1.2e11, mu = 8e10;             // [1/K], [Pa]
const double nu = lambda / (2.0 * (lambda + mu));                  // 0.3
const double slope = (1.0 + nu) * alpha * r_1;                     // [m/K]
const double dT_closing = (r_2 - r_1) / slope;                     // [K]
const std::vector<double> fractions = {0.0, 0.5, 0.97, 1.03, 1.5}; // of dT_closing

/// The shells' deck on the Exodus file `mesh_file`, with `solver` as its Solver list (none if
/// empty: Kiln's default).
Teuchos::ParameterList deck(const std::string &mesh_file, const Teuchos::ParameterList &solver)
{
  using namespace kiln_test;
  Teuchos::ParameterList input = steady_deck("Thermo-Elasticity", exodus_mesh(mesh_file));
  input.set("Material", lame(lambda, mu));
  input.sublist("Material")
      .set("Thermal Expansion", alpha)
      .set("Reference Temperature", 300.0)
      .set("Conductivity", 20.0);
  input.sublist("Thermal").set("Initial Temperature", 300.0);
  Teuchos::ParameterList table;
  table.set("Type", "Table").set("Times", values({0, 1000})).set("Values", values({300, 1300}));
  thermal_conditions(input).set("heated", temperature({3}, table));
  thermal_conditions(input).set("outer", temperature({4}, 300.0));
  mechanical_conditions(input).set("symmetry", normal_displacement({5, 6, 7}));
  contact_pairs(input).set("gap", contact_pair(2, 1)).sublist("gap").set("Search Distance", 0.1);
  if (solver.numParams() > 0)
    input.set("Solver", solver);
  return input;
}

/// The Solver list that forces `preconditioner`.
Teuchos::ParameterList solver_block(const std::string &preconditioner)
{
  Teuchos::ParameterList solver;
  solver.sublist("Linear Solver").set("Preconditioner Type", preconditioner);
  return solver;
}

/// The radial displacement u(r) = A r + B / r of a plane-strain cylinder [a, b] under the
/// pressures p_a on r = a and p_b on r = b (sigma_rr = 2 (lambda + mu) A - 2 mu B / r^2), at r.
double lame_displacement(const double a, const double b, const double p_a, const double p_b,
                         const double r)
{
  // sigma_rr(a) = -p_a, sigma_rr(b) = -p_b: subtracting, 2 mu B (1/a^2 - 1/b^2) = p_a - p_b.
  const double B = (p_a - p_b) / (2.0 * mu * (1.0 / (a * a) - 1.0 / (b * b)));
  const double A = (-p_a + 2.0 * mu * B / (a * a)) / (2.0 * (lambda + mu));
  return A * r + B / r;
}

/// The contact pressure on r_1 at dT [K] past closing (Lamé): the inner shell's free expansion
/// slope dT less its compression by p on r_1, less the outer shell's expansion by p r_1 / r_2 on
/// r_2, closes the gap r_2 - r_1.
double lame_pressure(const double dT)
{
  const double inner = -lame_displacement(r_a, r_1, 0.0, 1.0, r_1);      // per unit p, > 0
  const double outer = lame_displacement(r_2, r_b, r_1 / r_2, 0.0, r_2); // per unit p, > 0
  return (slope * dT - (r_2 - r_1)) / (inner + outer);
}

/// One output time's values at the rows (the secondary surface's nodes), in mesh node order.
struct Step
{
  double dT = 0.0;
  std::vector<double> angle, opening, pressure, active;
  double T_inner_min = 0.0, T_inner_max = 0.0, T_outer_min = 0.0, T_outer_max = 0.0;
};

/// The output times' states of the n_angle x n_radial shells, with `solver` as the Solver
/// list (solver_block(); Kiln's default if empty).
std::vector<Step> run(const int n_angle, const int n_radial,
                      const Teuchos::ParameterList &solver = Teuchos::ParameterList())
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base =
      kiln_test::temporary_base("pair_shells_closing_" + std::to_string(n_angle), *comm);
  const kiln::Mesh mesh = kiln_test::concentric_shells({r_a, r_1, r_2, r_b}, {n_angle, n_radial},
                                                       {n_angle + n_angle / 2, n_radial});
  const std::string file = kiln_test::write_mesh_file(mesh, base, *comm);
  std::vector<double> times;
  for (const double f : fractions)
    times.push_back(f * dT_closing);
  std::vector<Step> steps;
  std::exception_ptr failure;
  {
    const auto sim = kiln_test::make_simulation(deck(file, solver), comm);
    kiln::CoupledProblem &problem = sim->problem();
    kiln_test::Vector x = kiln_test::initial_state(*sim);
    const auto output = [&](const double time, int, double, const kiln_test::Vector &state)
    {
      Step s;
      s.dT = time;
      const kiln::CoupledProblem::ContactOutput contact = problem.contact_output(state);
      const std::vector<double> T = kiln_test::all_node_values(*sim, state);
      s.T_inner_min = s.T_outer_min = 1e300;
      s.T_inner_max = s.T_outer_max = -1e300;
      for (int n = 0; n < sim->mesh().n_nodes(); ++n)
      {
        const kiln::Point &X = sim->mesh().coordinates[n];
        const bool inner = std::hypot(X[0], X[1]) < 0.5 * (r_1 + r_2);
        (inner ? s.T_inner_min : s.T_outer_min) =
            std::min(inner ? s.T_inner_min : s.T_outer_min, T[n]);
        (inner ? s.T_inner_max : s.T_outer_max) =
            std::max(inner ? s.T_inner_max : s.T_outer_max, T[n]);
        if (std::isnan(contact.opening[n]))
          continue;
        s.angle.push_back(std::atan2(X[1], X[0]));
        s.opening.push_back(contact.opening[n]);
        s.pressure.push_back(-contact.traction[n]);
        s.active.push_back(contact.active[n]);
      }
      steps.push_back(s);
    };
    try
    {
      kiln_test::run_from(*sim, x, times, output);
    }
    catch (...) // a run expected to fail leaves no files either: removed below, then thrown
    {
      failure = std::current_exception();
    }
  }
  kiln_test::remove_results(base, *comm);
  if (failure)
    std::rethrow_exception(failure);
  return steps;
}
} // namespace

TEST(PairShellsClosing, HeatedUntilTheyTouch)
{
  std::vector<double> closing_errors, pressure_errors;
  for (const auto &[n_angle, n_radial] : {std::pair{8, 2}, std::pair{16, 4}, std::pair{32, 8}})
  {
    const std::vector<Step> steps = run(n_angle, n_radial);
    ASSERT_EQ(steps.size(), fractions.size());
    const Step &reference = steps.front();
    const std::size_t n_rows = reference.opening.size();
    EXPECT_EQ(n_rows, 2u * (n_angle + 1)) << "a row per node of the inner shell's outer face";
    // n_j . X_j / r_1: 1 inside the arc (the mean of two facets' normals, radial), cos(d/2) at
    // its ends (the one facet's normal), d = 1 / n_angle rad the facet angle.
    std::vector<double> factor(n_rows, 1.0);
    for (std::size_t j = 0; j < n_rows; ++j)
      if (std::abs(reference.angle[j]) < 1e-9 || std::abs(reference.angle[j] - 1.0) < 1e-9)
        factor[j] = std::cos(0.5 / n_angle);
    // Each row's closing temperature g0_j / (slope factor_j), against the hand dT*.
    double dT_first = 1e300, dT_last = 0.0, closing_error = 0.0;
    for (std::size_t j = 0; j < n_rows; ++j)
    {
      const double dT_j = reference.opening[j] / (slope * factor[j]);
      dT_first = std::min(dT_first, dT_j);
      dT_last = std::max(dT_last, dT_j);
      closing_error = std::max(closing_error, std::abs(dT_j / dT_closing - 1.0));
    }
    closing_errors.push_back(closing_error);
    std::printf("%2d x %d: the rows close (by the law checked below) between dT = %.6f and %.6f "
                "K, dT* = %.6f K by hand: max_j |dT_j / dT* - 1| = %.3e\n",
                n_angle, n_radial, dT_first, dT_last, dT_closing, closing_error);
    for (const Step &s : steps)
    {
      SCOPED_TRACE(std::to_string(n_angle) + " x " + std::to_string(n_radial) + " cells, dT " +
                   std::to_string(s.dT) + " K");
      // Each shell at its uniform temperature.
      EXPECT_NEAR(s.T_inner_min, 300.0 + s.dT, 1e-9 * (300.0 + s.dT));
      EXPECT_NEAR(s.T_inner_max, 300.0 + s.dT, 1e-9 * (300.0 + s.dT));
      EXPECT_NEAR(s.T_outer_min, 300.0, 1e-9 * 300.0);
      EXPECT_NEAR(s.T_outer_max, 300.0, 1e-9 * 300.0);
      ASSERT_EQ(s.opening.size(), n_rows);
      int closed = 0;
      double p_min = 1e300, p_max = -1e300;
      for (std::size_t j = 0; j < n_rows; ++j)
      {
        closed += s.active[j] == 1.0;
        p_min = std::min(p_min, s.pressure[j]);
        p_max = std::max(p_max, s.pressure[j]);
        // Open, the free expansion, exact for the discretization: g_j - g0_j = -slope dT
        // factor_j.
        if (s.dT < dT_first)
        {
          EXPECT_NEAR(s.opening[j] - reference.opening[j], -slope * s.dT * factor[j],
                      1e-9 * slope * dT_closing)
              << "row " << j;
        }
      }
      std::printf("%2d x %d: dT %.6f K (%.2f dT*), %2d of %zu rows closed, pressure in [%.6e, "
                  "%.6e] Pa, Lame %.6e Pa\n",
                  n_angle, n_radial, s.dT, s.dT / dT_closing, closed, n_rows, p_min, p_max,
                  s.dT > dT_closing ? lame_pressure(s.dT) : 0.0);
      if (s.dT < dT_first)
      {
        EXPECT_EQ(closed, 0);
      }
      if (s.dT > dT_last)
      {
        EXPECT_EQ(closed, static_cast<int>(n_rows));
      }
    }
    // Closed at 1.5 dT*: the mean of the rows' pressures against Lamé's.
    const Step &last = steps.back();
    double mean = 0.0;
    for (const double p : last.pressure)
      mean += p / static_cast<double>(n_rows);
    pressure_errors.push_back(std::abs(mean - lame_pressure(last.dT)) / lame_pressure(last.dT));
    std::printf("%2d x %d: mean pressure at %.2f dT* %.6e Pa against Lame %.6e Pa (error %.3e)\n",
                n_angle, n_radial, last.dT / dT_closing, mean, lame_pressure(last.dT),
                pressure_errors.back());
  }
  // Both second order in the facet angle: a factor of about 4 per level.
  for (std::size_t k = 1; k < closing_errors.size(); ++k)
  {
    EXPECT_GT(closing_errors[k - 1] / closing_errors[k], 3.5) << "level " << k;
    EXPECT_GT(pressure_errors[k - 1] / pressure_errors[k], 3.5) << "level " << k;
  }
  EXPECT_LT(closing_errors.back(), 2.5e-3);
  EXPECT_LT(pressure_errors.back(), 4e-3);
  // The finest mesh brackets the hand closing within 3%: open at 0.97 dT*, closed at 1.03.
  EXPECT_LT(closing_errors.back(), 0.03);
}

// MueLu on the whole coupled system, forced on the two meshes where the default is Direct,
// gives Direct's states: every row's opening and pressure, and the temperatures. Before the
// temperature mode of the near-null space carried the free expansion (0095), MueLu diverged
// on 16 x 4 already while open (|F| to 5e32) and reached only Newton's default tolerance on
// 8 x 2.
TEST(PairShellsClosing, MueLuGivesTheDirectStates)
{
  for (const auto &[n_angle, n_radial] : {std::pair{8, 2}, std::pair{16, 4}})
  {
    const std::vector<Step> direct = run(n_angle, n_radial, solver_block("Direct"));
    const std::vector<Step> muelu = run(n_angle, n_radial, solver_block("MueLu"));
    ASSERT_EQ(muelu.size(), direct.size());
    double opening = 0.0, pressure = 0.0, temperature = 0.0;
    for (std::size_t s = 0; s < direct.size(); ++s)
    {
      ASSERT_EQ(muelu[s].opening.size(), direct[s].opening.size());
      EXPECT_EQ(muelu[s].active, direct[s].active) << "dT " << direct[s].dT;
      for (std::size_t j = 0; j < direct[s].opening.size(); ++j)
      {
        opening = std::max(opening, std::abs(muelu[s].opening[j] - direct[s].opening[j]));
        pressure = std::max(pressure, std::abs(muelu[s].pressure[j] - direct[s].pressure[j]));
      }
      for (const auto &[a, b] : {std::pair{muelu[s].T_inner_min, direct[s].T_inner_min},
                                 std::pair{muelu[s].T_inner_max, direct[s].T_inner_max},
                                 std::pair{muelu[s].T_outer_min, direct[s].T_outer_min},
                                 std::pair{muelu[s].T_outer_max, direct[s].T_outer_max}})
        temperature = std::max(temperature, std::abs(a - b));
    }
    std::printf("%2d x %d, MueLu against Direct: openings %.3e m, pressures %.3e Pa, "
                "temperatures %.3e K apart at most\n",
                n_angle, n_radial, opening, pressure, temperature);
    EXPECT_LT(opening, 1e-9 * (r_2 - r_1));
    EXPECT_LT(pressure, 1e-8 * lame_pressure(fractions.back() * dT_closing));
    EXPECT_LT(temperature, 1e-9 * 300.0);
  }
}

// A preconditioner that does not solve the Jacobian (MueLu without the near-null space,
// `Near-Null Space` false: its constant per unknown): every GMRES solve falls short of its
// tolerance, and NOX takes its step anyway ("Rescue Bad Newton Solve"). Newton stops once
// ||F|| has grown a millionfold, with a message that names the linear solves, instead of
// going on to its 20 iterations (||F|| 1e4 -> 1e29 before 0095) and advising smaller steps.
TEST(PairShellsClosing, LinearSolvesThatFailStopNewtonWithAMessage)
{
  Teuchos::ParameterList solver = solver_block("MueLu");
  solver.set("Near-Null Space", false);
  try
  {
    run(16, 4, solver);
    FAIL() << "the run was expected to stop with a RunError";
  }
  catch (const kiln::RunError &e)
  {
    const std::string message = e.what();
    std::printf("%s\n", message.c_str());
    EXPECT_NE(message.find("the linear solves fell short of their tolerance"), std::string::npos);
    EXPECT_NE(message.find("diverged"), std::string::npos);
    EXPECT_NE(message.find("The preconditioner does not solve this Jacobian"), std::string::npos);
    EXPECT_EQ(message.find("limit of 20 iterations"), std::string::npos);
  }
}
