// Tests the Jacobian of CoupledProblem::evaluate with frictionless contact across a split gap
// (each pair's pressure condensed into its normal displacement unknowns, the pair's rows
// combined) against central differences of the residual, entry by entry, on a rotated box of
// 4 x 3 x 3 cells whose interior nodes are moved (those of the cut plane within it), split at
// its middle plane (16 node pairs). Rollers on faces 1, 3 and 5 (gap nodes on 3 and 5 have
// their roller, the gap normal and a third axis as frame), a prescribed normal motion of face 2,
// a pressure on 4; a temperature on 1, convection on 2 and 6, a heat flux on 3; a table k(T)
// and a time derivative. States, set through x (the nodes' frames read back from
// node_displacements), each pair's P and c g checked to be far from the switch P = c g:
// - all pairs open: the halves apart, colder than T_ref ("Min");
// - all pairs closed: the halves pushed into each other, warmer than T_ref ("Min"), where the
//   contact row of each pair is A c g;
// - mixed: the opening tilted across the gap, half the pairs closed ("Min");
// - "Fischer-Burmeister" in the tilted state warmer than T_ref: P and c g nonzero at each pair;
// - the "Contact Dependent" gap conductance with a jump of 6 to 9 K across the gap, open (the
//   dh/dg term: the heat rows of gap nodes depend on the gap nodes' displacements only) and
//   closed under compression (the dh/dp term: they also depend on the other nodes of the two
//   cells), and open but warmer than T_ref (both terms);
// - the same closed and open-but-warm states with two materials on the two sides of the gap,
//   side b with E(T) and alpha(T) (each side's p from its own material's model);
// - with the temperature frozen (freeze_temperature), closed.
// No perturbation changes the number of pairs in contact (checked at every evaluation). At np 2
// the partition puts the two nodes of every pair on different ranks, at np 3 half of them.
// KILN_TEST_NP: 1 2 3
#include "physics/coupled_problem.hpp"

#include "mesh/hex_geometry.hpp"
#include "support/jacobian_check.hpp"
#include "support/parameter_lists.hpp"
#include "support/problem_fixture.hpp"
#include "support/tensors.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace kiln_test;
using kiln::GO;
using kiln::LO;
using kiln::Point;
using Vector = kiln::NonlinearProblem::Vector;
using Matrix = kiln::NonlinearProblem::Matrix;

/// Material: TableMaterial (aluminium-like; states stay inside (280, 400) K: no kink of k).
constexpr double T_ref = TableMaterial::T_ref;
constexpr double phi = 30.0, theta = -20.0;
/// Time of the evaluations [s] and a of the time derivative (T' = a T + b) [1/s].
constexpr double t_now = 4.0, a_time = 3.0;
/// Finite-difference steps: temperatures [K], displacements [m].
constexpr double eps_T = 1.0e-3, eps_u = 1.0e-9;
/// |J - J_fd| <= tolerance * (the largest |J| or |J_fd| of the row in that block).
constexpr double tolerance = 1.0e-7;
/// A pair's |P - c g| must be at least this fraction of max(|P|, |c g|).
constexpr double margin_fraction = 0.1;

/// The box 0.04 x 0.03 x 0.03 m, 4 x 3 x 3 cells, rotated by phi, theta; its nodes off the
/// outer faces moved by up to 20% of a cell along each block axis (random, the same on every
/// rank), those of the middle plane within it (so that the gap is plane); split at side set 10.
kiln::Mesh split_box()
{
  return distorted_box({{0.04, 0.03, 0.03}, {4, 3, 3}, phi, theta}, 0.2, 10, true);
}

enum class Conductance
{
  constant,
  contact_dependent
};

/// The Thermal block: h0 = 1e4 W/(m^2 K) (Contact Dependent: L = 1e-5 m, h_p = 1e-3
/// W/(m^2 K Pa)); T = T_1 on side set 1, convection on 2 and 6, a heat flux on 3.
Teuchos::ParameterList thermal_block(const Conductance model, const double T_1)
{
  Teuchos::ParameterList thermal;
  thermal.set("Initial Temperature", 300.0);
  thermal.set("Gap Conductance", 1.0e4);
  if (model == Conductance::contact_dependent)
  {
    thermal.set("Gap Conductance Model", "Contact Dependent");
    thermal.set("Gap Width Scale", 1.0e-5);
    thermal.set("Gap Pressure Coefficient", 1.0e-3);
  }
  Teuchos::ParameterList &bcs = thermal.sublist("Boundary Conditions");
  Teuchos::ParameterList &held = bcs.sublist("held");
  held.set("Type", "Temperature");
  held.set("Side Sets", ids({1}));
  held.set("Temperature", constant_function(T_1));
  Teuchos::ParameterList &cooled = bcs.sublist("cooled");
  cooled.set("Type", "Convection");
  cooled.set("Side Sets", ids({2, 6}));
  cooled.set("Coefficient", 50.0);
  cooled.set("Ambient Temperature", constant_function(290.0));
  Teuchos::ParameterList &heated = bcs.sublist("heated");
  heated.set("Type", "Heat Flux");
  heated.set("Side Sets", ids({3}));
  heated.set("Heat Flux", constant_function(2.0e4));
  return thermal;
}

