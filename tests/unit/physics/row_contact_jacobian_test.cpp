// Tests the Jacobian of CoupledProblem::evaluate with a pairing's rows (issue 30, step 1: rows
// with several weighted partners; doc/contact.md, "Condensation with the dual basis") against
// central differences of the residual, entry by entry. Two bodies meshed apart
// (tests/support/two_body_mesh): body 1 on [0, 1]^2 x [-0.2, 0] with 3 x 3 x 1 cells, body 2
// on [0.125, 1.125] x [0, 1] x 0.2 high with 4 x 2 x 1 cells, its bottom at z = gap + tilt (x -
// 0.55), rotated; the rows of body 2's bottom (secondary) against body 1's top (primary) from
// MortarPairing (D_jj, w_jk = M_jk / D_jj, g0_j = g~_j / D_jj), so that
// body 2's last column of faces is half covered and its far nodes have small D_jj. Body 1's
// bottom held, body 2's top held in x and y. The opening is the mesh's (g0, the rows' initial
// gap), far from the switch P = c g; x is noise about the reference (temperatures within 0.2 K
// of T_ref, displacements within 2e-8 m): all rows open (gap 2e-4 m), all closed (gap -1e-4 m:
// interpenetrating), mixed (tilt 4e-4); kind "Contact" ("Min" and "Fischer-Burmeister") and
// "Bonded". At np 2 the cells are split at the block x = 0.55, so that both surfaces, and rows
// and their partners, lie on two ranks. With the heat across the pair's gap (PairGapHeat: gas
// and radiation) open and mixed: its T-T and T-u blocks (through Couplings::cell_blocks and
// the heat's links), to 1e-7 (about 7e-8 measured: the T-u entries, k dT/(g + g_jump)^2 with
// dT < 0.4 K, from differences of residuals of steps 1e-9 m, are at the round-off's level).
// With the contact conductance h_p max(p, 0) as well ("Gap Pressure Coefficient"; p from the
// stress of the two cells of each mortar cell's faces, at 1 K above T_ref so that p > 0 in every
// cell): open, closed and mixed, its T-u and T-T blocks over both cells' nodes, np 1 and 2
// (measured 1.0e-8, 1.3e-9, 3.1e-8; with its derivatives left out, 1.2, 1 and 1.2).
// KILN_TEST_NP: 1 2
#include "base/log.hpp"
#include "base/parameters.hpp"
#include "contact/interface_parameters.hpp"
#include "contact/mortar_pairing.hpp"
#include "mesh/hex_geometry.hpp"
#include "physics/coupled_problem.hpp"
#include "physics/heat/pair_gap_heat.hpp"
#include "physics/heat/thermal_physics.hpp"
#include "physics/mechanics/mechanical_physics.hpp"
#include "solvers/newton_solver.hpp"
#include "support/jacobian_check.hpp"
#include "support/parameter_lists.hpp"
#include "support/problem_fixture.hpp"
#include "support/two_body_mesh.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_Tuple.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace
{
using namespace kiln_test;
using kiln::LO;
using kiln::Point;
using Vector = kiln::NonlinearProblem::Vector;

constexpr double g0 = 2.0e-4;               ///< the initial gap [m]
constexpr double phi = 25.0, theta = -15.0; ///< the rotation [degrees]
constexpr double tolerance = 1.0e-7;        ///< as contact_jacobian_test

/// The rows of the secondary side set 2 against the primary side set 1 (MortarPairing; the
/// interpenetrating meshes of the closed states accepted).
std::vector<kiln::ContactRow> mortar_rows(const kiln::Mesh &mesh)
{
  kiln::MortarPairingOptions options;
  options.penetration_tolerance = 1e-3;
  return kiln::MortarPairing(mesh, 1, 2, options, "test").rows();
}

/// How body 2 is meshed against body 1: its bottom at block z = gap + tilt (x - 0.55) [m].
struct State
{
  double gap = 0.0;
  double tilt = 0.0;
  /// Side set 1 (the partners) held along x and side set 2 (the rows' nodes) along y: the
  /// partners' held axes are eliminated, the rows' normals lean.
  bool held_surfaces = false;
  /// Body 2's top free, "Free Motions" = "Minimum Norm": open rows held shut.
  bool minimum_norm = false;
  /// Body 2's shift along the block x [m].
  double shift = 0.125;
  /// Heat across the pair's gap (PairGapHeat): gas (0.2 W/(m K), jump distance 1e-4 m) and
  /// radiation (emissivities 0.8), so that its T-T and T-u blocks are in the Jacobian.
  bool heat = false;
  /// With the heat: the contact conductance too ("Gap Pressure Coefficient" 1e-4 W/(m^2 K Pa):
  /// h_p p about 450 W/(m^2 K) at the pressure p of 1 K above T_ref in the cells), its
  /// T-u and T-T blocks over both cells' nodes.
  bool contact_conductance = false;
  /// Added to every node's temperature [K]: T_ref + 1 K puts p = 3 K alpha (T - T_ref) > 0 in
  /// every cell (the cells' strain, from noise of 2e-8 m, adds 1e4 Pa at most), away from the
  /// kink of max(p, 0).
  double T_offset = 0.0;
};

/// The pair's heat across the gap if `state` asks for it (else null).
std::shared_ptr<kiln::PairGapHeat> gap_heat(const kiln::Mesh &mesh, const State &state)
{
  if (!state.heat)
    return nullptr;
  Teuchos::ParameterList p;
  p.set("Gas Conductivity", 0.2);
  p.set("Jump Distance", 1.0e-4);
  p.set("Primary Emissivity", 0.8);
  p.set("Secondary Emissivity", 0.8);
  if (state.contact_conductance)
    p.set("Gap Pressure Coefficient", 1.0e-4);
  const std::string where = "Kiln/Mechanics/Contact/Pairs/test/Heat Transfer";
  static const kiln::Material material = TableMaterial::make();
  return std::make_shared<kiln::PairGapHeat>(
      mesh, 1, 2, 0.5, 0.0,
      kiln::validated(p, kiln::MortarGapHeat::valid_parameters(), "test.xml", where), where,
      &material);
}

/// The DofManager's links: the rows' partners and the heat's.
std::vector<std::pair<int, int>> all_links(const std::vector<kiln::ContactRow> &rows,
                                           const kiln::PairGapHeat *heat)
{
  std::vector<std::pair<int, int>> links = kiln::partner_links(rows);
  if (heat != nullptr)
  {
    const auto more = heat->links();
    links.insert(links.end(), more.begin(), more.end());
  }
  return links;
}

/// The two bodies, body 2 moved along x and placed as `state` says (block frame),
/// then rotated; `block_x` gets each node's x before the rotation.
kiln::Mesh two_bodies(const State &state, std::vector<double> &block_x)
{
  kiln::Mesh mesh = two_flat_bodies({3, 3}, {4, 2}, 1.0);
  block_x.clear();
  for (Point &x : mesh.coordinates)
  {
    if (x[2] > 0.5)
    {
      x[0] += state.shift;
      x[2] += state.gap + state.tilt * (x[0] - 0.55) - 1.0;
    }
    block_x.push_back(x[0]);
  }
  rotate(mesh, phi, theta);
  return mesh;
}

struct TwoBodies
{
  explicit TwoBodies(const State &state)
      : mesh(two_bodies(state, block_x)), rows(mortar_rows(mesh)),
        cell_rank(static_cast<std::size_t>(mesh.n_cells()), 0), heat(gap_heat(mesh, state)),
        dofs((split_cells(), mesh), cell_rank, comm, kiln::DofLayout{true, true, true},
             all_links(rows, heat.get()))
  {
  }
  /// At np 2: rank 1 takes the cells whose centre lies beyond block x = 0.55.
  void split_cells()
  {
    if (comm->getSize() < 2)
      return;
    for (int c = 0; c < mesh.n_cells(); ++c)
    {
      double x = 0.0;
      for (const int n : mesh.cell_nodes(c))
        x += block_x[n] / 8.0;
      cell_rank[c] = x > 0.55 ? 1 : 0;
    }
  }

  Teuchos::RCP<const Teuchos::Comm<int>> comm = Teuchos::DefaultComm<int>::getComm();
  std::vector<double> block_x;
  kiln::Mesh mesh;
  std::vector<kiln::ContactRow> rows;
  std::vector<int> cell_rank;
  std::shared_ptr<kiln::PairGapHeat> heat;
  kiln::DofManager dofs;
  kiln::Material material = TableMaterial::make();
};

Teuchos::ParameterList thermal_list()
{
  Teuchos::ParameterList thermal;
  thermal.set("Initial Temperature", TableMaterial::T_ref);
  Teuchos::ParameterList &held = thermal.sublist("Boundary Conditions").sublist("held");
  held.set("Type", "Temperature");
  held.set("Side Sets", ids({3}));
  held.set("Temperature", constant_function(TableMaterial::T_ref));
  return thermal;
}

Teuchos::ParameterList mechanics_list(const State &state)
{
  Teuchos::ParameterList mechanics;
  Teuchos::ParameterList &bcs = mechanics.sublist("Boundary Conditions");
  Teuchos::ParameterList &base = bcs.sublist("base");
  base.set("Type", "Displacement");
  base.set("Side Sets", ids({3}));
  base.set("Components", Teuchos::Array<std::string>(Teuchos::tuple<std::string>("x", "y", "z")));
  if (state.minimum_norm)
    mechanics.set("Free Motions", "Minimum Norm");
  else
  {
    Teuchos::ParameterList &top = bcs.sublist("top");
    top.set("Type", "Displacement");
    top.set("Side Sets", ids({4}));
    top.set("Components", Teuchos::Array<std::string>(Teuchos::tuple<std::string>("x", "y")));
  }
  if (state.held_surfaces)
    for (const auto &[id, component] : {std::pair<int, std::string>{1, "x"}, {2, "y"}})
    {
      Teuchos::ParameterList &held = bcs.sublist("held " + component);
      held.set("Type", "Displacement");
      held.set("Side Sets", ids({id}));
      held.set("Components", Teuchos::Array<std::string>(1, component));
    }
  return mechanics;
}

/// The pairing's parameters: kind `kind` with `function`, validated as a "Contact" sublist.
kiln::PairingRows pairing(const std::vector<kiln::ContactRow> &rows, const std::string &kind,
                          const std::string &function)
{
  Teuchos::ParameterList p("Contact");
  p.set("Enabled", true);
  p.set("Kind", kind);
  if (kind == "Contact")
    p.set("Complementarity Function", function);
  p.validateParametersAndSetDefaults(kiln::interface_parameters());
  return {"pair \"test\"", rows, p, nullptr, nullptr};
}

/// A problem on the two bodies with the Thermal and Mechanics lists (validated here) and the
/// pairings.
Teuchos::RCP<kiln::CoupledProblem> make_problem(const TwoBodies &s,
                                                const Teuchos::ParameterList &thermal,
                                                const Teuchos::ParameterList &mechanics,
                                                const std::vector<kiln::PairingRows> &pairings)
{
  const Teuchos::ParameterList t = kiln::validated(
      thermal, kiln::ThermalPhysics::valid_parameters(), "test.xml", "Kiln/Thermal");
  const Teuchos::ParameterList m = kiln::validated(
      mechanics, kiln::MechanicalPhysics::valid_parameters(), "test.xml", "Kiln/Mechanics");
  return Teuchos::rcp(new kiln::CoupledProblem(s.mesh, s.dofs, s.material, t, m, "test.xml: Kiln",
                                               nullptr, pairings));
}

/// Runs one case: J at the state against central differences; returns the error.
double run_case(const std::string &name, const std::string &kind, const std::string &function,
                const State &state)
{
  TwoBodies s(state);
  kiln::PairingRows rows = pairing(s.rows, kind, function);
  rows.heat = s.heat;
  const auto problem_rcp = make_problem(s, thermal_list(), mechanics_list(state), {rows});
  kiln::CoupledProblem &problem = *problem_rcp;
  EXPECT_TRUE(problem.has_contact());
  EXPECT_EQ(problem.n_pairs(), static_cast<int>(s.rows.size()));
  // The rows: several partners each, weights summing to 1.
  std::size_t most = 0;
  for (const kiln::ContactRow &row : s.rows)
  {
    double sum = 0.0;
    for (const double w : row.weights)
      sum += w;
    EXPECT_NEAR(sum, 1.0, 1e-12);
    most = std::max(most, row.partners.size());
  }
  EXPECT_GE(most, 4u);
  if (s.comm->getSize() == 2)
  {
    // Rows on both ranks, and rows with partners owned by the other rank.
    const auto &owner = s.dofs.node_owner();
    int on_rank[2] = {0, 0}, across = 0;
    for (const kiln::ContactRow &row : s.rows)
    {
      ++on_rank[owner[row.node]];
      across += std::any_of(row.partners.begin(), row.partners.end(),
                            [&](const int k) { return owner[k] != owner[row.node]; });
    }
    EXPECT_GT(on_rank[0], 0);
    EXPECT_GT(on_rank[1], 0);
    EXPECT_GT(across, 0);
  }

  // The state through x: noise about the reference (the opening is the mesh's, g0).
  const auto frames = node_frames(problem);
  Vector x(problem.solution_map());
  std::mt19937 random(11u);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto &owned = s.dofs.owned_nodes();
  std::vector<double> T_noise(s.mesh.n_nodes());
  std::vector<Point> u_noise(s.mesh.n_nodes());
  for (int n = 0; n < s.mesh.n_nodes(); ++n)
  {
    T_noise[n] = 0.2 * unit(random);
    for (double &v : u_noise[n])
      v = 2.0e-8 * unit(random);
  }
  for (std::size_t i = 0; i < owned.size(); ++i)
  {
    const int n = owned[i];
    const auto c = frame_components(frames[i], u_noise[n]);
    x.replaceLocalValue(static_cast<LO>(4 * i), TableMaterial::T_ref + state.T_offset + T_noise[n]);
    for (int k = 0; k < 3; ++k)
      x.replaceLocalValue(static_cast<LO>(4 * i + 1 + k), c[k]);
  }
  int n_closed = 0;
  double closest = 1e300;
  for (const kiln::ContactRow &row : s.rows)
  {
    const double g = row.gap0;
    n_closed += kind == "Bonded" || g < 0.0;
    closest = std::min(closest, std::abs(g));
  }
  EXPECT_GT(closest, 1e-5) << "a row is too near the switch";
  if (state.minimum_norm)
  {
    // Open rows held shut, so that no rigid motion is left free.
    const int n_active = problem.n_active_pairs(x);
    EXPECT_GT(n_active, n_closed);
    n_closed = n_active;
  }
  const double error = jacobian_error(s.dofs, problem, x, n_closed);
  if (s.comm->getRank() == 0)
    std::cout << name << " (np " << s.comm->getSize() << "): " << s.rows.size() << " rows, "
              << n_closed << " closed, up to " << most << " partners; max |J - J_fd| / row scale "
              << error << "\n";
  return error;
}
} // namespace

