#include "support/problem_fixture.hpp"

#include "base/parameters.hpp"
#include "mesh/box_mesh_generator.hpp"
#include "mesh/gap_splitter.hpp"
#include "mesh/hex_geometry.hpp"
#include "mesh/metis_partitioner.hpp"
#include "support/jacobian_check.hpp"
#include "support/parameter_lists.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace kiln_test
{
kiln::Material TableMaterial::make()
{
  Teuchos::ParameterList user;
  user.set("Density", density);
  user.set("Specific Heat", specific_heat);
  user.set("Young's Modulus", youngs);
  user.set("Poisson's Ratio", poisson);
  user.set("Thermal Expansion", alpha);
  user.set("Reference Temperature", T_ref);
  Teuchos::ParameterList &k = user.sublist("Conductivity");
  k.set("Type", "Table");
  k.set("Temperatures", values({200.0, 280.0, 400.0}));
  k.set("Values", values({300.0, 120.0, 360.0}));
  const Teuchos::ParameterList p =
      kiln::validated(user, kiln::Material::valid_parameters(), "test.xml", "Kiln/Material");
  return kiln::Material(p, "test.xml: Kiln/Material");
}

namespace
{
kiln::Mesh generate(const BoxShape &box, const bool mid_y = false, const bool mid_z = false)
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  p.set("Size", values({box.size[0], box.size[1], box.size[2]}));
  p.set("Cells", ids({box.cells[0], box.cells[1], box.cells[2]}));
  p.set("Phi", box.phi);
  p.set("Theta", box.theta);
  p.set("Translation", values({box.shift[0], box.shift[1], box.shift[2]}));
  kiln::Mesh mesh = kiln::BoxMeshGenerator(p, "test/Box").generate(mid_y, mid_z);
  if (box.shear != 0.0)
  {
    // x_block += shear z_block, y_block += shear z_block; x = A x_block + shift.
    const auto A = kiln::rotation_matrix(box.phi, box.theta);
    for (kiln::Point &x : mesh.coordinates)
    {
      double z_block = 0.0;
      for (int d = 0; d < 3; ++d)
        z_block += A[d][2] * (x[d] - box.shift[d]);
      for (int d = 0; d < 3; ++d)
        x[d] += box.shear * z_block * (A[d][0] + A[d][1]);
    }
  }
  return mesh;
}
} // namespace

std::vector<std::array<kiln::Point, 3>> node_frames(kiln::CoupledProblem &problem)
{
  using LO = kiln::LO;
  kiln::NonlinearProblem::Vector probe(problem.solution_map());
  const std::vector<kiln::Point> u0 = problem.node_displacements(probe);
  std::vector<std::array<kiln::Point, 3>> q(u0.size());
  for (int k = 0; k < 3; ++k)
  {
    probe.putScalar(0.0);
    for (std::size_t i = 0; i < q.size(); ++i)
      probe.replaceLocalValue(static_cast<LO>(4 * i + 1 + k), 1.0);
    const std::vector<kiln::Point> u = problem.node_displacements(probe);
    for (std::size_t i = 0; i < q.size(); ++i)
      for (int d = 0; d < 3; ++d)
        q[i][k][d] = u[i][d] - u0[i][d];
  }
  return q;
}

std::array<double, 3> frame_components(const std::array<kiln::Point, 3> &t, const kiln::Point &u)
{
  // The free components solve G û = (t_j . u) with G_jk = t_j . t_k over the free axes (they
  // are orthogonal to the constrained ones): Gauss-Jordan on at most 3 x 3.
  std::vector<int> free;
  for (int k = 0; k < 3; ++k)
    if (std::sqrt(kiln::dot(t[k], t[k])) > 0.5)
      free.push_back(k);
  const std::size_t m = free.size();
  std::vector<std::vector<double>> G(m, std::vector<double>(m + 1));
  for (std::size_t j = 0; j < m; ++j)
  {
    for (std::size_t k = 0; k < m; ++k)
      G[j][k] = kiln::dot(t[free[j]], t[free[k]]);
    G[j][m] = kiln::dot(t[free[j]], u);
  }
  for (std::size_t c = 0; c < m; ++c)
    for (std::size_t r = 0; r < m; ++r)
      if (r != c)
      {
        const double f = G[r][c] / G[c][c];
        for (std::size_t k = c; k <= m; ++k)
          G[r][k] -= f * G[c][k];
      }
  std::array<double, 3> u_hat{};
  for (std::size_t j = 0; j < m; ++j)
    u_hat[free[j]] = G[j][m] / G[j][j];
  return u_hat;
}

double jacobian_error(const ProblemFixture &s, kiln::CoupledProblem &problem,
                      kiln::NonlinearProblem::Vector &x, const int n_active)
{
  return jacobian_error(s.dofs, problem, x, n_active);
}