/// The Mechanics block: rollers on 1, 3, 5, the normal displacement u_2 of face 2, a pressure
/// on 4; contact with the given function and scale (or the interface `kind`, "Sliding" or
/// "Bonded", when it is not "Contact").
Teuchos::ParameterList mechanics_block(const std::string &function, const double scale,
                                       const double u_2, const std::string &kind = "Contact")
{
  Teuchos::ParameterList mechanics;
  Teuchos::ParameterList &bcs = mechanics.sublist("Boundary Conditions");
  Teuchos::ParameterList &rollers = bcs.sublist("rollers");
  rollers.set("Type", "Normal Displacement");
  rollers.set("Side Sets", ids({1, 3, 5}));
  Teuchos::ParameterList &end = bcs.sublist("end");
  end.set("Type", "Normal Displacement");
  end.set("Side Sets", ids({2}));
  end.set("Displacement", constant_function(u_2));
  Teuchos::ParameterList &pressure = bcs.sublist("pressure");
  pressure.set("Type", "Pressure");
  pressure.set("Side Sets", ids({4}));
  pressure.set("Pressure", constant_function(1.0e6));
  Teuchos::ParameterList &contact = mechanics.sublist("Contact");
  contact.set("Enabled", true);
  contact.set("Kind", kind);
  if (kind == "Contact")
    contact.set("Complementarity Function", function);
  contact.set("Complementarity Scale", scale);
  return mechanics;
}

/// The state of a test, per side of the gap (a: the normal n points away from it).
struct Design
{
  double T_a = T_ref, T_b = T_ref; ///< mean temperatures [K]
  double opening = 0.0;            ///< (u_b - u_a).n where the block y is 0 [m]
  double tilt = 0.0;               ///< its rate along the block y axis [-]
  double T_noise = 0.5;            ///< random deviations per node, up to [K]
  double u_noise = 2.0e-8;         ///< random displacement per node, up to [m] (each axis)
};

/// What each pair is at a state, from a "Min" problem (P does not depend on the function).
struct PairStates
{
  std::vector<double> P, cg, g; ///< per pair [Pa], [Pa], [m]
  std::vector<char> active;
  int n_active = 0;
  double min_relative_margin = 1.0; ///< min |P - c g| / max(|P|, |c g|)
  double min_margin = 1e300;        ///< min |P - c g| [Pa]
  double min_abs_P = 0.0, min_abs_cg = 0.0;
  double max_contact_row_error = 0.0; ///< closed pairs: |F_b - A c g| / (A c |g|)
};

/// The problem fixture on the split box, and the node data of the states.
struct Fixture : ProblemFixture
{
  Fixture() : ProblemFixture(split_box(), kiln::DofLayout{true, true, true})
  {
    const int N = mesh.n_nodes();
    normal = mesh.gap_pairs.at(0).normal;
    const Point x0 = mesh.coordinates[mesh.gap_pairs[0].node_a];
    pair_of_node.assign(N, -1);
    for (std::size_t k = 0; k < mesh.gap_pairs.size(); ++k)
    {
      pair_of_node[mesh.gap_pairs[k].node_a] = pair_of_node[mesh.gap_pairs[k].node_b] =
          static_cast<int>(k);
      for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(mesh.gap_pairs[k].normal[d], normal[d], 1e-12) << "the gap is not plane";
    }
    const auto A = kiln::rotation_matrix(phi, theta);
    side_b.assign(N, 0);
    eta.assign(N, 0.0);
    noise_T.assign(N, 0.0);
    noise_u.assign(N, Point{});
    std::mt19937 random(7u);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int n = 0; n < N; ++n)
    {
      const Point &x = mesh.coordinates[n];
      const int k = pair_of_node[n];
      const Point r{x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
      side_b[n] = k >= 0 ? n == mesh.gap_pairs[k].node_b : dot(normal, r) > 0.0;
      for (int d = 0; d < 3; ++d)
        eta[n] += A[d][1] * x[d];
      noise_T[n] = unit(random);
      for (double &u : noise_u[n])
        u = unit(random);
    }
  }

