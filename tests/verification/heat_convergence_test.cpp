// Convergence of the heat-conduction discretization on a rotated generated mesh, for the
// decay of one cosine mode between two faces held at T0 (insulated elsewhere):
//   T(x', t) = T0 + A exp(-lambda t) cos(pi x' / L),   lambda = k pi^2 / (rho c L^2),
// x' the coordinate along the box's first axis (the box is rotated by phi, theta).
// - Space: BDF2 with small fixed steps on 4 x 2 x 2 ... 32 x 16 x 16 cells; L2 error of
//   order 2 +- 0.1.
// - Time: on uniform Q1 cells the nodal cosine is an exact eigenvector of the discrete
//   operator (Dirichlet ends), so the semi-discrete solution is known exactly:
//   T0 + A exp(-lambda_h t) cos(pi x'/L), theta = pi h / L, with the consistent capacity
//   lambda_h = (k/(rho c)) (6/h^2) (1 - cos(theta)) / (2 + cos(theta)), with the lumped one
//   lambda_h = (k/(rho c)) (2/h^2) (1 - cos(theta)) (the mode is constant across the box, where
//   the lumped and consistent matrices have the same row sums). The error against it is the
//   time-stepping error alone: order 1 for backward Euler, 2 for BDF2, for either capacity.
// Both capacities (Kiln/Thermal/"Capacity") are run; the default's lines are printed as
// doc/verification/report.py reads them, the other's prefixed by its name.
// KILN_TEST_NP: 2
#include "mesh/hex_geometry.hpp"
#include "support/parameter_lists.hpp"
#include "support/simulation_runs.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace
{
constexpr double pi = 3.14159265358979323846;
constexpr double L = 1.0; // box size [m]
constexpr double T0 = 300.0;
constexpr double A = 10.0; // mode amplitude [K]
constexpr double phi = 45.0, theta = -30.0;

/// The box on nx x ny x ny cells, its ends held at T0, k = rho = c = 1, from T0 by `method` in
/// fixed steps dt (minimum dt/10), the capacity `capacity`; Newton to 1e-10 absolute, 1e-12
/// relative.
Teuchos::ParameterList deck(const int nx, const int ny, const std::string &method, const double dt,
                            const std::string &capacity)
{
  using namespace kiln_test;
  Teuchos::ParameterList input("Kiln");
  input.set("Mesh", box_mesh({L, L, L}, {nx, ny, ny}));
  input.sublist("Mesh").sublist("Box").set("Phi", phi).set("Theta", theta);
  Teuchos::ParameterList &material = input.sublist("Material");
  material.set("Density", 1.0).set("Specific Heat", 1.0);
  material.sublist("Conductivity").set("Value", 1.0);
  input.sublist("Thermal").set("Initial Temperature", T0).set("Capacity", capacity);
  thermal_conditions(input).set("ends", temperature({1, 2}, T0));
  input.sublist("Time Stepping")
      .set("Method", method)
      .set("Initial Step", dt)
      .set("Maximum Step", dt)
      .set("Minimum Step", dt / 10)
      .set("Growth Factor", 1.0)
      .set("Error Control", false);
  input.set("Solver", newton_tolerances(1e-10, 1e-12));
  return input;
}

/// x' = (A^T x)_0: the coordinate along the box's first axis.
double box_x(const kiln::Point &x)
{
  const auto R = kiln::rotation_matrix(phi, theta);
  return R[0][0] * x[0] + R[1][0] * x[1] + R[2][0] * x[2];
}

double mode(const kiln::Point &x)
{
  return std::cos(pi * box_x(x) / L);
}

struct Result
{
  std::vector<double> nodal; ///< all nodes
  std::unique_ptr<kiln::Simulation> sim;
};

/// Runs from the exact initial state to t_end; the temperatures at t_end.
Result run(const int nx, const int ny, const std::string &method, const double dt,
           const double t_end, const std::string &capacity)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  Result r;
  r.sim = kiln_test::make_simulation(deck(nx, ny, method, dt, capacity), comm);
  kiln::CoupledProblem &problem = r.sim->problem();
  kiln_test::Vector x(problem.solution_map());
  kiln_test::interpolate(
      *r.sim, [](const kiln::Point &p) { return T0 + A * mode(p); }, x);
  const auto stats = kiln_test::run_from(*r.sim, x, {t_end});
  EXPECT_EQ(stats.steps, static_cast<int>(std::lround(t_end / dt)));
  r.nodal = kiln_test::all_node_values(*r.sim, x);
  return r;
}

