// Tests src/solvers/block_triangular_preconditioner.cpp on a chain of nodes with a temperature
// and three displacements each: a Jacobian that is block lower-triangular in (T, u), split
// over the ranks. With exact block inverses (MueLu on one level, 100 Gauss-Seidel sweeps) the
// preconditioner is J^{-1}: the split, the coupling J_uT and the reassembly of the unknowns
// are right. A temperature block with identity rows (the held temperature) is inverted by its
// diagonal; a kept preconditioner takes the new values of J through refresh().
// KILN_TEST_NP: 1 2
#include "solvers/block_triangular_preconditioner.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Thyra_DefaultLinearOpSource.hpp>
#include <Thyra_TpetraLinearOp.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace
{
using Teuchos::ParameterList;
using Teuchos::RCP;
using Teuchos::rcp;
using Matrix = Tpetra::CrsMatrix<double>;
using MV = Tpetra::MultiVector<double>;
using Map = Tpetra::Map<>;
using GO = Map::global_ordinal_type;
using LO = Map::local_ordinal_type;
using Node = Map::node_type;
using kiln::internal::BlockTriangularPreconditionerFactory;

constexpr GO n_nodes = 40;

/// The chain's Jacobian: T rows couple the neighbours' T (4, -1); u rows their own
/// component (`stiffness`, -1) and the node's other components (0.5); u rows read the
/// neighbours' T with `coupling` (s + 1) (j - i + 2). `held`: the T rows are identity rows
/// that keep their graph, as while Kiln holds the temperature.
struct Chain
{
  RCP<Matrix> J;
  RCP<MV> coordinates, modes;
};

Chain make_chain(const double coupling, const bool held, const double stiffness = 6.0)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const int rank = comm->getRank(), size = comm->getSize();
  const GO first = n_nodes * rank / size, last = n_nodes * (rank + 1) / size;
  std::vector<GO> node_gids, dof_gids;
  for (GO n = first; n < last; ++n)
  {
    node_gids.push_back(n);
    for (int s = 0; s < 4; ++s)
      dof_gids.push_back(4 * n + s);
  }
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  const auto nodes = rcp(new Map(invalid, node_gids, 0, comm));
  const auto dofs = rcp(new Map(invalid, dof_gids, 0, comm));
  Chain c;
  c.J = rcp(new Matrix(dofs, 12));
  for (GO n = first; n < last; ++n)
    for (GO m = std::max<GO>(0, n - 1); m <= std::min<GO>(n_nodes - 1, n + 1); ++m)
    {
      const double t_value = held ? (m == n ? 1.0 : 0.0) : (m == n ? 4.0 : -1.0);
      c.J->insertGlobalValues(4 * n, Teuchos::tuple<GO>(4 * m), Teuchos::tuple(t_value));
      for (int s = 1; s < 4; ++s)
      {
        c.J->insertGlobalValues(4 * n + s, Teuchos::tuple<GO>(4 * m),
                                Teuchos::tuple(coupling * (s + 1) * double(m - n + 2)));
        for (int t = 1; t < 4; ++t)
        {
          const double value = m == n ? (s == t ? stiffness : 0.5) : (s == t ? -1.0 : 0.0);
          c.J->insertGlobalValues(4 * n + s, Teuchos::tuple<GO>(4 * m + t), Teuchos::tuple(value));
        }
      }
    }
  c.J->fillComplete();
  c.coordinates = rcp(new MV(nodes, 3));
  c.modes = rcp(new MV(dofs, 7));
  for (GO n = first; n < last; ++n)
  {
    const LO l = nodes->getLocalElement(n);
    c.coordinates->replaceLocalValue(l, 0, double(n));
    for (int s = 0; s < 4; ++s)
      c.modes->replaceLocalValue(4 * l + s, s, 1.0);     // T constant, three translations
    c.modes->replaceLocalValue(4 * l + 2, 4, double(n)); // rotations about the chain's axis
    c.modes->replaceLocalValue(4 * l + 3, 5, double(n));
    c.modes->replaceLocalValue(4 * l + 1, 6, 1.0);
  }
  return c;
}

/// The factory with each block solved to round-off: one level, 100 symmetric Gauss-Seidel
/// sweeps (the blocks are diagonally dominant by a factor 2; KLU2 is not used because
/// Debian's Amesos2 solves wrongly on more than one rank, doc/solvers.md).
RCP<BlockTriangularPreconditionerFactory> exact_factory(const Chain &c)
{
  auto factory = rcp(new BlockTriangularPreconditionerFactory);
  auto p = rcp(new ParameterList);
  for (const char *block : {"Temperature", "Displacement"})
  {
    p->sublist(block).set("coarse: max size", 100000);
    p->sublist(block).sublist("coarse: params").set("relaxation: sweeps", 100);
  }
  factory->setParameterList(p);
  factory->set_hints(c.coordinates, c.modes, ParameterList());
  return factory;
}