  /// Sets the time derivative T' = a T + b with b = -a (T_a or T_b - 1 K): T' about 3 K/s.
  void set_time(kiln::CoupledProblem &problem, const Design &design) const
  {
    Vector b(problem.solution_map());
    const auto &owned = dofs.owned_nodes();
    for (std::size_t i = 0; i < owned.size(); ++i)
    {
      const int n = owned[i];
      b.replaceLocalValue(static_cast<LO>(4 * i),
                          -a_time * ((side_b[n] ? design.T_b : design.T_a) - 1.0));
    }
    problem.set_time_derivative(t_now, a_time, b);
  }

  /// x of the design: T = T_side + noise; u = s (opening + tilt eta)/2 n + noise with s = -1
  /// on side a, +1 on side b, put in each node's frame (constrained unknowns: as prescribed).
  Vector state(kiln::CoupledProblem &problem, const Design &design) const
  {
    const auto map = problem.solution_map();
    const auto &owned = dofs.owned_nodes();
    // The frame: the physical direction of each displacement unknown (0 if constrained).
    const std::vector<std::array<Point, 3>> q = node_frames(problem);
    Vector x(map);
    problem.initial_condition(t_now, x);
    for (std::size_t i = 0; i < owned.size(); ++i)
    {
      const int n = owned[i];
      const double s = side_b[n] ? 1.0 : -1.0;
      x.replaceLocalValue(static_cast<LO>(4 * i),
                          (side_b[n] ? design.T_b : design.T_a) + design.T_noise * noise_T[n]);
      Point u{};
      for (int d = 0; d < 3; ++d)
        u[d] = s * 0.5 * (design.opening + design.tilt * eta[n]) * normal[d] +
               design.u_noise * noise_u[n][d];
      for (int k = 0; k < 3; ++k)
      {
        const double length = std::sqrt(dot(q[i][k], q[i][k]));
        if (length > 0.5)
        {
          EXPECT_NEAR(length, 1.0, 1e-12) << "frame of node " << n;
          x.replaceLocalValue(static_cast<LO>(4 * i + 1 + k), dot(q[i][k], u));
        }
        else
          EXPECT_EQ(length, 0.0) << "frame of node " << n;
      }
    }
    return x;
  }

  /// Every pair's P, c g and state at x, from a "Min" problem with complementarity scale
  /// `scale`: P = -traction where in contact, else (F_b - F_a)/(2A) of the normal rows.
  PairStates pair_states(kiln::CoupledProblem &min_problem, const Vector &x,
                         const double scale) const
  {
    const int N = mesh.n_nodes();
    const auto map = min_problem.solution_map();
    const kiln::CoupledProblem::ContactOutput out = min_problem.contact_output(x);
    Vector f(map);
    min_problem.evaluate(x, &f, nullptr);
    // Per mesh node (on every rank): u, and the normal row of F (the unknown along n).
    std::vector<double> local(4 * static_cast<std::size_t>(N), 0.0), global(local.size(), 0.0);
    const auto &owned = dofs.owned_nodes();
    const std::vector<Point> u = min_problem.node_displacements(x);
    {
      const auto fv = f.getData();
      Vector probe(map);
      const std::vector<Point> u0 = min_problem.node_displacements(probe);
      for (int k = 0; k < 3; ++k)
      {
        probe.putScalar(0.0);
        for (std::size_t i = 0; i < owned.size(); ++i)
          probe.replaceLocalValue(static_cast<LO>(4 * i + 1 + k), 1.0);
        const std::vector<Point> uk = min_problem.node_displacements(probe);
        for (std::size_t i = 0; i < owned.size(); ++i)
        {
          const Point qk{uk[i][0] - u0[i][0], uk[i][1] - u0[i][1], uk[i][2] - u0[i][2]};
          if (pair_of_node[owned[i]] >= 0 && std::abs(dot(qk, normal) - 1.0) < 1e-9)
            local[4 * owned[i] + 3] = fv[4 * i + 1 + k];
        }
      }
      for (std::size_t i = 0; i < owned.size(); ++i)
        for (int d = 0; d < 3; ++d)
          local[4 * owned[i] + d] = u[i][d];
    }
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 4 * N, local.data(), global.data());

