#include "solvers/direct_preconditioner.hpp"

#include "base/errors.hpp"

#include <Amesos2.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_ComputeGatherMap.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>

#include <functional>
#include <string>
#include <vector>

namespace kiln
{
namespace internal
{
namespace
{
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
    }
    catch (const std::exception &e)
    {
      failure = one_line_library_message(e.what());
    }
  }
  check_run_collectively(
      *comm, failure.empty(),
      "the Direct preconditioner could not factor the Jacobian (Amesos2 KLU2: " + failure +
          "): it is singular, e.g. a body that no displacement condition or contact holds "
          "can move freely; check the Boundary Conditions, or set Kiln/Solver/Linear "
          "Solver/\"Preconditioner Type\" to \"MueLu\"");
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
