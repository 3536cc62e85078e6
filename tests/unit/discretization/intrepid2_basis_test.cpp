// Tests src/discretization/elements/ against Intrepid2's HGRAD bases (Trilinos 13.2): the
// values and reference gradients of every type Intrepid2 has (all but HEX20 and QUAD8) agree to
// round-off at random points and at the quadrature points, node for node: Kiln's Exodus numbering
// is Shards' (including HEX27's centroid and face centres). HEX20 against the first Intrepid's
// HGRAD_HEX_I2 (QUAD8: finite_element_test's hand-derived values).
// KILN_TEST_NP: 1
#include "elements/finite_element.hpp"
#include "support/intrepid2_bases.hpp"

#include <Intrepid_FieldContainer.hpp>
#include <Intrepid_HGRAD_HEX_I2_FEM.hpp>
#include <Kokkos_Core.hpp>
#include <Shards_BasicTopologies.hpp>
#include <Shards_CellTopology.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace
{
using kiln::CellType;
using kiln::FiniteElement;
using kiln::Point;

/// Kokkos, initialised once for the whole test program (it cannot be initialised twice);
/// nothing else in Kiln uses it.
class KokkosEnvironment : public ::testing::Environment
{
public:
  void SetUp() override { Kokkos::initialize(); }
  void TearDown() override { Kokkos::finalize(); }
};
const auto *const kokkos_environment = ::testing::AddGlobalTestEnvironment(new KokkosEnvironment);

class Intrepid2Agreement : public ::testing::TestWithParam<CellType>
{
};

std::vector<Point> sample_points(const FiniteElement &fe)
{
  // The quadrature points and points scattered through (and a little beyond: both bases are
  // the same polynomials there, except the pyramid's rational term) the reference cell's box.
  std::vector<Point> points = fe.quadrature().points;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.05, 0.45);
  const bool d3 = fe.cell().dim() == 3;
  for (int i = 0; i < 20; ++i)
    points.push_back({u(rng), u(rng), d3 ? u(rng) : 0.0});
  return points;
}

TEST_P(Intrepid2Agreement, ValuesAndGradients)
{
  const FiniteElement &fe = FiniteElement::of(GetParam());
  const auto basis = kiln_test::intrepid2_basis(GetParam());
  ASSERT_TRUE(basis);
  const int n = fe.n_shape(), dim = fe.cell().dim();
  ASSERT_EQ(basis->getCardinality(), n);
  const std::vector<Point> points = sample_points(fe);
  const int np = static_cast<int>(points.size());
  const kiln_test::Intrepid2View x = kiln_test::intrepid2_points(points, dim);
  kiln_test::Intrepid2View N("N", n, np), dN("dN", n, np, dim);
  basis->getValues(N, x, Intrepid2::OPERATOR_VALUE);
  basis->getValues(dN, x, Intrepid2::OPERATOR_GRAD);
  std::vector<double> v(n);
  std::vector<Point> g(n);
  for (int p = 0; p < np; ++p)
  {
    fe.values(points[p], v.data());
    fe.gradients(points[p], g.data());
    for (int i = 0; i < n; ++i)
    {
      EXPECT_NEAR(v[i], N(i, p), 1e-14) << fe.cell().name() << ": N_" << i << " at point " << p;
      for (int k = 0; k < dim; ++k)
        EXPECT_NEAR(g[i][k], dN(i, p, k), 1e-13)
            << fe.cell().name() << ": dN_" << i << "/dxi_" << k << " at point " << p;
    }
  }
}

TEST(IntrepidHex20, ValuesAndGradients)
{
  const FiniteElement &fe = FiniteElement::of(CellType::hex20);
  Intrepid::Basis_HGRAD_HEX_I2_FEM<double, Intrepid::FieldContainer<double>> basis;
  ASSERT_EQ(basis.getCardinality(), 20);
  const std::vector<Point> points = sample_points(fe);
  const int np = static_cast<int>(points.size());
  Intrepid::FieldContainer<double> x(np, 3), N(20, np), dN(20, np, 3);
  for (int p = 0; p < np; ++p)
    for (int k = 0; k < 3; ++k)
      x(p, k) = points[p][k];
  basis.getValues(N, x, Intrepid::OPERATOR_VALUE);
  basis.getValues(dN, x, Intrepid::OPERATOR_GRAD);
  std::vector<double> v(20);
  std::vector<Point> g(20);
  for (int p = 0; p < np; ++p)
  {
    fe.values(points[p], v.data());
    fe.gradients(points[p], g.data());
    for (int i = 0; i < 20; ++i)
    {
      EXPECT_NEAR(v[i], N(i, p), 1e-14) << "N_" << i << " at point " << p;
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(g[i][k], dN(i, p, k), 1e-13) << "dN_" << i << "/dxi_" << k << " at " << p;
    }
  }
}

TEST(Shards, SideNodeMapsAreTheFaceNodes)
{
  const std::vector<std::pair<CellType, shards::CellTopology>> topologies = {
      {CellType::hex8, shards::getCellTopologyData<shards::Hexahedron<8>>()},
      {CellType::tet4, shards::getCellTopologyData<shards::Tetrahedron<4>>()},
      {CellType::wedge6, shards::getCellTopologyData<shards::Wedge<6>>()},
      {CellType::pyramid5, shards::getCellTopologyData<shards::Pyramid<5>>()},
      {CellType::tet10, shards::getCellTopologyData<shards::Tetrahedron<10>>()},
      {CellType::hex20, shards::getCellTopologyData<shards::Hexahedron<20>>()},
      {CellType::hex27, shards::getCellTopologyData<shards::Hexahedron<27>>()}};
  std::vector<std::string> rotated; // the sides Shards starts at another corner
  for (const auto &[type, topology] : topologies)
  {
    const kiln::ReferenceCell &cell = kiln::ReferenceCell::of(type);
    ASSERT_EQ(static_cast<int>(topology.getNodeCount()), cell.n_nodes()) << cell.name();
    ASSERT_EQ(static_cast<int>(topology.getSideCount()), cell.n_faces()) << cell.name();
    for (int f = 0; f < cell.n_faces(); ++f)
    {
      std::vector<int> side;
      for (unsigned k = 0; k < topology.getNodeCount(2, f); ++k)
        side.push_back(static_cast<int>(topology.getNodeMap(2, f, k)));
      if (side != cell.face_nodes(f))
      {
        rotated.push_back(cell.name() + " side " + std::to_string(f + 1));
        std::rotate(side.begin(), std::find(side.begin(), side.end(), cell.face_nodes(f)[0]),
                    side.end());
      }
      EXPECT_EQ(side, cell.face_nodes(f)) << cell.name() << " side " << f + 1;
    }
  }
  EXPECT_EQ(rotated, std::vector<std::string>{"PYRAMID5 side 4"});
}

INSTANTIATE_TEST_SUITE_P(TypesIntrepid2Has, Intrepid2Agreement,
                         ::testing::Values(CellType::hex8, CellType::tet4, CellType::wedge6,
                                           CellType::pyramid5, CellType::tet10, CellType::hex27,
                                           CellType::quad4, CellType::tri3, CellType::quad9,
                                           CellType::tri6),
                         [](const ::testing::TestParamInfo<CellType> &type_info)
                         { return kiln::ReferenceCell::of(type_info.param).name(); });
} // namespace