    PairStates s;
    const double modulus = material.lame_lambda() + 2.0 * material.shear_modulus();
    s.min_abs_P = s.min_abs_cg = 1e300;
    for (const kiln::GapPair &pair : mesh.gap_pairs)
    {
      const std::size_t a = pair.node_a, b = pair.node_b;
      const Point du{global[4 * b] - global[4 * a], global[4 * b + 1] - global[4 * a + 1],
                     global[4 * b + 2] - global[4 * a + 2]};
      const double g = dot(pair.normal, du);
      const double c = scale * modulus / std::sqrt(pair.area);
      const bool active = out.active[a] == 1.0;
      EXPECT_EQ(out.active[a], out.active[b]);
      const double F_a = global[4 * a + 3], F_b = global[4 * b + 3];
      const double P = active ? -out.traction[a] : (F_b - F_a) / (2.0 * pair.area);
      if (active)
        s.max_contact_row_error =
            std::max(s.max_contact_row_error,
                     std::abs(F_b - pair.area * c * g) / (pair.area * c * std::abs(g)));
      s.P.push_back(P);
      s.cg.push_back(c * g);
      s.g.push_back(g);
      s.active.push_back(active);
      s.n_active += active;
      EXPECT_EQ(active, P - c * g > 0.0) << "pair of node " << a;
      s.min_relative_margin = std::min(
          s.min_relative_margin, std::abs(P - c * g) / std::max(std::abs(P), std::abs(c * g)));
      s.min_margin = std::min(s.min_margin, std::abs(P - c * g));
      s.min_abs_P = std::min(s.min_abs_P, std::abs(P));
      s.min_abs_cg = std::min(s.min_abs_cg, std::abs(c * g));
    }
    EXPECT_EQ(s.n_active, min_problem.n_active_pairs(x));
    return s;
  }

  /// "node 37 (gap side b) T" or "... u#1 (along n)" for a global unknown id.
  std::string describe(const GO gid) const
  {
    const int n = static_cast<int>(gid / 4), slot = static_cast<int>(gid % 4);
    std::ostringstream s;
    s << "node " << n;
    if (pair_of_node[n] >= 0)
      s << " (gap side " << (side_b[n] ? "b" : "a") << ")";
    else
      s << " (side " << (side_b[n] ? "b" : "a") << ")";
    if (slot == 0)
      s << " T";
    else
      s << " u^" << slot - 1;
    return s.str();
  }

  Point normal{};                ///< of the (plane) gap, from side a to side b
  std::vector<int> pair_of_node; ///< per mesh node: its gap pair or -1
  std::vector<char> side_b;      ///< per mesh node
  std::vector<double> eta;       ///< per mesh node: the block y coordinate [m]
  std::vector<double> noise_T;   ///< per mesh node, in [-1, 1]
  std::vector<Point> noise_u;
};

/// Blocks: (rows T or u) x (columns T or u).
const auto block_of = thermo_mechanical_block;
const auto &block_names = thermo_mechanical_block_names;

struct JacobianCheck
{
  std::array<double, 4> max_J{};        ///< the largest |J| per block
  std::array<double, 4> max_relative{}; ///< max |J - J_fd| / (row's block scale) per block
  std::array<double, 4> max_difference{};
  int count_changes = 0;      ///< perturbed evaluations with another number of active pairs
  double seconds = 0.0;       ///< of the finite differences
  double gap_T_gap_u = 0.0;   ///< max |dF_T/du| over T rows and u columns of gap nodes
  double gap_T_other_u = 0.0; ///< ... over T rows of gap nodes, u columns of other nodes
  PairStates pairs;           ///< at x (run_case)
};

