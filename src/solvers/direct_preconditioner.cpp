#include "solvers/direct_preconditioner.hpp"

#include "base/errors.hpp"

#include <Amesos2.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_ComputeGatherMap.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace kiln
{
namespace internal
{
namespace
{
/// Above this the Jacobian is taken as singular (a free rigid motion, a body held by nothing):
/// 1e-4 of 1 / (machine epsilon).
constexpr double max_condition = 4.5e11;
using Teuchos::ParameterList;
using Teuchos::RCP;
using Teuchos::rcp;
using Matrix = Tpetra::CrsMatrix<double>;
using MV = Tpetra::MultiVector<double>;
using Op = Tpetra::Operator<double>;
using Map = Tpetra::Map<>;
using Import = Tpetra::Import<>;
using LO = Map::local_ordinal_type;
using GO = Map::global_ordinal_type;
using Node = Map::node_type;
using Solver = Amesos2::Solver<Matrix, MV>;

/// Over a one-rank communicator, the ids of `map`'s rows on this rank renumbered by
/// `number` (KLU2 takes only ids 0, 1, ..., n - 1 in order).
RCP<const Map> serial_map(const Map &map, const std::function<GO(GO)> &number,
                          const RCP<const Teuchos::Comm<int>> &self)
{
  std::vector<GO> gids;
  for (const GO gid : map.getNodeElementList())
    gids.push_back(number(gid));
  return rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(), gids, 0, self));
}

/// A lower bound of the condition number ||A|| ||A^{-1}|| (infinity norms) of the factored
/// A: ||A|| ||x|| / ||b|| for x = A^{-1} b, b_i = 1 + sin(i) / 2 (no pattern that a null
/// vector could be orthogonal to). Infinite if x is not finite. A singular matrix that the
/// factorization's round-off makes regular gives about 1e16 and more; Kiln's Jacobians of
/// held bodies 1e3 to 1e9 (doc/solvers.md).
double condition_estimate(const Matrix &A, Solver &solver)
{
  const auto local = A.getLocalMatrixHost();
  double norm_A = 0.0;
  for (LO i = 0; i < static_cast<LO>(local.numRows()); ++i)
  {
    double row = 0.0;
    for (auto k = local.graph.row_map(i); k < local.graph.row_map(i + 1); ++k)
      row += std::abs(local.values(k));
    norm_A = std::max(norm_A, row);
  }
  MV b(A.getRowMap(), 1, false), x(A.getRowMap(), 1, false);
  {
    auto values = b.getDataNonConst(0);
    for (LO i = 0; i < static_cast<LO>(values.size()); ++i)
      values[i] = 1.0 + 0.5 * std::sin(static_cast<double>(i));
  }
  solver.solve(Teuchos::ptrFromRef(x), Teuchos::ptrFromRef(b));
  double norm_x = 0.0;
  for (const double v : x.getData(0))
  {
    if (!std::isfinite(v))
      return std::numeric_limits<double>::infinity();
    norm_x = std::max(norm_x, std::abs(v));
  }
  return norm_A * norm_x / 1.5;
}
} // namespace

/// What J's factors need: the gather of J's rows onto rank 0, and there the LU factors of
/// the gathered matrix over a one-rank communicator.
struct DirectPreconditionerFactory::Factors
{
  RCP<const Map> rows;                ///< J's row map, which the gather was made for
  RCP<const Map> gathered;            ///< J's rows, all on rank 0
  RCP<const Import> gather;           ///< J's row map -> gathered
  RCP<const Teuchos::Comm<int>> self; ///< rank 0 alone (the other ranks: their own)
  RCP<const Map> serial_rows;         ///< rank 0: 0, ..., n - 1 over `self`
  RCP<Solver> solver;                 ///< rank 0: KLU2 with the factors of J
  bool root = false;                  ///< this rank holds the factors
};

namespace
{
/// M^{-1} x by the factors: x gathered onto rank 0, solved there, the solution scattered.
class DirectOperator final : public Op
{
public:
  DirectOperator(RCP<const Map> map, std::shared_ptr<const DirectPreconditionerFactory::Factors> f)
      : map_(std::move(map)), f_(std::move(f))
  {
  }
  RCP<const Map> getDomainMap() const override { return map_; }
  RCP<const Map> getRangeMap() const override { return map_; }
  void apply(const MV &X, MV &Y, Teuchos::ETransp mode, double alpha, double beta) const override;

private:
  RCP<const Map> map_;
  std::shared_ptr<const DirectPreconditionerFactory::Factors> f_;
};

void DirectOperator::apply(const MV &X, MV &Y, const Teuchos::ETransp mode, const double alpha,
                           const double beta) const
{
  TEUCHOS_TEST_FOR_EXCEPTION(mode != Teuchos::NO_TRANS, std::logic_error,
                             "Kiln's Direct preconditioner: only M^{-1} x is applied");
  const std::size_t n = X.getNumVectors();
  MV x0(f_->gathered, n, false), y0(f_->gathered, n, false);
  x0.doImport(X, *f_->gather, Tpetra::INSERT);
  if (f_->root)
  {
    // The same rows over rank 0 alone: copies, as small as the problem.
    MV xs(f_->serial_rows, n, false), ys(f_->serial_rows, n, false);
    Tpetra::deep_copy(xs, x0);
    f_->solver->solve(Teuchos::ptrFromRef(ys), Teuchos::ptrFromRef(xs));
    Tpetra::deep_copy(y0, ys);
  }
  if (alpha == 1.0 && beta == 0.0)
  {
    Y.doExport(y0, *f_->gather, Tpetra::INSERT);
    return;
  }
  MV y(Y.getMap(), n, false);
  y.doExport(y0, *f_->gather, Tpetra::INSERT);
  Y.update(alpha, y, beta);
}
} // namespace

