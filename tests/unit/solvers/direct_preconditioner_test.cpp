// Tests src/solvers/direct_preconditioner.cpp: J gathered onto rank 0 and factored there is
// J^{-1} on any number of ranks, also for rows spread over the ranks out of order (every
// size-th global row on a rank); a preconditioner made before keeps its factors when the next
// is made for new values; a singular J ends the run on every rank with a message that says
// what to do.
// KILN_TEST_NP: 1 2
#include "solvers/direct_preconditioner.hpp"

#include "base/errors.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <Thyra_DefaultLinearOpSource.hpp>
#include <Thyra_TpetraLinearOp.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace
{
using Teuchos::RCP;
using Teuchos::rcp;
using Matrix = Tpetra::CrsMatrix<double>;
using MV = Tpetra::MultiVector<double>;
using Map = Tpetra::Map<>;
using GO = Map::global_ordinal_type;
using LO = Map::local_ordinal_type;
using Node = Map::node_type;
using kiln::internal::DirectPreconditionerFactory;

constexpr GO n_rows = 30;

/// A nonsymmetric tridiagonal matrix plus an entry to row + 7: (`diagonal` + i / 10) on the
/// diagonal, -1 before, -2 after, 0.5 at +7; row `zero` (if >= 0) all zero. Rank r holds the
/// rows i with i % size == r.
/// The rows i of n_rows with i % size == rank.
RCP<const Map> spread_rows()
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  std::vector<GO> gids;
  for (GO i = comm->getRank(); i < n_rows; i += comm->getSize())
    gids.push_back(i);
  return rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(), gids, 0, comm));
}

RCP<Matrix> make_matrix(const double diagonal, const GO zero = -1)
{
  const auto map = spread_rows();
  auto J = rcp(new Matrix(map, 4));
  for (const GO i : map->getNodeElementList())
  {
    const double s = i == zero ? 0.0 : 1.0;
    J->insertGlobalValues(i, Teuchos::tuple<GO>(i), Teuchos::tuple(s * (diagonal + i / 10.0)));
    if (i > 0)
      J->insertGlobalValues(i, Teuchos::tuple<GO>(i - 1), Teuchos::tuple(-s));
    if (i + 1 < n_rows)
      J->insertGlobalValues(i, Teuchos::tuple<GO>(i + 1), Teuchos::tuple(-2.0 * s));
    if (i + 7 < n_rows)
      J->insertGlobalValues(i, Teuchos::tuple<GO>(i + 7), Teuchos::tuple(0.5 * s));
  }
  J->fillComplete();
  return J;
}

RCP<const Thyra::LinearOpSourceBase<double>> source(const RCP<Matrix> &J)
{
  return Thyra::defaultLinearOpSource<double>(Thyra::tpetraLinearOp<double, LO, GO, Node>(
      Thyra::tpetraVectorSpace<double>(J->getRangeMap()),
      Thyra::tpetraVectorSpace<double>(J->getDomainMap()), J));
}

RCP<const Tpetra::Operator<double>> operator_of(const Thyra::PreconditionerBase<double> &prec)
{
  return Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>::getConstTpetraOperator(
      prec.getUnspecifiedPrecOp());
}

/// max |P J x - x| over the ranks, for two vectors x (columns sin(gid + j)).
double error(const Thyra::PreconditionerBase<double> &prec, const Matrix &J)
{
  MV x(J.getDomainMap(), 2), b(J.getRangeMap(), 2), z(J.getDomainMap(), 2);
  for (LO l = 0; l < static_cast<LO>(x.getLocalLength()); ++l)
    for (int j = 0; j < 2; ++j)
      x.replaceLocalValue(l, j, std::sin(double(J.getDomainMap()->getGlobalElement(l) + j)));
  J.apply(x, b);
  operator_of(prec)->apply(b, z);
  z.update(-1.0, x, 1.0);
  std::vector<double> norms(2);
  z.normInf(norms);
  return std::max(norms[0], norms[1]);
}