/// J at x against central differences of F, column by column (every rank in lock step).
/// Each entry's difference is measured against the largest |J| or |J_fd| of its row within
/// its block. Expects n_active pairs in contact at x and at every perturbed x.
JacobianCheck check_jacobian(const Fixture &s, kiln::CoupledProblem &problem, Vector &x,
                             const int n_active, const std::string &name)
{
  JacobianCheck result;
  const auto map = problem.solution_map();
  const GO n_global = s.dofs.n_global_dofs();
  const std::size_t n_rows = map->getNodeNumElements();
  Vector f(map);
  Matrix J(problem.jacobian_graph());
  problem.evaluate(x, &f, &J);
  EXPECT_EQ(problem.n_active_pairs(x), n_active) << name;
  const Dense rows = dense_rows(J, n_global);

  const auto start = std::chrono::steady_clock::now();
  const Dense fd = finite_difference_rows(
      problem, x, [](const GO j) { return j % 4 == 0 ? eps_T : eps_u; },
      [&](const Vector &perturbed)
      { result.count_changes += problem.n_active_pairs(perturbed) != n_active; });
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(result.count_changes, 0) << name << ": perturbations changed the active set";

  // Entry by entry, against the row's scale in the block; the worst few are reported.
  struct Miss
  {
    double relative;
    GO row, column;
    double J, fd;
  };
  std::vector<Miss> misses;
  for (std::size_t i = 0; i < n_rows; ++i)
  {
    const GO gi = map->getGlobalElement(static_cast<LO>(i));
    std::array<double, 4> scale{};
    for (GO j = 0; j < n_global; ++j)
    {
      const int k = block_of(gi, j);
      scale[k] = std::max({scale[k], std::abs(rows[i][j]), std::abs(fd[i][j])});
      result.max_J[k] = std::max(result.max_J[k], std::abs(rows[i][j]));
    }
    for (GO j = 0; j < n_global; ++j)
    {
      const int k = block_of(gi, j);
      const double difference = std::abs(rows[i][j] - fd[i][j]);
      if (difference == 0.0)
        continue;
      const double relative = difference / scale[k];
      result.max_difference[k] = std::max(result.max_difference[k], difference);
      result.max_relative[k] = std::max(result.max_relative[k], relative);
      if (relative > tolerance)
        misses.push_back({relative, gi, j, rows[i][j], fd[i][j]});
    }
    // Heat rows of gap nodes against displacements.
    const int node = static_cast<int>(gi / 4);
    if (gi % 4 == 0 && s.pair_of_node[node] >= 0)
      for (GO j = 0; j < n_global; ++j)
      {
        if (j % 4 == 0)
          continue;
        const double v = std::abs(rows[i][j]);
        const int column_node = static_cast<int>(j / 4);
        (s.pair_of_node[column_node] >= 0 ? result.gap_T_gap_u : result.gap_T_other_u) = std::max(
            s.pair_of_node[column_node] >= 0 ? result.gap_T_gap_u : result.gap_T_other_u, v);
      }
  }
  std::sort(misses.begin(), misses.end(),
            [](const Miss &a, const Miss &b) { return a.relative > b.relative; });
  for (std::size_t m = 0; m < std::min<std::size_t>(misses.size(), 20); ++m)
    ADD_FAILURE() << name << ": row " << misses[m].row << " = " << s.describe(misses[m].row)
                  << ", column " << misses[m].column << " = " << s.describe(misses[m].column)
                  << ": J = " << misses[m].J << ", finite difference " << misses[m].fd
                  << " (relative difference " << misses[m].relative << ")";
  if (misses.size() > 20)
    ADD_FAILURE() << name << ": " << misses.size() << " entries beyond the tolerance";

  const auto &comm = *s.comm;
  std::array<double, 4> global{};
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 4, result.max_J.data(), global.data());
  result.max_J = global;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 4, result.max_relative.data(), global.data());
  result.max_relative = global;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 4, result.max_difference.data(), global.data());
  result.max_difference = global;
  std::array<double, 3> gap_local{result.gap_T_gap_u, result.gap_T_other_u, result.seconds},
      gap_global{};
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 3, gap_local.data(), gap_global.data());
  result.gap_T_gap_u = gap_global[0];
  result.gap_T_other_u = gap_global[1];
  result.seconds = gap_global[2];
  if (comm.getRank() == 0)
  {
    std::cout << name << " (" << n_global << " unknowns, " << n_active << " of "
              << problem.n_pairs() << " pairs in contact; finite differences " << result.seconds
              << " s):";
    for (int k = 0; k < 4; ++k)
      std::cout << "\n  block " << block_names[k] << ": max |J| = " << result.max_J[k]
                << ", max |J - J_fd| = " << result.max_difference[k]
                << ", max relative to the row = " << result.max_relative[k];
    std::cout << "\n  heat rows of gap nodes: max |dF/du| over gap nodes' u " << result.gap_T_gap_u
              << ", over other nodes' u " << result.gap_T_other_u << "\n";
  }
  return result;
}

void print_pairs(const Fixture &s, const std::string &name, const PairStates &p)
{
  if (s.comm->getRank() != 0)
    return;
  std::cout << name << ": " << p.n_active << " of " << p.P.size()
            << " pairs in contact; min |P - c g| = " << p.min_margin
            << " Pa, min |P - c g| / max(|P|, |c g|) = " << p.min_relative_margin
            << ", min |P| = " << p.min_abs_P << " Pa, min |c g| = " << p.min_abs_cg << " Pa; P in ["
            << *std::min_element(p.P.begin(), p.P.end()) << ", "
            << *std::max_element(p.P.begin(), p.P.end()) << "] Pa, g in ["
            << *std::min_element(p.g.begin(), p.g.end()) << ", "
            << *std::max_element(p.g.begin(), p.g.end())
            << "] m; closed pairs' rows F_b = A c g to " << p.max_contact_row_error << "\n";
}

