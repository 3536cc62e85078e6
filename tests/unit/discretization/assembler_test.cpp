// Tests discretization/assembler: the graph holds every coupling, the owned
// residual and Jacobian exported from the overlap ones are consistent
// (F(T) = K T for a linear problem), symmetric, free of rank-count effects,
// and a gap-face coupling between twins gives zero flux for equal temperatures.
// KILN_TEST_NP: 1 2 3
#include "discretization/assembler.hpp"
#include "discretization/element_values.hpp"
#include "discretization/face_values.hpp"
#include "mesh/box_mesh_generator.hpp"
#include "mesh/gap_splitter.hpp"
#include "mesh/hex_geometry.hpp"
#include "mesh/metis_partitioner.hpp"
#include "support/reference_cells.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_Tuple.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace
{
using kiln::GO;
using kiln::LO;
using kiln::Mesh;

Mesh split_box()
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  p.set("Cells", Teuchos::Array<int>(Teuchos::tuple(4, 3, 2)));
  p.set("Phi", 45.0);
  p.set("Theta", -30.0);
  Mesh mesh = kiln::BoxMeshGenerator(p, "test/Box").generate();
  kiln::split_gap(mesh, 10, "test");
  return mesh;
}

/// Conduction (k = 1) in the cells plus a gap conductance h between twins:
/// linear, so the local residual is K_e T_e.
struct Fixture
{
  Teuchos::RCP<const Teuchos::Comm<int>> comm = Teuchos::DefaultComm<int>::getComm();
  Mesh mesh = split_box();
  std::vector<int> cell_rank = kiln::partition_cells(mesh, *comm, "test");
  kiln::DofManager dofs{mesh, cell_rank, comm, kiln::DofLayout{true, false, false}};
  kiln::Assembler assembler{mesh, dofs};
  double h = 7.0;

  void assemble(const kiln::Assembler::Vector &T, kiln::Assembler::Vector *f,
                kiln::Assembler::Matrix *J)
  {
    auto T_overlap = assembler.make_overlap_vector();
    assembler.gather(T, *T_overlap);
    const auto t = T_overlap->getData();
    assembler.begin(f != nullptr, J);
    kiln::ElementValues fe;
    kiln::LocalSystem cell(8, 1);
    for (const int c : dofs.owned_cells())
    {
      kiln_test::reinit(fe, kiln::cell_nodes(mesh, c));
      const auto lids = assembler.cell_lids(c);
      cell.clear();
      for (int q = 0; q < fe.n_qpoints(); ++q)
        for (int i = 0; i < 8; ++i)
          for (int j = 0; j < 8; ++j)
          {
            double g = 0;
            for (int d = 0; d < 3; ++d)
              g += fe.grad(i, q)[d] * fe.grad(j, q)[d];
            cell.jacobian(0, i, 0, j) += g * fe.JxW(q);
            cell.residual(0, i) += g * fe.JxW(q) * t[lids[j]];
          }
      assembler.add(lids, cell);
    }
    kiln::FaceValues face_values;
    kiln::LocalSystem pair(8, 1);
    for (std::size_t k = 0; k < mesh.gap_faces.size(); ++k)
    {
      const auto &face = mesh.gap_faces[k];
      if (cell_rank[face.cell_a] != comm->getRank())
        continue;
      kiln_test::reinit(face_values, kiln::face_nodes(mesh, face.cell_a, face.face_a));
      const auto lids = assembler.gap_face_lids(static_cast<int>(k));
      pair.clear();
      for (int q = 0; q < 4; ++q)
      {
        double jump = 0; // T_b - T_a at q
        for (int j = 0; j < 4; ++j)
          jump += face_values.shape(j, q) * (t[lids[4 + j]] - t[lids[j]]);
        for (int i = 0; i < 4; ++i)
        {
          const double w = h * face_values.shape(i, q) * face_values.JxW(q);
          pair.residual(0, i) -= w * jump;
          pair.residual(0, 4 + i) += w * jump;
          for (int j = 0; j < 4; ++j)
          {
            const double wj = w * face_values.shape(j, q);
            pair.jacobian(0, i, 0, j) += wj;
            pair.jacobian(0, i, 0, 4 + j) -= wj;
            pair.jacobian(0, 4 + i, 0, j) -= wj;
            pair.jacobian(0, 4 + i, 0, 4 + j) += wj;
          }
        }
      }
      assembler.add(lids, pair);
    }
    assembler.finish(f, J);
  }
};