TEST(RowContactJacobian, AllRowsOpen)
{
  EXPECT_LT(run_case("open", "Contact", "Min", {g0, 0.0}), tolerance);
}

TEST(RowContactJacobian, AllRowsOpenWithGapHeat)
{
  State state{g0, 0.0};
  state.heat = true;
  EXPECT_LT(run_case("open, heat across the gap", "Contact", "Min", state), tolerance);
}

TEST(RowContactJacobian, SomeRowsClosedWithGapHeat)
{
  State state{0.0, 4.0e-4};
  state.heat = true;
  EXPECT_LT(run_case("mixed, heat across the gap", "Contact", "Min", state), tolerance);
}

TEST(RowContactJacobian, AllRowsOpenWithContactConductance)
{
  State state{g0, 0.0};
  state.heat = state.contact_conductance = true;
  state.T_offset = 1.0;
  EXPECT_LT(run_case("open, heat with contact conductance", "Contact", "Min", state), tolerance);
}

TEST(RowContactJacobian, AllRowsClosedWithContactConductance)
{
  State state{-1.0e-4, 0.0};
  state.heat = state.contact_conductance = true;
  state.T_offset = 1.0;
  EXPECT_LT(run_case("closed, heat with contact conductance", "Contact", "Min", state), tolerance);
}