DirectPreconditionerFactory::DirectPreconditionerFactory() = default;
DirectPreconditionerFactory::~DirectPreconditionerFactory() = default;

void DirectPreconditionerFactory::initializePrec(
    const RCP<const Thyra::LinearOpSourceBase<double>> &fwdOpSrc,
    Thyra::PreconditionerBase<double> *precOp, Thyra::ESupportSolveUse) const
{
  uninitializePrec(precOp, nullptr, nullptr);
  const RCP<const Matrix> J = crs_matrix(*fwdOpSrc, true);
  const auto comm = J->getComm();
  // New factors: the operators made before keep theirs. The gather depends on J's rows only.
  auto f = std::make_shared<Factors>();
  if (factors_ != nullptr && factors_->rows.get() == J->getRowMap().get())
  {
    f->rows = factors_->rows;
    f->gathered = factors_->gathered;
    f->gather = factors_->gather;
    f->self = factors_->self;
    f->serial_rows = factors_->serial_rows;
  }
  else
  {
    f->rows = J->getRowMap();
    f->gathered = Tpetra::Details::computeGatherMap<Map>(J->getRowMap(), Teuchos::null);
    f->gather = rcp(new Import(J->getRowMap(), f->gathered));
    f->self = comm->split(comm->getRank() == 0 ? 0 : 1, 0);
    // Rank 0's rows numbered in order: a column's number is its row's.
    f->serial_rows = comm->getRank() == 0
                         ? rcp(new Map(f->gathered->getNodeNumElements(), 0, f->self))
                         : Teuchos::null;
  }
  f->root = comm->getRank() == 0;
  const RCP<Matrix> gathered =
      Tpetra::importAndFillCompleteCrsMatrix<Matrix>(J, *f->gather, f->gathered, f->gathered);
  std::string failure;
  if (f->root)
  {
    try
    {
      // The gathered matrix over rank 0 alone: its local rows and columns, the columns
      // numbered by their rows.
      const auto local = gathered->getLocalMatrixHost();
      const std::size_t rows = local.numRows();
      const std::size_t entries = local.nnz();
      Teuchos::ArrayRCP<std::size_t> offsets(rows + 1);
      Teuchos::ArrayRCP<LO> columns(entries);
      Teuchos::ArrayRCP<double> values(entries);
      for (std::size_t i = 0; i <= rows; ++i)
        offsets[i] = local.graph.row_map(i);
      for (std::size_t k = 0; k < entries; ++k)
      {
        columns[k] = local.graph.entries(k);
        values[k] = local.values(k);
      }
      const Map &gathered_rows = *f->gathered;
      const auto columns_map = serial_map(
          *gathered->getColMap(),
          [&gathered_rows](const GO gid) { return GO(gathered_rows.getLocalElement(gid)); },
          f->self);
      auto serial = rcp(new Matrix(f->serial_rows, columns_map, offsets, columns, values));
      serial->fillComplete(f->serial_rows, f->serial_rows);
      f->solver = Amesos2::create<Matrix, MV>("KLU2", serial);
      f->solver->symbolicFactorization().numericFactorization();
      const double condition = condition_estimate(*serial, *f->solver);
      if (!(condition < max_condition))
      {
        std::ostringstream s;
        s.precision(2);
        s << "the factors are singular to working precision, a condition number of at least "
          << condition << " (above " << max_condition << ")";
        failure = s.str();
      }
    }
    catch (const std::exception &e)
    {
      failure = one_line_library_message(e.what());
    }
  }
  check_run_collectively(
      *comm, failure.empty(),
      "the Direct preconditioner could not factor the Jacobian (Amesos2 KLU2: " + failure +
          "): it is singular, so the solution would be arbitrary: a body free to move as a "
          "rigid body, e.g. one that only contact holds along the gap's normal while the gap "
          "is open; hold it with a displacement condition (doc/mechanics.md, \"Free "
          "motions\")");
  ++factorizations_;
  factors_ = f;
  set_operator(*precOp, *J, rcp(new DirectOperator(J->getRowMap(), f)));
}

RCP<const ParameterList> DirectPreconditionerFactory::getValidParameters() const
{
  static const RCP<const ParameterList> valid = rcp(new ParameterList("Direct"));
  return valid;
}
} // namespace internal
} // namespace kiln
