// Tests src/discretization/nodal_constraints.cpp, every constraint on nodal unknowns:
// - frames: Gram-Schmidt of the constrained directions in the order given, a dependent
//   direction dropped, a free axis right after them (its slot), the coordinate axes last;
// - the first prescribed temperature of a node applies;
// - prescribed components by forward substitution for directions that are not orthogonal,
//   so that n_l . u = g_l(t) holds for the expanded u;
// - temperature() and displacement(): x~, the prescribed values in place of the unknowns;
// - distribute(): rows and columns rotated into the frames, constrained rows and columns
//   removed, a held temperature's row alone removed; residual-only systems alike;
// - add_rows(): s (x - g) and x_T - T_held with the scale of the node;
// - free axes that lean to each other (gaps that cross at an angle): the frame keeps them, the
//   dual basis gives u and the rows, a nearly dependent one is refused.
// KILN_TEST_NP: 1 2
#include "discretization/nodal_constraints.hpp"

#include "discretization/assembler.hpp"
#include "mesh/box_mesh_generator.hpp"
#include "mesh/metis_partitioner.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_Tuple.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{
using kiln::Point;

Point unit(const Point &v)
{
  const double length = std::sqrt(kiln::dot(v, v));
  return {v[0] / length, v[1] / length, v[2] / length};
}

struct Fixture
{
  Teuchos::RCP<const Teuchos::Comm<int>> comm = Teuchos::DefaultComm<int>::getComm();
  kiln::Mesh mesh = []
  {
    Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
    p.set("Size", Teuchos::Array<double>(Teuchos::tuple(1.0, 1.0, 1.0)));
    p.set("Cells", Teuchos::Array<int>(Teuchos::tuple(2, 2, 2)));
    return kiln::BoxMeshGenerator(p, "test/Box").generate();
  }();
  std::vector<int> cell_rank = kiln::partition_cells(mesh, *comm, "test");
  kiln::DofManager dofs{mesh, cell_rank, comm, kiln::DofLayout{true, true, false}};
  kiln::NodalConstraints constraints{mesh, dofs};
};
} // namespace

TEST(NodalConstraints, FramesFollowTheDirectionsInOrder)
{
  Fixture s;
  const int g1 = s.constraints.add_value("one", [](const double t) { return 1e-3 * t; });
  const int g2 = s.constraints.add_value("two", [](const double t) { return -2e-3 * t; });
  const Point n1 = unit({1.0, 1.0, 0.0}), n2 = unit({0.0, 1.0, 0.0});
  // Node 0: two directions at 45 degrees, then one in their span (dropped), then a free axis.
  s.constraints.constrain_direction(0, n1, g1);
  s.constraints.constrain_direction(0, n2, g2);
  s.constraints.constrain_direction(0, unit({1.0, 2.0, 0.0}), g1);
  EXPECT_EQ(s.constraints.directions(0).size(), 2u);
  EXPECT_EQ(s.constraints.add_free_axis(0, {0.0, 0.0, 1.0}), 2);
  // Node 1: a free axis alone is slot 0; node 2: a free axis in the span of its constraint.
  EXPECT_EQ(s.constraints.add_free_axis(1, unit({0.0, 1.0, 1.0})), 0);
  s.constraints.constrain_direction(2, {1.0, 0.0, 0.0}, g1);
  EXPECT_EQ(s.constraints.add_free_axis(2, {1.0, 0.0, 0.0}), -1);
  // Temperatures: the first one given applies.
  const int T1 = s.constraints.add_value("hot", [](double) { return 400.0; });
  const int T2 = s.constraints.add_value("cold", [](double) { return 300.0; });
  s.constraints.constrain_temperature(3, T1);
  s.constraints.constrain_temperature(3, T2);
  s.constraints.close(200.0, 1e11);
  s.constraints.set_time(2.0);

  const auto &q = s.constraints.axes(0);
  EXPECT_EQ(s.constraints.n_constrained(0), 2);
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l)
      EXPECT_NEAR(kiln::dot(q[k], q[l]), k == l ? 1.0 : 0.0, 1e-15);
  EXPECT_NEAR(kiln::dot(q[0], n1), 1.0, 1e-15);
  EXPECT_NEAR(std::abs(q[2][2]), 1.0, 1e-15);
  EXPECT_NEAR(kiln::dot(s.constraints.axes(1)[0], unit({0.0, 1.0, 1.0})), 1.0, 1e-15);
  EXPECT_FALSE(s.constraints.has_frame(4));
  EXPECT_EQ(s.constraints.axes(4)[1], (Point{0.0, 1.0, 0.0}));
  EXPECT_EQ(s.constraints.prescribed_temperature(3, 0.0), 400.0);
  EXPECT_EQ(s.constraints.value_name(s.constraints.directions(0)[1].value), "two");

  // The expanded displacement meets both constraints at t = 2 whatever the unknowns hold.
  const double unknowns[4] = {350.0, 7.0, -3.0, 5e-4};
  const Point u = s.constraints.displacement(0, unknowns);
  EXPECT_NEAR(kiln::dot(n1, u), 2e-3, 1e-17);
  EXPECT_NEAR(kiln::dot(n2, u), -4e-3, 1e-17);
  EXPECT_NEAR(kiln::dot(q[2], u), 5e-4, 1e-17); // the free unknown is kept
  EXPECT_EQ(s.constraints.temperature(0, unknowns), 350.0);
  EXPECT_EQ(s.constraints.temperature(3, unknowns), 400.0);
  const auto u_hat = s.constraints.prescribed_components(0, 2.0);
  EXPECT_NEAR(u_hat[0], 2e-3, 1e-17);
  EXPECT_EQ(u_hat[2], 0.0);
}

