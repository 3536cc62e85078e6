// Convergence of Kiln's Q1 elasticity on two problems with a non-uniform stress and a known
// exact solution, posed with today's loads (a constant body force, temperature BCs, rollers).
// A bar of length L along z (z measured from its bottom face; the generated box is centred
// on the origin), cross-section 0.25 x 0.25 on 2 x 2 x N cells, rollers on its four sides
// (u_x = 0 on the x faces, u_y = 0 on the y faces: uniaxial strain), u_z = 0 on the bottom,
// the top traction free. With M = lambda + 2G:
// - Own weight (Physics Elasticity, body force b_z = -1 N/m^3):
//     sigma_zz = b_z (L - z),  sigma_xx = sigma_yy = lambda / M sigma_zz,
//     u_z = b_z / M (L z - z^2 / 2).
// - Thermal (Physics Thermo-Elasticity, steady, T = T_ref on z = 0 and T_ref + g on z = L,
//   so T = T_ref + g z / L, no body force): sigma_zz = 0, M eps_zz = beta (T - T_ref),
//     u_z = beta g z^2 / (2 M L),  sigma_xx = sigma_yy = (lambda / M - 1) beta (T - T_ref),
//   beta = (3 lambda + 2G) alpha.
// Theory: the solution is one-dimensional, and linear elements in 1D give the exact nodal
// values (the load is integrated exactly); the L2 error of the displacement is then the
// interpolation error of a quadratic, order 2, and the L2 error of the cell-averaged stress
// (piecewise constant against a linear exact stress) is order 1 (its value at the cell
// centre is exact: the cell averages are the exact stress at the centres). The test checks
// the orders of the last refinement (2 +- 0.1 and 1 +- 0.1) and prints every error, which
// doc/verification/report.py tabulates. Errors: L2 of u_z over the bar; L2 of the cell
// stress's xx, yy and zz against the exact stress. A three-dimensional manufactured solution
// needs a body force that varies in space, which Kiln does not take (Mechanics/"Body Force"
// is one constant vector): hence these one-dimensional fields on a 3D mesh.
// KILN_TEST_NP: 2
#include "mesh/hex_geometry.hpp"
#include "physics/coupled_problem.hpp"
#include "support/parallel.hpp"
#include "support/parameter_lists.hpp"
#include "support/simulation_runs.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>

namespace
{
constexpr double L = 1.0;      // bar length [m]
constexpr double E = 1.0;      // Young's modulus [Pa]
constexpr double nu = 0.25;    // Poisson's ratio
constexpr double alpha = 1e-3; // thermal expansion [1/K]
constexpr double T_ref = 300.0;
constexpr double g = 10.0; // temperature rise over the bar [K]
constexpr double b = -1.0; // body force along z [N/m^3]
constexpr double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
constexpr double G = E / (2 * (1 + nu));
constexpr double M = lambda + 2 * G;
constexpr double beta = (3 * lambda + 2 * G) * alpha;

/// The bar on 2 x 2 x n cells on rollers, its bottom held: under its own weight (Elasticity) or
/// heated from T_ref at the bottom to T_ref + g at the top (Thermo-Elasticity, `thermal`);
/// Newton to 1e-14 absolute, 1e-12 relative; results in the temporary folder.
Teuchos::ParameterList deck(const int n, const bool thermal)
{
  using namespace kiln_test;
  Teuchos::ParameterList input = steady_deck(thermal ? "Thermo-Elasticity" : "Elasticity",
                                             box_mesh({0.25, 0.25, L}, {2, 2, n}));
  input.set("Material", young(E, nu));
  input.sublist("Material").set("Thermal Expansion", alpha).set("Reference Temperature", T_ref);
  if (thermal)
  {
    input.sublist("Thermal").set("Initial Temperature", T_ref);
    thermal_conditions(input).set("bottom", temperature({5}, T_ref));
    thermal_conditions(input).set("top", temperature({6}, T_ref + g));
  }
  input.sublist("Mechanics").set("Body Force", values({0.0, 0.0, thermal ? 0.0 : b}));
  mechanical_conditions(input).set("x rollers", displacement({1, 2}, {"x"}));
  mechanical_conditions(input).set("y rollers", displacement({3, 4}, {"y"}));
  mechanical_conditions(input).set("bottom", displacement({5}, {"z"}));
  input.set("Solver", newton_tolerances(1e-14, 1e-12));
  const auto base = std::filesystem::temp_directory_path() /
                    ("kiln-elastic-convergence-" + std::to_string(n) + (thermal ? "-T" : ""));
  input.sublist("Output").set("File Base", base.string());
  return input;
}

struct Exact
{
  double (*u_z)(double z);
  double (*sigma_zz)(double z);
  double (*sigma_xx)(double z);
};

const Exact weight{[](double z) { return b / M * (L * z - z * z / 2); },
                   [](double z) { return b * (L - z); },
                   [](double z) { return lambda / M * b * (L - z); }};
const Exact heated{[](double z) { return beta * g * z * z / (2 * M * L); },
                   [](double) { return 0.0; },
                   [](double z) { return (lambda / M - 1) * beta * g * z / L; }};

struct Errors
{
  double u = 0.0;     ///< L2 of u_z - exact (m * m^1.5)
  double sigma = 0.0; ///< L2 of the cell-averaged stress (xx, yy, zz) - exact
};

/// One run on 2 x 2 x n cells: the L2 errors of u_z and of Kiln's cell stress.
Errors run(const int n, const bool thermal, const Exact &exact)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  auto sim = std::make_unique<kiln::Simulation>(deck(n, thermal), "elastic-convergence.xml", comm);
  sim->run(); // sets up and solves; the output to the temporary folder (File Base)
  kiln::CoupledProblem &problem = sim->problem();
  const kiln_test::Vector &x = sim->solution();