/// One case: the problem with `function` and `model`, the state of `design`; expects
/// `expected_active` pairs in contact (-1: some but not all). With `freeze`, the temperature
/// is frozen at its values in x (CoupledProblem::freeze_temperature).
JacobianCheck run_case(const std::string &name, const Design &design, const std::string &function,
                       const double scale, const Conductance model, const int expected_active,
                       const bool freeze = false, const kiln::MaterialMap *materials = nullptr)
{
  Fixture s;
  EXPECT_EQ(static_cast<int>(s.mesh.gap_pairs.size()), 16);
  if (s.comm->getSize() > 1 && s.comm->getRank() == 0)
  {
    // How the partition cuts the gap: pairs whose nodes have different owners, gap faces
    // whose cells are on different ranks.
    int split_pairs = 0, split_faces = 0;
    for (const kiln::GapPair &pair : s.mesh.gap_pairs)
      split_pairs += s.dofs.node_owner()[pair.node_a] != s.dofs.node_owner()[pair.node_b];
    for (const kiln::GapFace &face : s.mesh.gap_faces)
      split_faces += s.cell_rank[face.cell_a] != s.cell_rank[face.cell_b];
    std::cout << name << ": " << split_pairs << " of 16 pairs have their nodes on two ranks, "
              << split_faces << " of " << s.mesh.gap_faces.size() << " gap faces their cells\n";
  }
  const Teuchos::ParameterList thermal = thermal_block(model, design.T_a);
  auto problem =
      s.problem(thermal, mechanics_block(function, scale, 0.5 * design.opening), materials);
  auto min_problem =
      s.problem(thermal, mechanics_block("Min", scale, 0.5 * design.opening), materials);
  EXPECT_EQ(problem->n_pairs(), 16);
  s.set_time(*problem, design);
  s.set_time(*min_problem, design);
  Vector x = s.state(*problem, design);
  if (freeze)
    problem->freeze_temperature(&x);

  const PairStates pairs = s.pair_states(*min_problem, x, scale);
  print_pairs(s, name, pairs);
  if (expected_active >= 0)
    EXPECT_EQ(pairs.n_active, expected_active) << name;
  else
  {
    EXPECT_GT(pairs.n_active, 0) << name;
    EXPECT_LT(pairs.n_active, 16) << name;
  }
  EXPECT_GE(pairs.min_relative_margin, margin_fraction) << name << ": a pair is near its switch";
  EXPECT_LE(pairs.max_contact_row_error, 1e-12) << name << ": the contact row is not A c g";

  JacobianCheck check = check_jacobian(s, *problem, x, pairs.n_active, name);
  check.pairs = pairs;
  for (int k = 0; k < 4; ++k)
    EXPECT_LE(check.max_relative[k], tolerance) << name << ", block " << block_names[k];
  EXPECT_GT(check.max_J[0], 0.0);
  EXPECT_GT(check.max_J[2], 0.0);
  EXPECT_GT(check.max_J[3], 0.0);
  if (model == Conductance::constant || freeze)
  {
    EXPECT_EQ(check.max_J[1], 0.0) << name << ": heat rows depend on u";
  }
  if (freeze)
  {
    EXPECT_EQ(check.max_J[0], 1.0) << name << ": frozen heat rows are not T - T_x";
  }
  return check;
}
} // namespace

TEST(ContactJacobian, AllPairsOpen)
{
  Design d;
  d.T_a = d.T_b = 290.0;
  d.opening = 2.0e-6;
  run_case("open (Min)", d, "Min", 1.0, Conductance::constant, 0);
}

TEST(ContactJacobian, AllPairsClosed)
{
  Design d;
  d.T_a = d.T_b = 308.0;
  d.opening = -2.0e-6;
  run_case("closed (Min)", d, "Min", 1.0, Conductance::constant, 16);
}

TEST(ContactJacobian, SomePairsClosed)
{
  Design d;
  d.T_a = d.T_b = T_ref;
  d.T_noise = 0.2;
  d.tilt = 5.0e-4;
  run_case("mixed (Min)", d, "Min", 1.0, Conductance::constant, -1);
}

TEST(ContactJacobian, FischerBurmeister)
{
  Design d;
  d.T_a = 304.0;
  d.T_b = 306.0;
  d.opening = 5.0e-7;
  d.tilt = 5.0e-4;
  const JacobianCheck check = run_case("tilted (Fischer-Burmeister)", d, "Fischer-Burmeister", 0.5,
                                       Conductance::constant, -1);
  // Away from the kink of Fischer-Burmeister at P = c g = 0.
  const double size = std::max(check.pairs.min_abs_P, check.pairs.min_abs_cg);
  EXPECT_GT(check.pairs.min_abs_P, 0.1 * size);
  EXPECT_GT(check.pairs.min_abs_cg, 0.1 * size);
}