TEST(NodalConstraints, LeaningFreeAxesGetTheDualBasis)
{
  // Node 0: a roller along z, then two free axes at 60 degrees in the plane z = 0 (after the
  // roller's part is taken out of the second): the frame (z, n1, n2') is not orthonormal; the
  // unknowns are n_k . u and u = sum_k u_k t_k with the dual axes. Node 1: a free axis, then
  // one within the 1e-3 sine of its span (refused), then a perpendicular one (orthonormal
  // frame, t = q). Node 2: three free axes in one plane: the third is refused.
  Fixture s;
  const int g = s.constraints.add_value("roller", [](const double t) { return 1e-3 * t; });
  const Point z{0.0, 0.0, 1.0}, n1{1.0, 0.0, 0.0};
  const Point n2 = unit({0.5, std::sqrt(3.0) / 2.0, 0.3});
  s.constraints.constrain_direction(0, z, g);
  EXPECT_EQ(s.constraints.add_free_axis(0, n1), 1);
  EXPECT_EQ(s.constraints.add_free_axis(0, n2), 2);
  EXPECT_EQ(s.constraints.add_free_axis(1, n1), 0);
  EXPECT_EQ(s.constraints.add_free_axis(1, unit({1.0, 5e-4, 0.0})), -1);
  EXPECT_EQ(s.constraints.add_free_axis(1, {0.0, 1.0, 0.0}), 1);
  EXPECT_EQ(s.constraints.add_free_axis(2, n1), 0);
  EXPECT_EQ(s.constraints.add_free_axis(2, unit({1.0, 1.0, 0.0})), 1);
  EXPECT_EQ(s.constraints.add_free_axis(2, unit({1.0, -2.0, 0.0})), -1);
  s.constraints.close(1.0, 1.0);
  s.constraints.set_time(2.0);

  EXPECT_FALSE(s.constraints.orthonormal(0));
  EXPECT_TRUE(s.constraints.orthonormal(1));
  EXPECT_TRUE(s.constraints.orthonormal(3));
  const auto &q = s.constraints.axes(0);
  const auto &t = s.constraints.dual_axes(0);
  const Point n2_free = unit({0.5, std::sqrt(3.0) / 2.0, 0.0});
  EXPECT_NEAR(kiln::dot(q[1], n1), 1.0, 1e-15);
  EXPECT_NEAR(kiln::dot(q[2], n2_free), 1.0, 1e-15);
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(kiln::dot(q[j], t[k]), j == k ? 1.0 : 0.0, 1e-15) << j << k;
  EXPECT_EQ(s.constraints.dual_axes(1), s.constraints.axes(1));

  // u from the unknowns: the roller's value along z, and n_k . u = u_k for the free axes.
  const double unknowns[4] = {300.0, 9.0, 3e-4, -7e-4};
  const Point u = s.constraints.displacement(0, unknowns);
  EXPECT_NEAR(kiln::dot(z, u), 2e-3, 1e-18);
  EXPECT_NEAR(kiln::dot(n1, u), 3e-4, 1e-18);
  EXPECT_NEAR(kiln::dot(n2_free, u), -7e-4, 1e-18);

  // distribute(): node 0's rows are t_k . R and its columns J t_k.
  kiln::LocalSystem local(1, 4);
  std::mt19937 random(3u);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for (double &v : local.residual_values())
    v = value(random);
  for (double &v : local.jacobian_values())
    v = value(random);
  kiln::LocalSystem original = local;
  s.constraints.distribute({0}, local);
  for (int k = 1; k < 3; ++k)
  {
    double row = 0.0;
    for (int d = 0; d < 3; ++d)
      row += t[k][d] * original.residual(1 + d, 0);
    EXPECT_NEAR(local.residual(1 + k, 0), row, 1e-15);
    double column = 0.0;
    for (int d = 0; d < 3; ++d)
      column += original.jacobian(0, 0, 1 + d, 0) * t[k][d];
    EXPECT_NEAR(local.jacobian(0, 0, 1 + k, 0), column, 1e-15);
  }
}

