// The thermal part of the contact box, variant A (inputs/contact-box-close.xml and
// contact-box-open.xml as they are): at every output time the temperature is symmetric
// about the gap (the mesh, the end-face temperatures and the gap are), and at t = 150 s
// it is uniform at the end-face temperature, 308 K (closing) or 288 K (opening), to 1e-8
// relative.
// KILN_TEST_NP: 1 2
#include "io/input_reader.hpp"
#include "mesh/hex_geometry.hpp"
#include "support/simulation_runs.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <map>
#include <tuple>

namespace
{
using kiln_test::inputs;

/// For each node, the node at its mirror image x' -> -x' in the box frame (phi 45,
/// theta -30), on the other side of the gap.
std::vector<int> mirror_nodes(const kiln::Mesh &mesh)
{
  const auto R = kiln::rotation_matrix(45.0, -30.0);
  // The side of each node: the block of its cells (1: x' < 0, 2: x' > 0).
  std::vector<int> block(mesh.n_nodes(), 0);
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (const int n : mesh.cell_nodes(c))
      block[n] = mesh.block_id[c];
  const auto key = [&](const int n, const bool mirrored)
  {
    std::array<long, 3> k{};
    for (int j = 0; j < 3; ++j)
    {
      double xj = 0.0; // x'_j = (A^T x)_j
      for (int i = 0; i < 3; ++i)
        xj += R[i][j] * mesh.coordinates[n][i];
      k[j] = std::lround((mirrored && j == 0 ? -xj : xj) * 1e6); // 1 um grid
    }
    return std::make_tuple(k[0], k[1], k[2], mirrored ? 3 - block[n] : block[n]);
  };
  std::map<std::tuple<long, long, long, int>, int> node_at;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    node_at[key(n, false)] = n;
  std::vector<int> mirror(mesh.n_nodes(), -1);
  for (int n = 0; n < mesh.n_nodes(); ++n)
    mirror[n] = node_at.at(key(n, true));
  return mirror;
}

void check_variant_a(const std::string &name, const double final_temperature)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string path = inputs + name;
  auto sim = std::make_unique<kiln::Simulation>(kiln::read_input(path, *comm), path, comm);
  sim->setup();
  const std::vector<int> mirror = mirror_nodes(sim->mesh());
  kiln::CoupledProblem &problem = sim->problem();
  kiln_test::Vector x(problem.solution_map());
  problem.initial_condition(0.0, x);
  std::vector<double> times_seen;
  std::vector<double> final_T;
  kiln_test::run_from(*sim, x, {0.0, 50.0, 53.0, 150.0},
                      [&](const double t, int, double, const kiln_test::Vector &state)
                      {
                        times_seen.push_back(t);
                        const auto T = kiln_test::all_node_values(*sim, state);
                        double asymmetry = 0.0;
                        for (int n = 0; n < sim->mesh().n_nodes(); ++n)
                          asymmetry = std::max(asymmetry, std::abs(T[n] - T[mirror[n]]));
                        std::cout << name << ": t = " << t
                                  << " s, max |T - T_mirror| = " << asymmetry << " K\n";
                        EXPECT_LE(asymmetry, 1e-8 * final_temperature) << "t = " << t;
                        final_T = T;
                      });
  EXPECT_EQ(times_seen, (std::vector<double>{0.0, 50.0, 53.0, 150.0}));
  double deviation = 0.0;
  for (const double T : final_T)
    deviation = std::max(deviation, std::abs(T - final_temperature));
  std::cout << name << ": t = 150 s, max |T - " << final_temperature << "| = " << deviation
            << " K\n";
  EXPECT_LE(deviation, 1e-8 * final_temperature);
}
} // namespace

TEST(ContactBoxThermal, ClosingIsSymmetricAndReaches308K)
{
  check_variant_a("contact-box-close.xml", 308.0);
}

TEST(ContactBoxThermal, OpeningIsSymmetricAndReaches288K)
{
  check_variant_a("contact-box-open.xml", 288.0);
}