TEST(RowContactJacobian, SomeRowsClosedWithContactConductance)
{
  State state{0.0, 4.0e-4};
  state.heat = state.contact_conductance = true;
  state.T_offset = 1.0;
  EXPECT_LT(run_case("mixed, heat with contact conductance", "Contact", "Min", state), tolerance);
}

TEST(RowContactJacobian, AllRowsClosed)
{
  EXPECT_LT(run_case("closed", "Contact", "Min", {-1.0e-4, 0.0}), tolerance);
}

TEST(RowContactJacobian, SomeRowsClosed)
{
  EXPECT_LT(run_case("mixed", "Contact", "Min", {0.0, 4.0e-4}), tolerance);
}

TEST(RowContactJacobian, FischerBurmeister)
{
  EXPECT_LT(run_case("mixed, Fischer-Burmeister", "Contact", "Fischer-Burmeister", {0.0, 4.0e-4}),
            tolerance);
}

TEST(RowContactJacobian, Bonded)
{
  EXPECT_LT(run_case("bonded", "Bonded", "Min", {0.0, 4.0e-4}), tolerance);
}

TEST(RowContactJacobian, HeldPartnersAndLeaningNormals)
{
  EXPECT_LT(run_case("mixed, surfaces held along x and y", "Contact", "Min", {0.0, 4.0e-4, true}),
            tolerance);
  EXPECT_LT(run_case("bonded, surfaces held along x and y", "Bonded", "Min", {0.0, 4.0e-4, true}),
            tolerance);
}