TEST(DirectPreconditioner, InvertsTheJacobianOnAnyNumberOfRanks)
{
  const RCP<Matrix> J = make_matrix(5.0);
  DirectPreconditionerFactory factory;
  ASSERT_TRUE(factory.isCompatible(*source(J)));
  const auto prec = factory.createPrec();
  factory.initializePrec(source(J), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_LT(error(*prec, *J), 1e-13);
  EXPECT_EQ(factory.factorizations(), 1);

  // Y = alpha M^{-1} X + beta Y, as Tpetra's apply() promises.
  MV x(J->getDomainMap(), 1), y(J->getRangeMap(), 1), z(J->getDomainMap(), 1);
  x.putScalar(1.0);
  J->apply(x, y); // y = J 1
  z.putScalar(3.0);
  operator_of(*prec)->apply(y, z, Teuchos::NO_TRANS, 2.0, -1.0); // 2 * 1 - 3
  for (LO l = 0; l < static_cast<LO>(z.getLocalLength()); ++l)
    EXPECT_NEAR(z.getData(0)[l], -1.0, 1e-13);
}

TEST(DirectPreconditioner, AnEarlierPreconditionerKeepsItsFactors)
{
  // The second initializePrec() factors new values of the same graph (a Jacobian evaluated
  // anew); the first preconditioner still inverts the values it was made for.
  const RCP<Matrix> old_values = make_matrix(5.0), new_values = make_matrix(9.0);
  DirectPreconditionerFactory factory;
  const auto first = factory.createPrec(), second = factory.createPrec();
  factory.initializePrec(source(old_values), first.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  factory.initializePrec(source(new_values), second.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(factory.factorizations(), 2);
  EXPECT_LT(error(*second, *new_values), 1e-13);
  EXPECT_GT(error(*second, *old_values), 1e-2);
  EXPECT_LT(error(*first, *old_values), 1e-13);
}

/// The message of the RunError initializePrec() throws for J ("no RunError" if none).
std::string factorization_error(const RCP<Matrix> &J, const DirectPreconditionerFactory &factory)
{
  const auto prec = factory.createPrec();
  try
  {
    factory.initializePrec(source(J), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  }
  catch (const kiln::RunError &e)
  {
    return e.what();
  }
  return "no RunError";
}

TEST(DirectPreconditioner, ASingularJacobianEndsTheRunOnEveryRank)
{
  // Row 3 is zero: KLU2 on rank 0 fails, and every rank throws the same RunError (none is
  // left waiting in a collective call).
  DirectPreconditionerFactory factory;
  const std::string message = factorization_error(make_matrix(5.0, 3), factory);
  EXPECT_THAT(message, testing::StartsWith("the Direct preconditioner could not factor the "
                                           "Jacobian (Amesos2 KLU2: "));
  EXPECT_THAT(message, testing::HasSubstr("hold it with a displacement condition"));
  EXPECT_EQ(factory.factorizations(), 0);
}

TEST(DirectPreconditioner, AJacobianSingularToRoundOffIsRefused)
{
  // The 1D Laplacian with free ends (a body held by nothing: the constant is its null
  // vector), made regular by 1e-15 on the end diagonals: KLU2 factors it without complaint
  // (pivots of 1e-15), and the condition estimate (about 1e17) refuses it.
  const auto map = spread_rows();
  auto J = rcp(new Matrix(map, 3));
  for (const GO i : map->getNodeElementList())
  {
    const bool end = i == 0 || i + 1 == n_rows;
    J->insertGlobalValues(i, Teuchos::tuple<GO>(i), Teuchos::tuple(end ? 1.0 + 1e-15 : 2.0));
    if (i > 0)
      J->insertGlobalValues(i, Teuchos::tuple<GO>(i - 1), Teuchos::tuple(-1.0));
    if (i + 1 < n_rows)
      J->insertGlobalValues(i, Teuchos::tuple<GO>(i + 1), Teuchos::tuple(-1.0));
  }
  J->fillComplete();
  DirectPreconditionerFactory factory;
  EXPECT_THAT(factorization_error(J, factory),
              testing::HasSubstr("the factors are singular to working precision, a "
                                 "condition number of at least "));
  EXPECT_EQ(factory.factorizations(), 0);
}
} // namespace