/// J takes the values of `from` (a chain of the same graph) in place, as a Jacobian
/// evaluated anew; with `last_rank_only` only the last rank's rows change. Collective.
void set_values(Matrix &J, const Matrix &from, const bool last_rank_only = false)
{
  const auto comm = J.getComm();
  const bool mine = !last_rank_only || comm->getRank() == comm->getSize() - 1;
  J.resumeFill();
  for (LO l = 0; mine && l < static_cast<LO>(J.getNodeNumRows()); ++l)
  {
    Matrix::nonconst_local_inds_host_view_type cols("cols", J.getNumEntriesInLocalRow(l));
    Matrix::nonconst_values_host_view_type values("values", cols.extent(0));
    std::size_t n = 0;
    from.getLocalRowCopy(l, cols, values, n);
    J.replaceLocalValues(l, cols, values);
  }
  J.fillComplete();
}

RCP<const Thyra::LinearOpSourceBase<double>> source(const RCP<Matrix> &J)
{
  return Thyra::defaultLinearOpSource<double>(Thyra::tpetraLinearOp<double, LO, GO, Node>(
      Thyra::tpetraVectorSpace<double>(J->getRangeMap()),
      Thyra::tpetraVectorSpace<double>(J->getDomainMap()), J));
}

/// max_i |(P J x - x)_i| over the ranks, x_i = sin(gid).
double error(const Thyra::PreconditionerBase<double> &prec, const Matrix &J)
{
  MV x(J.getDomainMap(), 1), b(J.getRangeMap(), 1), z(J.getDomainMap(), 1);
  for (LO l = 0; l < static_cast<LO>(x.getLocalLength()); ++l)
    x.replaceLocalValue(l, 0, std::sin(double(J.getDomainMap()->getGlobalElement(l))));
  J.apply(x, b);
  const auto op =
      Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>::getConstTpetraOperator(
          prec.getUnspecifiedPrecOp());
  op->apply(b, z);
  z.update(-1.0, x, 1.0);
  std::vector<double> norm(1);
  z.normInf(norm);
  return norm[0];
}