/// A field that depends on position only, so it is the same at every rank count.
void set_field(const Fixture &s, kiln::Assembler::Vector &T, const bool jump_across_gap)
{
  const auto map = T.getMap();
  auto v = T.getDataNonConst();
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
  {
    const int n = static_cast<int>(map->getGlobalElement(static_cast<LO>(i)));
    const auto &x = s.mesh.coordinates[n];
    const bool side_b = n >= 60; // the twins: 5*4*3 = 60 original nodes
    v[i] = 300 + 100 * x[0] + 20 * x[1] * x[1] - 50 * x[2] + (jump_across_gap && side_b ? 3 : 0);
  }
}
} // namespace

TEST(Assembler, ResidualEqualsJacobianTimesFieldAndIsRankIndependent)
{
  Fixture s;
  ASSERT_EQ(s.mesh.n_nodes(), 60 + 12);
  kiln::Assembler::Vector T(s.dofs.owned_dof_map()), f(s.dofs.owned_dof_map()),
      KT(s.dofs.owned_dof_map());
  kiln::Assembler::Matrix J(s.assembler.owned_graph());
  set_field(s, T, true);
  s.assemble(T, &f, &J);
  J.apply(T, KT);
  KT.update(-1.0, f, 1.0);
  EXPECT_LT(KT.normInf(), 1e-10 * f.normInf());

  // Symmetric: x' J y = y' J x for two position-dependent fields.
  kiln::Assembler::Vector y(s.dofs.owned_dof_map()), Jy(s.dofs.owned_dof_map()),
      Jx(s.dofs.owned_dof_map());
  set_field(s, y, false);
  J.apply(y, Jy);
  J.apply(T, Jx);
  // The dot products cancel: scale the tolerance by the norms, not by their value.
  EXPECT_NEAR(T.dot(Jy), y.dot(Jx), 1e-12 * (T.norm2() * Jy.norm2() + y.norm2() * Jx.norm2()));

  // A constant field has zero residual (Neumann everywhere, equal temperatures
  // across the gap give no flux).
  kiln::Assembler::Vector one(s.dofs.owned_dof_map()), f1(s.dofs.owned_dof_map()),
      J1(s.dofs.owned_dof_map());
  one.putScalar(288.0);
  s.assemble(one, &f1, nullptr);
  EXPECT_LT(f1.normInf(), 1e-12 * 288.0);
  J.apply(one, J1);
  EXPECT_LT(J1.normInf(), 1e-12 * 288.0);
}

TEST(Assembler, GapFluxMatchesTheJumpTimesArea)
{
  // T = 0 on side a, 1 on side b: the flux out of side b, h * area, must enter side a.
  Fixture s;
  kiln::Assembler::Vector T(s.dofs.owned_dof_map()), f(s.dofs.owned_dof_map());
  auto v = T.getDataNonConst();
  const auto map = T.getMap();
  std::vector<char> on_b(s.mesh.n_nodes(), 0);
  for (int c = 0; c < s.mesh.n_cells(); ++c)
    if (s.mesh.block_id[c] == 2)
      for (const int n : s.mesh.cell_nodes(c))
        on_b[n] = 1;
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
    v[i] = on_b[map->getGlobalElement(static_cast<LO>(i))];
  s.assemble(T, &f, nullptr);
  // Sum of the residual over side-b gap nodes = +h * A (cells contribute 0 in total).
  const double area = 0.04 * 0.04;
  double side_b = 0, all = 0;
  const auto r = f.getData();
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
  {
    all += r[i];
    if (on_b[map->getGlobalElement(static_cast<LO>(i))])
      side_b += r[i];
  }
  double side_b_sum = 0, all_sum = 0;
  Teuchos::reduceAll(*s.comm, Teuchos::REDUCE_SUM, side_b, Teuchos::outArg(side_b_sum));
  Teuchos::reduceAll(*s.comm, Teuchos::REDUCE_SUM, all, Teuchos::outArg(all_sum));
  EXPECT_NEAR(side_b_sum, s.h * area, 1e-12);
  EXPECT_NEAR(all_sum, 0.0, 1e-12);
}