  // u_z at every node (owned values summed over the ranks), then its L2 error.
  std::vector<double> local(sim->mesh().n_nodes(), 0.0), u_z(local.size(), 0.0);
  const auto u = problem.node_displacements(x);
  const auto &owned = sim->dofs().owned_nodes();
  for (std::size_t i = 0; i < owned.size(); ++i)
    local[owned[i]] = u[i][2];
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(),
                     u_z.data());
  Errors e;
  e.u =
      kiln_test::l2_error(*sim, u_z, [&](const kiln::Point &p) { return exact.u_z(p[2] + L / 2); });

  // The cell stress against the exact linear stress: per cell, the integral over z (the
  // cell's z extent [z0, z1], area A) of (s - (a + c z))^2 by 3-point Gauss.
  static const double gz[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  static const double wz[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const auto cells = problem.cell_averages(x);
  const auto &owned_cells = sim->dofs().owned_cells();
  double sum = 0.0;
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    const kiln::HexNodes nodes = kiln::cell_nodes(sim->mesh(), owned_cells[i]);
    double z0 = nodes[0][2], z1 = nodes[0][2], x0 = nodes[0][0], x1 = nodes[0][0], y0 = nodes[0][1],
           y1 = nodes[0][1];
    for (const auto &p : nodes)
    {
      z0 = std::min(z0, p[2]), z1 = std::max(z1, p[2]);
      x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]);
      y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
    }
    const double area = (x1 - x0) * (y1 - y0), half = (z1 - z0) / 2, mid = (z0 + z1) / 2;
    for (int q = 0; q < 3; ++q)
    {
      const double z = mid + half * gz[q] + L / 2; // from the bottom
      const double dxx = cells[i].stress[0] - exact.sigma_xx(z);
      const double dyy = cells[i].stress[1] - exact.sigma_xx(z);
      const double dzz = cells[i].stress[2] - exact.sigma_zz(z);
      sum += (dxx * dxx + dyy * dyy + dzz * dzz) * wz[q] * half * area;
    }
  }
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, sum, Teuchos::outArg(e.sigma));
  e.sigma = std::sqrt(e.sigma);
  return e;
}

double order(const double coarse_error, const double fine_error)
{
  return std::log2(coarse_error / fine_error);
}

/// Runs N = 4 ... 32, prints every error and order (doc/verification/report.py reads the
/// lines "<label> cells N: L2 error u ..., sigma ..."), checks the last orders.
void check_orders(const std::string &label, const bool thermal, const Exact &exact)
{
  std::vector<Errors> errors;
  for (const int n : {4, 8, 16, 32})
  {
    errors.push_back(run(n, thermal, exact));
    kiln_test::rank0_out() << label << " cells " << n << ": L2 error u " << errors.back().u
                           << ", sigma " << errors.back().sigma;
    if (errors.size() > 1)
    {
      const Errors &c = errors[errors.size() - 2];
      kiln_test::rank0_out() << ", orders " << order(c.u, errors.back().u) << " "
                             << order(c.sigma, errors.back().sigma);
    }
    kiln_test::rank0_out() << "\n";
  }
  EXPECT_NEAR(order(errors[2].u, errors[3].u), 2.0, 0.1) << label;
  EXPECT_NEAR(order(errors[2].sigma, errors[3].sigma), 1.0, 0.1) << label;
}
} // namespace

TEST(ElasticConvergence, BarUnderOwnWeight)
{
  check_orders("own weight", false, weight);
}

TEST(ElasticConvergence, HeatedBarThermoElastic)
{
  check_orders("thermal", true, heated);
}