TEST(ContactJacobian, ContactDependentConductanceOpen)
{
  // Both sides colder than T_ref: p < 0 at every face, so only dh/dg acts (on the gap
  // nodes' displacements).
  Design d;
  d.T_a = 293.0;
  d.T_b = 284.0;
  d.opening = 2.0e-6;
  const JacobianCheck check = run_case("open, Contact Dependent conductance", d, "Min", 1.0,
                                       Conductance::contact_dependent, 0);
  EXPECT_GT(check.gap_T_gap_u, 1.0e3); // ~ jump * area * h0 L / (L + g)^2
  EXPECT_EQ(check.gap_T_other_u, 0.0);
}

/// Both sides warmer than T_ref and pushed together: p > 0 at every face, g < 0, so only
/// dh/dp acts (on the displacements of all nodes of the two cells, and the temperatures).
/// `materials`: a material per block (null: the fixture's everywhere).
void check_closed_contact_dependent(const std::string &name, const kiln::MaterialMap *materials)
{
  Design d;
  d.T_a = 312.0;
  d.T_b = 303.0;
  d.opening = -2.0e-6;
  const JacobianCheck check =
      run_case(name, d, "Min", 1.0, Conductance::contact_dependent, 16, false, materials);
  EXPECT_GT(check.gap_T_other_u, 1.0e3); // ~ jump * area * h_p (lambda + 2G) / h
  EXPECT_GT(check.gap_T_gap_u, 1.0e3);
}

/// Open (g > 0) but warmer than T_ref: p > 0 at every face as well, so dh/dg and dh/dp both
/// act; P > 0 but c g larger, so every pair stays open.
void check_open_under_compression(const std::string &name, const kiln::MaterialMap *materials)
{
  Design d;
  d.T_a = 303.0;
  d.T_b = 309.0;
  d.opening = 6.0e-6;
  const JacobianCheck check =
      run_case(name, d, "Min", 1.0, Conductance::contact_dependent, 0, false, materials);
  EXPECT_GT(check.gap_T_gap_u, 1.0e3);
  EXPECT_GT(check.gap_T_other_u, 1.0e3);
}

TEST(ContactJacobian, ContactDependentConductanceClosed)
{
  check_closed_contact_dependent("closed, Contact Dependent conductance", nullptr);
}

TEST(ContactJacobian, ContactDependentConductanceOpenUnderCompression)
{
  check_open_under_compression("open and warm, Contact Dependent conductance", nullptr);
}

/// Two materials on the two sides of the gap (the Contact Dependent conductance takes each
/// side's own, issue 31): block 1 the fixture's (E 70 GPa, nu 0.33, alpha 2.2e-5, k(T)), so
/// that the contact scale is the same; block 2 a steel with E(T) a table (210 GPa at 280 K, 170
/// GPa at 320 K), nu 0.3 and alpha(T) a formula (the secant coefficient from T_ref = 298 K).
kiln::MaterialMap two_materials()
{
  Teuchos::ParameterList kiln_user;
  Teuchos::ParameterList &a = kiln_user.sublist("Materials").sublist("aluminium");
  a.set("Blocks", ids({1}));
  a.set("Young's Modulus", TableMaterial::youngs);
  a.set("Poisson's Ratio", TableMaterial::poisson);
  a.set("Thermal Expansion", TableMaterial::alpha);
  a.set("Reference Temperature", TableMaterial::T_ref);
  Teuchos::ParameterList &k = a.sublist("Conductivity");
  k.set("Type", "Table");
  k.set("Temperatures", values({200.0, 280.0, 400.0}));
  k.set("Values", values({300.0, 120.0, 360.0}));
  Teuchos::ParameterList &b = kiln_user.sublist("Materials").sublist("steel");
  b.set("Blocks", ids({2}));
  Teuchos::ParameterList &E = b.sublist("Young's Modulus");
  E.set("Type", "Table");
  E.set("Temperatures", values({280.0, 320.0}));
  E.set("Values", values({2.1e11, 1.7e11}));
  b.set("Poisson's Ratio", 0.3);
  Teuchos::ParameterList &alpha = b.sublist("Thermal Expansion");
  alpha.set("Type", "Expression");
  alpha.set("Expression", "1.2e-5 + 4e-8*(T - 298)");
  b.set("Reference Temperature", TableMaterial::T_ref);
  b.set("Conductivity", 50.0);
  return material_map(kiln_user, {1, 2});
}

