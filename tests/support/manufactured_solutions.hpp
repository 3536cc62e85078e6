#pragma once
/// Manufactured-solution convergence studies on every element type (tests/verification/mms_*):
/// the exact fields, decks on the generated unit cube [0,1]^3 with the exact values prescribed
/// on its six faces, a steady run, and the L2 and H1-seminorm errors of the nodal solution
/// interpolated by each cell's own basis (any type, mixed meshes too).
///
/// Kiln takes no volumetric source (no heat source, one constant body force), so the exact
/// fields solve the homogeneous equations (doc/verification/manufactured-solutions.md):
/// - heat, constant k: T = T0 + A h, h = sin(a x + 0.3) cos(b y + 0.2) exp(c (z - 1)),
///   c^2 = a^2 + b^2, so that h is harmonic;
/// - heat, k(T) = k0 (1 + beta (T - T0)): the Kirchhoff transform of T is k0 A h, so that
///   T = T0 + (sqrt(1 + 2 beta A h) - 1) / beta;
/// - elasticity, constant E, nu: u = s grad h (div u = 0 and Laplace u = 0: Navier's equation
///   holds whatever lambda and G);
/// - thermo-elasticity with E(T), alpha(T) under the steady T = T0 + g z: u = s grad p(x, y) +
///   w(z) e_z with p = sin(a x + 0.3) exp(a (y - 1)) harmonic in (x, y), so that the
///   deviatoric stress 2 G(z) grad grad p has no z row, and w' = (sigma_zz + beta(T) (T - T0))
///   / M(T) with a uniform sigma_zz, so that u_z depends on E(T) (nu constant: beta / M =
///   (1 + nu) / (1 - nu) alpha).
#include "support/simulation_runs.hpp"

#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace kiln_test::mms
{
/// An exact field of 1 (temperature) or 3 (displacement) components: value[i] and
/// gradient[i] = grad of component i at a point.
struct ExactField
{
  int n_components = 1;
  std::function<void(const kiln::Point &, double *value, kiln::Point *gradient)> evaluate;
  /// The muparser formula of each component in x, y, z (the Dirichlet values of the deck).
  std::vector<std::string> formulas;
};

/// L2 norm and H1 seminorm of the error (all components together).
struct Errors
{
  double l2 = 0.0;
  double h1 = 0.0;
};

/// The errors of the field given by its values at every node (node-major: n_components values
/// per node, all nodes, replicated on every rank) against `exact`, integrated over the owned
/// cells (summed over the ranks) with 5^3 collapsed Gauss points per cell (degree 7 at least in
/// the reference coordinates of every type), the geometry and the field interpolated by the
/// cell's own basis.
Errors field_errors(const kiln::Simulation &sim, const std::vector<double> &nodal,
                    const ExactField &exact);

/// u at every node (3 per node, owned values summed over the ranks).
std::vector<double> all_node_displacements(const kiln::Simulation &sim, const Vector &x);

/// The problems of the studies.
enum class Problem
{
  heat,                   ///< constant k, T of the harmonic h
  heat_k_expression,      ///< k(T) = 1 + 0.02 (T - 300) given as an Expression in T
  heat_k_table,           ///< the same k(T) as a Table of two points
  elasticity,             ///< constant E, nu; u = s grad h
  thermoelastic_e_alpha_t ///< E(T), alpha(T) under T = 300 + 20 z; u of p and w
};

/// The exact solution of `problem` (temperature or displacement).
ExactField exact_solution(Problem problem);

/// The deck of `problem` on the unit cube of n^3 cells of `cell_type` (a "Cell Type" of the
/// box generator), steady, solver tolerances tight.
std::string deck(Problem problem, const std::string &cell_type, int n);

/// One steady run of deck(problem, cell_type, n): the errors of its field.
Errors run(Problem problem, const std::string &cell_type, int n);

/// log2(coarse / fine) of each error (refinements by 2).
Errors orders(const Errors &coarse, const Errors &fine);

/// Runs `problem` on n = each of `cells`, prints a line per run ("<label> <type> n: L2 e, H1 e,
/// orders o o", which doc/verification/manufactured-solutions.md tabulates) and returns the
/// errors.
std::vector<Errors> study(Problem problem, const std::string &label, const std::string &cell_type,
                          const std::vector<int> &cells);

/// A cell type and its refinements; the orders asserted on the last refinement.
struct Case
{
  std::string cell_type;
  std::vector<int> cells;
  double min_l2_order;
  double min_h1_order;
};

/// How gtest prints a Case (its cell type) in a failure.
inline void PrintTo(const Case &c, std::ostream *os)
{
  *os << c.cell_type;
}

/// A Case's test name (its cell type), for INSTANTIATE_TEST_SUITE_P.
inline std::string case_name(const ::testing::TestParamInfo<Case> &param)
{
  return param.param.cell_type;
}

/// study() then EXPECT_GE on the last orders.
void check_orders(Problem problem, const std::string &label, const Case &c);

/// The linear types: HEX8, TETRA4, WEDGE6, PYRAMID5, MIXED on 4, 8, 16 cells along each edge:
/// L2 >= 1.8, H1 >= 0.9.
const std::vector<Case> &linear_types();
/// The quadratic types: TETRA10, HEX20, HEX27 on 2, 4, 8: L2 >= 2.8, H1 >= 1.8.
const std::vector<Case> &quadratic_types();
/// Both.
std::vector<Case> every_type();
/// HEX8 and TETRA4 as in linear_types() (the temperature-dependent properties).
std::vector<Case> hex_and_tet();
} // namespace kiln_test::mms