TEST(Assembler, GraphHasCellAndGapCouplings)
{
  Fixture s;
  const auto graph = s.assembler.owned_graph();
  // Every owned row of a twin node couples with its side-a partner.
  for (const auto &pair : s.mesh.gap_pairs)
    for (const int n : {pair.node_a, pair.node_b})
    {
      const GO row = s.dofs.dof(n, kiln::Field::T);
      const LO i = graph->getRowMap()->getLocalElement(row);
      if (i == Teuchos::OrdinalTraits<LO>::invalid())
        continue;
      const GO partner = s.dofs.dof(n == pair.node_a ? pair.node_b : pair.node_a, kiln::Field::T);
      Teuchos::Array<GO> cols(graph->getNumEntriesInGlobalRow(row));
      std::size_t count = 0;
      graph->getGlobalRowCopy(row, cols(), count);
      EXPECT_NE(std::find(cols.begin(), cols.end(), partner), cols.end()) << "row " << row;
    }
}

/// Couplings::temperature_depends_on_displacement false: the temperature rows of a
/// thermo-elastic layout hold temperature columns only, the displacement rows all four; a
/// local system with a T-u entry is refused, one with zeros there is added.
TEST(Assembler, LeavesOutTheTemperatureRowsDisplacementColumns)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const Mesh mesh = split_box();
  const std::vector<int> cell_rank = kiln::partition_cells(mesh, *comm, "test");
  const kiln::DofManager dofs{mesh, cell_rank, comm, kiln::DofLayout{true, true, false}};
  for (const bool depends : {true, false})
  {
    kiln::Couplings couplings = kiln::Couplings::gap_faces(mesh);
    couplings.temperature_depends_on_displacement = depends;
    kiln::Assembler assembler(mesh, dofs, couplings);
    const auto graph = assembler.owned_graph();
    for (const int n : dofs.owned_nodes())
    {
      const std::size_t T_entries = graph->getNumEntriesInGlobalRow(dofs.dof(n, kiln::Field::T));
      const std::size_t u_entries = graph->getNumEntriesInGlobalRow(dofs.dof(n, kiln::Field::ux));
      EXPECT_EQ(u_entries % 4, 0u);
      EXPECT_EQ(T_entries, depends ? u_entries : u_entries / 4) << "node " << n;
    }
    const int c = dofs.owned_cells().front();
    const std::vector<int> nodes(mesh.cell_nodes(c).begin(), mesh.cell_nodes(c).end());
    kiln::LocalSystem local(8, 4);
    local.jacobian(0, 0, 0, 0) = 1.0; // T-T
    local.jacobian(1, 0, 0, 0) = 1.0; // u-T
    kiln::Assembler::Matrix J(graph);
    J.fillComplete(graph->getDomainMap(), graph->getRangeMap());
    assembler.begin(false, &J);
    EXPECT_NO_THROW(assembler.add(assembler.node_lids(nodes), local));
    local.jacobian(0, 0, 1, 0) = 1.0; // T-u
    if (depends)
      EXPECT_NO_THROW(assembler.add(assembler.node_lids(nodes), local));
    else
      EXPECT_THROW(assembler.add(assembler.node_lids(nodes), local), std::logic_error);
  }
}