TEST(ContactJacobian, ContactDependentConductanceTwoMaterialsClosed)
{
  // dh/dp through each side's tangent and dsigma/dT (the general path of the model layer on
  // side b).
  const kiln::MaterialMap materials = two_materials();
  check_closed_contact_dependent("closed, two materials, Contact Dependent conductance",
                                 &materials);
}

TEST(ContactJacobian, ContactDependentConductanceTwoMaterialsOpenUnderCompression)
{
  const kiln::MaterialMap materials = two_materials();
  check_open_under_compression("open and warm, two materials, Contact Dependent conductance",
                               &materials);
}

TEST(ContactJacobian, FrozenTemperatureWithContact)
{
  // freeze_temperature() replaces the heat rows (T - T_x: identity, the contact-dependent
  // conductance's u columns gone); the force rows keep their temperature columns.
  Design d;
  d.T_a = 312.0;
  d.T_b = 303.0;
  d.opening = -2.0e-6;
  run_case("closed, temperature frozen", d, "Min", 1.0, Conductance::contact_dependent, 16, true);
}

/// The tied kinds: every pair holds (its rows combined, A c g on each tied axis) in any state;
/// "Sliding" ties the normal axis, "Bonded" every axis the pair's nodes leave free (at gap
/// nodes on faces 3 and 5, the roller takes one). The states are the tilted one of
/// Fischer-Burmeister, half of whose pairs are open under "Contact", and a closed one with
/// the contact-dependent conductance (its dh/dg and dh/dp terms).
void run_tied_case(const std::string &name, const std::string &kind, const Design &design,
                   const Conductance model)
{
  Fixture s;
  const Teuchos::ParameterList thermal = thermal_block(model, design.T_a);
  auto problem = s.problem(thermal, mechanics_block("", 0.5, 0.5 * design.opening, kind));
  ASSERT_EQ(problem->n_pairs(), 16);
  s.set_time(*problem, design);
  Vector x = s.state(*problem, design);
  const JacobianCheck check = check_jacobian(s, *problem, x, 16, name);
  for (int k = 0; k < 4; ++k)
    EXPECT_LE(check.max_relative[k], tolerance) << name << ", block " << block_names[k];
  EXPECT_GT(check.max_J[2], 0.0);
  EXPECT_GT(check.max_J[3], 0.0);
  // Every pair holds, open or closed.
  const kiln::CoupledProblem::ContactOutput out = problem->contact_output(x);
  for (const kiln::GapPair &pair : s.mesh.gap_pairs)
    EXPECT_EQ(out.active[pair.node_a], 1.0) << name << ": pair of node " << pair.node_a;
}

TEST(ContactJacobian, SlidingTilted)
{
  Design d;
  d.T_a = 304.0;
  d.T_b = 306.0;
  d.opening = 5.0e-7;
  d.tilt = 5.0e-4;
  run_tied_case("tilted (Sliding)", "Sliding", d, Conductance::constant);
}

TEST(ContactJacobian, BondedTilted)
{
  Design d;
  d.T_a = 304.0;
  d.T_b = 306.0;
  d.opening = 5.0e-7;
  d.tilt = 5.0e-4;
  run_tied_case("tilted (Bonded)", "Bonded", d, Conductance::constant);
}

TEST(ContactJacobian, BondedClosedContactDependentConductance)
{
  Design d;
  d.T_a = 312.0;
  d.T_b = 303.0;
  d.opening = -2.0e-6;
  run_tied_case("closed, Contact Dependent conductance (Bonded)", "Bonded", d,
                Conductance::contact_dependent);
}

TEST(ContactJacobian, BondedTiesMoreThanSliding)
{
  // With random tangential displacements, the bonded rows (A c t.(u_b - u_a) on the tangent
  // axes) differ from the sliding ones (the sides' own rows there); the normal rows agree.
  Design d;
  d.opening = 5.0e-7;
  Fixture s;
  const Teuchos::ParameterList thermal = thermal_block(Conductance::constant, d.T_a);
  auto sliding = s.problem(thermal, mechanics_block("", 0.5, 0.5 * d.opening, "Sliding"));
  auto bonded = s.problem(thermal, mechanics_block("", 0.5, 0.5 * d.opening, "Bonded"));
  s.set_time(*sliding, d);
  s.set_time(*bonded, d);
  const Vector x = s.state(*sliding, d);
  Vector f_sliding(sliding->solution_map()), f_bonded(bonded->solution_map());
  sliding->evaluate(x, &f_sliding, nullptr);
  bonded->evaluate(x, &f_bonded, nullptr);
  f_bonded.update(-1.0, f_sliding, 1.0);
  EXPECT_GT(f_bonded.normInf(), 1e-6 * f_sliding.normInf());
}