double order(const double coarse_error, const double fine_error)
{
  return std::log2(coarse_error / fine_error);
}

/// "" for the default capacity (Lumped), else "Consistent capacity: ".
std::string prefix(const std::string &capacity)
{
  return capacity == "Lumped" ? std::string() : capacity + " capacity: ";
}
} // namespace

class HeatConvergence : public ::testing::TestWithParam<std::string>
{
};

TEST_P(HeatConvergence, SpatialL2OrderTwo)
{
  const std::string capacity = GetParam();
  const double lambda = pi * pi / (L * L); // k / (rho c) = 1
  // Small steps: the first step (backward Euler) leaves an O(dt^2) error that must stay
  // well below the spatial error of the finest mesh.
  const double dt = 2.5e-4, t_end = 5e-3;
  std::vector<double> errors;
  for (const int n : {4, 8, 16, 32})
  {
    // The solution does not vary across the box: half the cells there keep it cheap.
    const Result r = run(n, n / 2, "BDF2", dt, t_end, capacity);
    const double decay = std::exp(-lambda * t_end);
    errors.push_back(kiln_test::l2_error(
        *r.sim, r.nodal, [&](const kiln::Point &p) { return T0 + A * decay * mode(p); }));
  }
  // Every error is printed (doc/verification/report.py plots them), with the order from the
  // coarser mesh.
  for (std::size_t i = 0; i < errors.size(); ++i)
  {
    std::cout << prefix(capacity) << "cells " << (4 << i) << " x " << (2 << i) << " x " << (2 << i)
              << ": L2 error " << errors[i];
    if (i > 0)
      std::cout << ", order " << order(errors[i - 1], errors[i]);
    std::cout << "\n";
  }
  // The asymptotic range: the last two refinements.
  EXPECT_NEAR(order(errors[1], errors[2]), 2.0, 0.1);
  EXPECT_NEAR(order(errors[2], errors[3]), 2.0, 0.1);
}

/// Max nodal error against the exact semi-discrete solution, for steps dt, dt/2, ...
std::vector<double> temporal_errors(const std::string &method, const std::string &capacity)
{
  constexpr int nx = 8;
  const double h = L / nx;
  const double c = std::cos(pi * h / L);
  const double lambda_h =
      capacity == "Lumped" ? 2.0 / (h * h) * (1.0 - c) : 6.0 / (h * h) * (1.0 - c) / (2.0 + c);
  const double t_end = 0.1;
  std::vector<double> errors;
  for (const double dt : {0.02, 0.01, 0.005, 0.0025})
  {
    const Result r = run(nx, 2, method, dt, t_end, capacity);
    double e = 0.0;
    for (int n = 0; n < r.sim->mesh().n_nodes(); ++n)
    {
      const double exact =
          T0 + A * std::exp(-lambda_h * t_end) * mode(r.sim->mesh().coordinates[n]);
      e = std::max(e, std::abs(r.nodal[n] - exact));
    }
    errors.push_back(e);
    std::cout << prefix(capacity) << method << " dt " << dt << ": max nodal error " << e << "\n";
  }
  return errors;
}

TEST_P(HeatConvergence, BackwardEulerOrderOne)
{
  const std::vector<double> e = temporal_errors("Backward Euler", GetParam());
  for (std::size_t i = 1; i < e.size(); ++i)
    std::cout << "order " << order(e[i - 1], e[i]) << "\n";
  EXPECT_NEAR(order(e[2], e[3]), 1.0, 0.1);
}

TEST_P(HeatConvergence, Bdf2OrderTwo)
{
  const std::vector<double> e = temporal_errors("BDF2", GetParam());
  for (std::size_t i = 1; i < e.size(); ++i)
    std::cout << "order " << order(e[i - 1], e[i]) << "\n";
  EXPECT_NEAR(order(e[2], e[3]), 2.0, 0.1);
}

INSTANTIATE_TEST_SUITE_P(Capacity, HeatConvergence, ::testing::Values("Lumped", "Consistent"));