double jacobian_error(const kiln::DofManager &dofs, kiln::CoupledProblem &problem,
                      kiln::NonlinearProblem::Vector &x, const int n_active)
{
  using Vector = kiln::NonlinearProblem::Vector;
  using Matrix = kiln::NonlinearProblem::Matrix;
  using kiln::LO;
  const auto map = problem.solution_map();
  const GO n_global = dofs.n_global_dofs();
  Vector f(map);
  Matrix J(problem.jacobian_graph());
  problem.evaluate(x, &f, &J);
  EXPECT_EQ(problem.n_active_pairs(x), n_active);
  const Dense rows = dense_rows(J, n_global);
  int changes = 0;
  const Dense fd = finite_difference_rows(
      problem, x, [](const GO j) { return j % 4 == 0 ? 1.0e-3 : 1.0e-9; },
      [&](const Vector &perturbed) { changes += problem.n_active_pairs(perturbed) != n_active; });
  EXPECT_EQ(changes, 0) << "perturbations changed the pairs in contact";
  double worst = 0.0;
  for (std::size_t i = 0; i < rows.size(); ++i)
  {
    const GO gi = map->getGlobalElement(static_cast<LO>(i));
    std::array<double, 4> scale{};
    for (GO j = 0; j < n_global; ++j)
    {
      const int k = thermo_mechanical_block(gi, j);
      scale[k] = std::max({scale[k], std::abs(rows[i][j]), std::abs(fd[i][j])});
    }
    for (GO j = 0; j < n_global; ++j)
    {
      const double d = std::abs(rows[i][j] - fd[i][j]);
      if (d > 0.0)
        worst = std::max(worst, d / scale[thermo_mechanical_block(gi, j)]);
    }
  }
  double global = 0.0;
  Teuchos::reduceAll(*map->getComm(), Teuchos::REDUCE_MAX, worst, Teuchos::outArg(global));
  return global;
}

kiln::Mesh crossed_box(const BoxShape &box, const std::vector<int> &gap_side_sets)
{
  const auto has = [&](const int id)
  { return std::find(gap_side_sets.begin(), gap_side_sets.end(), id) != gap_side_sets.end(); };
  kiln::Mesh mesh = generate(box, has(11), has(12));
  kiln::split_gaps(mesh, gap_side_sets, "test");
  return mesh;
}

kiln::Mesh box_mesh(const BoxShape &box, const int gap_side_set)
{
  kiln::Mesh mesh = generate(box);
  if (gap_side_set != 0)
    kiln::split_gap(mesh, gap_side_set, "test");
  return mesh;
}

kiln::Mesh distorted_box(const BoxShape &box, const double distortion, const int gap_side_set,
                         const bool plane_gap)
{
  kiln::Mesh mesh = generate(box);
  std::vector<char> on_boundary(mesh.n_nodes(), 0), on_gap(mesh.n_nodes(), 0);
  for (const kiln::SideSet &set : mesh.side_sets)
  {
    const bool outer = set.id >= 1 && set.id <= 6;
    const bool gap = plane_gap && set.id == gap_side_set;
    if (outer || gap)
      for (int s = 0; s < set.n_sides(); ++s)
        for (const int i : kiln::hex_face_nodes[set.faces[s]])
          (outer ? on_boundary : on_gap)[mesh.cell_nodes(set.cells[s])[i]] = 1;
  }
  const auto A = kiln::rotation_matrix(box.phi, box.theta);
  std::mt19937 random(20240611u);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int n = 0; n < mesh.n_nodes(); ++n)
  {
    if (on_boundary[n])
      continue;
    kiln::Point shift_block{};
    for (int d = 0; d < 3; ++d)
      shift_block[d] = distortion * unit(random) * box.size[d] / box.cells[d];
    if (on_gap[n])
      shift_block[0] = 0.0;
    for (int d = 0; d < 3; ++d)
      for (int e = 0; e < 3; ++e)
        mesh.coordinates[n][d] += A[d][e] * shift_block[e];
  }
  if (gap_side_set != 0)
    kiln::split_gap(mesh, gap_side_set, "test");
  return mesh;
}

ProblemFixture::ProblemFixture(kiln::Mesh m, const kiln::DofLayout layout,
                               kiln::Material material_in)
    : mesh(std::move(m)), cell_rank(kiln::partition_cells(mesh, *comm, "test")),
      dofs(mesh, cell_rank, comm, layout), material(std::move(material_in))
{
}

kiln::MaterialMap material_map(const Teuchos::ParameterList &kiln_user,
                               const std::vector<int> &block_ids)
{
  Teuchos::ParameterList valid("Kiln");
  valid.sublist("Material").setParameters(kiln::Material::valid_parameters());
  kiln::set_named_sublists(valid, "Materials", "materials by name",
                           kiln::MaterialMap::valid_named_parameters());
  return kiln::MaterialMap(kiln::validated(kiln_user, valid, "test.xml", "Kiln"), block_ids,
                           "test.xml");
}

Teuchos::RCP<kiln::CoupledProblem> ProblemFixture::problem(const Teuchos::ParameterList &thermal,
                                                           const Teuchos::ParameterList &mechanics,
                                                           const kiln::MaterialMap *materials) const
{
  const Teuchos::ParameterList t = kiln::validated(
      thermal, kiln::ThermalPhysics::valid_parameters(), "test.xml", "Kiln/Thermal");
  const Teuchos::ParameterList m = kiln::validated(
      mechanics, kiln::MechanicalPhysics::valid_parameters(), "test.xml", "Kiln/Mechanics");
  return Teuchos::rcp(new kiln::CoupledProblem(
      mesh, dofs, materials != nullptr ? materials->uniform_material() : material, t, m,
      "test.xml: Kiln", materials));
}

std::vector<char> ProblemFixture::nodes_of_side_set(const int id) const
{
  std::vector<char> on(mesh.n_nodes(), 0);
  const kiln::SideSet &set = *mesh.find_side_set(id);
  for (int s = 0; s < set.n_sides(); ++s)
    for (const int i : kiln::hex_face_nodes[set.faces[s]])
      on[mesh.cell_nodes(set.cells[s])[i]] = 1;
  return on;
}
} // namespace kiln_test