TEST(NodalConstraints, DistributeRotatesAndEliminates)
{
  Fixture s;
  const int g = s.constraints.add_value("roller", [](double) { return 0.0; });
  const Point n = unit({1.0, 2.0, 2.0});
  s.constraints.constrain_direction(1, n, g);
  s.constraints.constrain_temperature(2, s.constraints.add_value("T", [](double) { return 1.0; }));
  s.constraints.close(1.0, 1.0);
  s.constraints.set_time(0.0);

  // A random symmetric 3-node system (nodes 0, 1, 2), 4 unknowns each.
  std::mt19937 random(7u);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  kiln::LocalSystem local(3, 4), residual_only(3, 4, false);
  for (int a = 0; a < 12; ++a)
  {
    local.residual_values()[a] = residual_only.residual_values()[a] = value(random);
    for (int b = 0; b <= a; ++b)
      local.jacobian_values()[12 * a + b] = local.jacobian_values()[12 * b + a] = value(random);
  }
  const kiln::LocalSystem original = local;
  const std::vector<int> nodes = {0, 1, 2};
  s.constraints.distribute(nodes, local);
  s.constraints.distribute(nodes, residual_only);
  EXPECT_EQ(local.residual_values(), residual_only.residual_values());

  const auto &q = s.constraints.axes(1);
  // Node 1's rows: q_k . R; its first (the constrained n) removed with its column.
  for (int k = 0; k < 3; ++k)
  {
    double rotated = 0.0;
    for (int d = 0; d < 3; ++d)
      rotated += q[k][d] * original.residual_values()[4 + 1 + d];
    EXPECT_NEAR(local.residual(1 + k, 1), k == 0 ? 0.0 : rotated, 1e-15);
  }
  // Q^T J Q for the node-1 block of free axes, and the symmetry kept.
  for (int k = 1; k < 3; ++k)
    for (int l = 1; l < 3; ++l)
    {
      double expected = 0.0;
      for (int d = 0; d < 3; ++d)
        for (int e = 0; e < 3; ++e)
          expected += q[k][d] * original.jacobian_values()[12 * (5 + d) + 5 + e] * q[l][e];
      EXPECT_NEAR(local.jacobian(1 + k, 1, 1 + l, 1), expected, 1e-14);
    }
  for (int a = 0; a < 12; ++a)
    for (int b = 0; b < 12; ++b)
      EXPECT_NEAR(local.jacobian_values()[12 * a + b], local.jacobian_values()[12 * b + a], 1e-14);
  // The constrained unknowns: u.n of node 1 and T of node 2, rows and columns zero.
  for (int a = 0; a < 12; ++a)
    for (const int c : {5, 8})
    {
      EXPECT_EQ(local.jacobian_values()[12 * a + c], 0.0);
      EXPECT_EQ(local.jacobian_values()[12 * c + a], 0.0);
    }
  // Node 0 has no frame: untouched.
  for (int a = 0; a < 4; ++a)
    EXPECT_EQ(local.residual_values()[a], original.residual_values()[a]);
}

