// Tests src/solvers/solver_hints.cpp: MueLu's coordinates keep each body of the mesh in one
// piece and move the bodies a gap separates ten diagonals apart (so its distance Laplacian
// drops every coupling across the gap); the near-null space and the unknown scale.
// KILN_TEST_NP: 1 2
#include "solvers/solver_hints.hpp"

#include "mesh/box_mesh_generator.hpp"
#include "mesh/gap_splitter.hpp"
#include "mesh/mesh_bodies.hpp"
#include "mesh/metis_partitioner.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_Tuple.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace
{
struct Fixture
{
  explicit Fixture(const bool split)
  {
    Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
    p.set("Size", Teuchos::Array<double>(Teuchos::tuple(0.04, 0.02, 0.01)));
    p.set("Cells", Teuchos::Array<int>(Teuchos::tuple(4, 2, 2)));
    p.set("Phi", 45.0);
    p.set("Theta", -30.0);
    mesh = kiln::BoxMeshGenerator(p, "test/Box").generate();
    if (split)
      kiln::split_gap(mesh, 10, "test");
  }
  Teuchos::RCP<const Teuchos::Comm<int>> comm = Teuchos::DefaultComm<int>::getComm();
  kiln::Mesh mesh;
};

/// The diagonal of the mesh's bounding box [m].
double diagonal(const kiln::Mesh &mesh)
{
  kiln::Point low = mesh.coordinates.front(), high = low;
  for (const kiln::Point &x : mesh.coordinates)
    for (int d = 0; d < 3; ++d)
    {
      low[d] = std::min(low[d], x[d]);
      high[d] = std::max(high[d], x[d]);
    }
  const kiln::Point e{high[0] - low[0], high[1] - low[1], high[2] - low[2]};
  return std::sqrt(kiln::dot(e, e));
}

/// Checks the coordinates of every owned node: the mesh's, moved along x by its body's
/// index times ten diagonals.
void expect_bodies_apart(const Fixture &f, const int expected_bodies)
{
  const std::vector<int> cell_rank = kiln::partition_cells(f.mesh, *f.comm, "test");
  const kiln::DofManager dofs{f.mesh, cell_rank, f.comm, kiln::DofLayout{true, true, true}};
  kiln::NodalConstraints constraints{f.mesh, dofs};
  constraints.close(240.0, 1.04e11);
  const kiln::SolverHints hints(f.mesh, dofs, constraints, 240.0, 1.04e11, 2.2e-5);
  const kiln::MeshBodies bodies = kiln::mesh_bodies(f.mesh);
  ASSERT_EQ(bodies.count, expected_bodies);
  const double spacing = 10.0 * diagonal(f.mesh);
  const auto coordinates = hints.coordinates();
  ASSERT_EQ(coordinates->getLocalLength(), dofs.owned_nodes().size());
  for (std::size_t i = 0; i < dofs.owned_nodes().size(); ++i)
  {
    const int n = dofs.owned_nodes()[i];
    const kiln::Point &x = f.mesh.coordinates[n];
    const double shift = bodies.body[n] * spacing;
    EXPECT_NEAR(coordinates->getData(0)[i], x[0] + shift, 1e-15 * spacing) << "node " << n;
    EXPECT_DOUBLE_EQ(coordinates->getData(1)[i], x[1]) << "node " << n;
    EXPECT_DOUBLE_EQ(coordinates->getData(2)[i], x[2]) << "node " << n;
  }
}

TEST(SolverHints, OneBodyKeepsTheMeshCoordinates)
{
  expect_bodies_apart(Fixture(false), 1);
}

TEST(SolverHints, TheBodiesOfASplitGapLieTenDiagonalsApart)
{
  expect_bodies_apart(Fixture(true), 2);
}

TEST(SolverHints, ScaleAndRigidTranslationsOfTheDisplacement)
{
  const Fixture f(true);
  const std::vector<int> cell_rank = kiln::partition_cells(f.mesh, *f.comm, "test");
  const kiln::DofManager dofs{f.mesh, cell_rank, f.comm, kiln::DofLayout{true, true, true}};
  kiln::NodalConstraints constraints{f.mesh, dofs};
  constraints.close(240.0, 1.04e11);
  const kiln::SolverHints hints(f.mesh, dofs, constraints, 240.0, 1.04e11, 2.2e-5);
  EXPECT_DOUBLE_EQ(hints.displacement_scale(), std::sqrt(240.0 / 1.04e11));
  // Without frames (no constraints here) mode 1 + k is the translation along axis k, and
  // mode 0 the constant temperature with its free expansion alpha (x - centre): the four
  // unknowns of a node are T, ux, uy, uz.
  const auto modes = hints.near_null_space();
  ASSERT_EQ(modes->getNumVectors(), 7u);
  kiln::Point centre{0, 0, 0};
  for (const kiln::Point &x : f.mesh.coordinates)
    for (int d = 0; d < 3; ++d)
      centre[d] += x[d] / f.mesh.n_nodes();
  const auto &owned = dofs.owned_nodes();
  for (std::size_t row = 0; row < modes->getLocalLength(); ++row)
  {
    const std::size_t k = row % 4;
    const kiln::Point &x = f.mesh.coordinates[owned[row / 4]];
    const double expansion = k == 0 ? 1.0 : 2.2e-5 * (x[k - 1] - centre[k - 1]);
    EXPECT_NEAR(modes->getData(0)[row], expansion, 1e-15) << "row " << row;
    for (std::size_t m = 1; m < 4; ++m)
      EXPECT_DOUBLE_EQ(modes->getData(m)[row], k == m ? 1.0 : 0.0)
          << "row " << row << ", mode " << m;
  }
}
} // namespace