TEST(BlockTriangularPreconditioner, ExactBlockInversesInvertTheJacobian)
{
  const Chain c = make_chain(0.3, false);
  const auto factory = exact_factory(c);
  const auto prec = factory->createPrec();
  factory->initializePrec(source(c.J), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_LT(error(*prec, *c.J), 1e-10);
}

TEST(BlockTriangularPreconditioner, WithoutTheCouplingBlockItWouldNotBeExact)
{
  // The same chain with J_uT zero: P is then the inverse of the block-diagonal J, which is
  // not J^{-1} of the coupled chain (so the first test sees J_uT).
  const Chain coupled = make_chain(0.3, false);
  const Chain uncoupled = make_chain(0.0, false);
  const auto factory = exact_factory(uncoupled);
  const auto prec = factory->createPrec();
  factory->initializePrec(source(uncoupled.J), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_LT(error(*prec, *uncoupled.J), 1e-10);
  EXPECT_GT(error(*prec, *coupled.J), 1e-2);
}

TEST(BlockTriangularPreconditioner, HeldTemperatureIsInvertedByItsDiagonal)
{
  // MueLu finds no node to aggregate in identity rows; D^{-1} inverts them exactly.
  const Chain c = make_chain(0.3, true);
  auto factory = rcp(new BlockTriangularPreconditionerFactory);
  factory->setParameterList(rcp(new ParameterList));
  factory->set_hints(c.coordinates, c.modes, ParameterList());
  const auto prec = factory->createPrec();
  factory->initializePrec(source(c.J), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  MV x(c.J->getDomainMap(), 1), b(c.J->getRangeMap(), 1), z(c.J->getDomainMap(), 1);
  x.putScalar(1.0);
  c.J->apply(x, b);
  Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>::getConstTpetraOperator(
      prec->getUnspecifiedPrecOp())
      ->apply(b, z);
  for (LO l = 0; l < static_cast<LO>(z.getLocalLength()); l += 4)
    EXPECT_DOUBLE_EQ(z.getData(0)[l], 1.0) << "temperature of local node " << l / 4;
}

TEST(BlockTriangularPreconditioner, RefreshTakesTheJacobiansNewValues)
{
  // J's coupling entries change in place, as a Jacobian evaluated anew. The preconditioner
  // built before is exact for the old J only; refresh() gives it the new values (the
  // diagonal blocks, unchanged here, keep their factorizations).
  const Chain c = make_chain(0.3, false);
  const auto factory = exact_factory(c);
  const auto prec = factory->createPrec();
  const auto src = source(c.J);
  factory->initializePrec(src, prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  set_values(*c.J, *make_chain(0.6, false).J);
  EXPECT_GT(error(*prec, *c.J), 1e-2);
  factory->refresh(*src);
  EXPECT_LT(error(*prec, *c.J), 1e-10);
}

TEST(BlockTriangularPreconditioner, KeepsTheHierarchyOfABlockWhoseValuesAreUnchanged)
{
  // The displacement block does not depend on the time step, the temperature block not on
  // the contact set: a new preconditioner rebuilds only the block whose values changed.
  const Chain c = make_chain(0.3, false);
  const auto factory = exact_factory(c);
  const auto prec = factory->createPrec();
  const auto src = source(c.J);
  const auto builds = [&](const int t, const int u)
  {
    factory->initializePrec(src, prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
    EXPECT_EQ(factory->builds().temperature, t);
    EXPECT_EQ(factory->builds().displacement, u);
    EXPECT_LT(error(*prec, *c.J), 1e-10); // a kept hierarchy is still the block's inverse
  };
  builds(1, 1);
  builds(1, 1); // the same values: both kept
  set_values(*c.J, *make_chain(0.3, true).J);
  builds(2, 1); // the temperature block changed
  set_values(*c.J, *make_chain(0.6, true).J);
  builds(2, 1); // J_uT changed: it has no hierarchy
  set_values(*c.J, *make_chain(0.6, true, 7.0).J);
  builds(2, 2); // the displacement block changed
  // Values given to a kept preconditioner (refresh) count as a change at the next build,
  // although J has not changed since.
  set_values(*c.J, *make_chain(0.6, true, 8.0).J);
  factory->refresh(*src);
  builds(2, 3);
  // A change on one rank only: every rank builds anew, since a set-up is collective (without
  // the reduction the ranks would disagree and the set-up hang).
  set_values(*c.J, *make_chain(0.6, true, 9.0).J, true);
  builds(2, 4);
  // New parameters: both anew.
  factory->setParameterList(Teuchos::rcp(new ParameterList(*factory->getParameterList())));
  builds(3, 5);
}
} // namespace

namespace
{
using kiln::internal::block_muelu_list;

std::string smoother(const ParameterList &muelu)
{
  return muelu.get<std::string>("smoother: type");
}

TEST(BlockTriangularPreconditioner,
     DisplacementBlockIsSmoothedByChebyshevUnlessTheInputSaysOtherwise)
{
  const ParameterList none;
  // Kiln's defaults: Chebyshev with Kiln's defaults for it for the displacements, Gauss-Seidel
  // for the temperatures.
  const ParameterList u = block_muelu_list(none, none, 3);
  EXPECT_EQ(smoother(u), "CHEBYSHEV");
  EXPECT_EQ(u.sublist("smoother: params").get<int>("chebyshev: degree"), 2);
  EXPECT_EQ(u.get<int>("number of equations"), 3);
  const ParameterList t = block_muelu_list(none, none, 1);
  EXPECT_EQ(smoother(t), "RELAXATION");
  EXPECT_EQ(t.sublist("smoother: params").get<std::string>("relaxation: type"),
            "Symmetric Gauss-Seidel");

  // The common list as Kiln's defaults fill it (entries marked as defaults): still Chebyshev.
  ParameterList defaults;
  defaults.get("smoother: type", std::string("RELAXATION"));
  ASSERT_TRUE(defaults.getEntry("smoother: type").isDefault());
  EXPECT_EQ(smoother(block_muelu_list(defaults, none, 3)), "CHEBYSHEV");

  // A smoother the input names, for both blocks or the displacement block alone, is kept.
  ParameterList given;
  given.set("smoother: type", "RELAXATION");
  const ParameterList from_common = block_muelu_list(given, none, 3);
  EXPECT_EQ(smoother(from_common), "RELAXATION");
  EXPECT_EQ(from_common.sublist("smoother: params").get<std::string>("relaxation: type"),
            "Gauss-Seidel");
  EXPECT_EQ(smoother(block_muelu_list(none, given, 3)), "RELAXATION");
  // So are the default smoother's parameters the input sets.
  ParameterList sweeps;
  sweeps.sublist("smoother: params").set("relaxation: sweeps", 2);
  const ParameterList tuned = block_muelu_list(none, sweeps, 3);
  EXPECT_EQ(smoother(tuned), "RELAXATION");
  EXPECT_EQ(tuned.sublist("smoother: params").get<int>("relaxation: sweeps"), 2);
  EXPECT_EQ(smoother(block_muelu_list(sweeps, none, 3)), "RELAXATION");
}
} // namespace