TEST(NodalConstraints, ConstraintRowsAndHeldTemperatures)
{
  Fixture s;
  const int g = s.constraints.add_value("motion", [](const double t) { return 1e-4 * t; });
  s.constraints.constrain_direction(0, {0.0, 0.0, 1.0}, g);
  s.constraints.constrain_temperature(0,
                                      s.constraints.add_value("T", [](double) { return 350.0; }));
  s.constraints.close(100.0, 1e10);
  s.constraints.set_time(3.0);
  kiln::Assembler assembler(s.mesh, s.dofs);
  kiln::Assembler::Vector x(s.dofs.owned_dof_map()), f(s.dofs.owned_dof_map());
  x.putScalar(1.0);
  auto x_overlap = assembler.make_overlap_vector();
  assembler.gather(x, *x_overlap);

  const auto row = [&](const kiln::Field field)
  {
    const auto lid = s.dofs.owned_dof_map()->getLocalElement(s.dofs.dof(0, field));
    return lid == Teuchos::OrdinalTraits<kiln::LO>::invalid() ? std::nan("") : f.getData()[lid];
  };
  assembler.begin(true, nullptr);
  s.constraints.add_rows(*x_overlap, assembler, false);
  assembler.finish(&f, nullptr);
  // s = c ∫|∇φ_0|^2 over the corner cell of the 2 x 2 x 2 unit-size box (cells of 0.5 m):
  // ∫|∇φ|^2 = h/3 for a cube of edge h at a corner node, so s = c/6.
  if (!std::isnan(row(kiln::Field::T)))
  {
    EXPECT_NEAR(row(kiln::Field::T), 100.0 / 6.0 * (1.0 - 350.0), 1e-9);
    EXPECT_NEAR(row(kiln::Field::ux), 1e10 / 6.0 * (1.0 - 3e-4), 1e-3);
    EXPECT_EQ(row(kiln::Field::uy), 0.0); // not constrained: no row
  }
  // Held: every temperature row is x - T_held with unit scale, the prescribed one too.
  kiln::Assembler::Vector held(s.dofs.owned_dof_map());
  held.putScalar(2.0);
  s.constraints.hold_temperature(&held);
  assembler.begin(true, nullptr);
  s.constraints.add_rows(*x_overlap, assembler, false);
  assembler.finish(&f, nullptr);
  for (const int n : s.dofs.owned_nodes())
    EXPECT_EQ(f.getData()[s.dofs.owned_dof_map()->getLocalElement(s.dofs.dof(n, kiln::Field::T))],
              -1.0);
  kiln::LocalSystem local(1, 4);
  local.residual(0, 0) = 5.0;
  local.jacobian(0, 0, 1, 0) = 3.0;
  local.jacobian(1, 0, 0, 0) = 4.0;
  s.constraints.distribute({5}, local);
  EXPECT_EQ(local.residual(0, 0), 0.0);
  EXPECT_EQ(local.jacobian(0, 0, 1, 0), 0.0); // the row is gone
  EXPECT_EQ(local.jacobian(1, 0, 0, 0), 4.0); // the column stays
  s.constraints.hold_temperature(nullptr);
  assembler.begin(true, nullptr);
  s.constraints.add_rows(*x_overlap, assembler, false);
  assembler.finish(&f, nullptr);
  for (const int n : s.dofs.owned_nodes())
  {
    if (n == 0)
      continue;
    EXPECT_EQ(f.getData()[s.dofs.owned_dof_map()->getLocalElement(s.dofs.dof(n, kiln::Field::T))],
              0.0);
  }
}