TEST(RowContactJacobian, MinimumNormHoldsOpenRowsShut)
{
  EXPECT_LT(run_case("open, Minimum Norm", "Contact", "Min", {g0, 0.0, false, true}), tolerance);
}

// The patch test of the rows: body 2 (4 x 2 faces) on body 1 (3 x 3), fully covered, rotated,
// touching (g0 = 0); body 1's bottom on rollers, a pressure p on body 2's top, the free
// lateral motions by "Minimum Norm", the temperature held at T_ref. The state is uniaxial,
// sigma = -p n n in both bodies (free lateral expansion), so every row carries P_j = p and
// u.n = -p (h + 0.2) / E, h the height above the interface.
TEST(RowContactJacobian, PatchTestUniformPressure)
{
  const State state{0.0, 0.0, false, true, 0.0};
  TwoBodies s(state);
  constexpr double p = 1.0e6;
  Teuchos::ParameterList thermal = thermal_list();
  thermal.sublist("Boundary Conditions").sublist("held").set("Side Sets", ids({3, 4}));
  Teuchos::ParameterList mechanics;
  mechanics.set("Free Motions", "Minimum Norm");
  Teuchos::ParameterList &bcs = mechanics.sublist("Boundary Conditions");
  Teuchos::ParameterList &rollers = bcs.sublist("rollers");
  rollers.set("Type", "Normal Displacement");
  rollers.set("Side Sets", ids({3}));
  Teuchos::ParameterList &load = bcs.sublist("load");
  load.set("Type", "Pressure");
  load.set("Side Sets", ids({4}));
  load.set("Pressure", constant_function(p));
  auto problem = make_problem(s, thermal, mechanics, {pairing(s.rows, "Contact", "Min")});
  Teuchos::ParameterList solver;
  solver.set("Relative Tolerance", 1e-12);
  solver.set("Absolute Tolerance", 1e-300);
  solver.set("Maximum Iterations", 20);
  Teuchos::ParameterList &belos =
      solver.sublist("Linear Solver").sublist("Linear Solver Types").sublist("Belos");
  belos.set("Solver Type", "Pseudo Block GMRES");
  Teuchos::ParameterList &krylov = belos.sublist("Solver Types").sublist("Pseudo Block GMRES");
  krylov.set("Convergence Tolerance", 1e-13);
  krylov.set("Maximum Iterations", 2000);
  kiln::NewtonSolver newton(solver, problem, kiln::rank0_stream(*s.comm));
  const auto map = problem->solution_map();
  Vector x(map), zero(map);
  problem->set_time_derivative(0.0, 0.0, zero);
  problem->initial_condition(0.0, x);
  const kiln::NewtonSolver::Result result = newton.solve(x);
  ASSERT_TRUE(result.converged) << "Newton " << result.newton_iterations << ", |F| "
                                << result.initial_residual_norm << " -> "
                                << result.final_residual_norm << ", linear failures "
                                << result.linear_failures << " " << result.step_failure;
  EXPECT_EQ(problem->n_active_pairs(x), static_cast<int>(s.rows.size()));
  const auto out = problem->contact_output(x);
  double worst_P = 0.0;
  for (const kiln::ContactRow &row : s.rows)
    worst_P = std::max(worst_P, std::abs(-out.traction[row.node] - p) / p);
  // u.n at every node against -p (z_block + 0.2) / E (uniaxial: free lateral expansion).
  const auto A = kiln::rotation_matrix(phi, theta);
  const Point N{A[0][2], A[1][2], A[2][2]};
  const std::vector<Point> u = problem->node_displacements(x);
  const auto &owned = s.dofs.owned_nodes();
  double worst_u = 0.0;
  for (std::size_t i = 0; i < owned.size(); ++i)
  {
    const double height = kiln::dot(N, s.mesh.coordinates[owned[i]]) + 0.2;
    const double expected = -p * height / TableMaterial::youngs;
    worst_u = std::max(worst_u,
                       std::abs(kiln::dot(N, u[i]) - expected) / (p * 0.4 / TableMaterial::youngs));
  }
  double global_u = 0.0;
  Teuchos::reduceAll(*s.comm, Teuchos::REDUCE_MAX, worst_u, Teuchos::outArg(global_u));
  if (s.comm->getRank() == 0)
    std::cout << "patch test (np " << s.comm->getSize() << "): " << s.rows.size()
              << " rows, Newton " << result.newton_iterations << ", max |P_j - p| / p " << worst_P
              << ", max |u.n - exact| / max " << global_u << "\n";
  EXPECT_LT(worst_P, 1e-9);
  EXPECT_LT(global_u, 1e-9);
}

TEST(RowContactJacobian, PairingSharingNodesIsAnInputError)
{
  const State state{g0, 0.0};
  TwoBodies s(state);
  kiln::PairingRows second = pairing(s.rows, "Contact", "Min");
  second.name = "pair \"again\"";
  const std::string message = input_error_message(
      [&]
      {
        make_problem(s, thermal_list(), mechanics_list(state),
                     {pairing(s.rows, "Contact", "Min"), second});
      });
  EXPECT_NE(message.find("test.xml: Kiln/Mechanics/Contact: node "), std::string::npos) << message;
  EXPECT_NE(message.find("is on pair \"test\" and on pair \"again\""), std::string::npos)
      << message;
}
