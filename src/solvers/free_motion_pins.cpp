#include "solvers/free_motion_pins.hpp"

#include "base/errors.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_LAPACK.hpp>
#include <Teuchos_OrdinalTraits.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace kiln
{
namespace internal
{
namespace
{
using GO = NonlinearProblem::Map::global_ordinal_type;
using LO = NonlinearProblem::Map::local_ordinal_type;

/// Orthonormal columns with the span of V's (modified Gram-Schmidt, twice). Collective.
Teuchos::RCP<FreeMotionPins::MultiVector> orthonormal(const FreeMotionPins::MultiVector &V)
{
  auto Q = Teuchos::rcp(new FreeMotionPins::MultiVector(V, Teuchos::Copy));
  const auto k = Q->getNumVectors();
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t j = 0; j < k; ++j)
    {
      auto q = Q->getVectorNonConst(j);
      for (std::size_t i = 0; i < j; ++i)
      {
        const auto e = Q->getVector(i);
        q->update(-e->dot(*q), *e, 1.0);
      }
      const double length = q->norm2();
      KILN_ASSERT(length > 0.0, "a free motion is a combination of the others");
      q->scale(1.0 / length);
    }
  return Q;
}
} // namespace

FreeMotionPins::FreeMotionPins(const MultiVector &motions, const Vector *inverse_scale,
                               std::vector<std::string> names)
    : V_(Teuchos::rcp(new MultiVector(motions, Teuchos::Copy))), names_(std::move(names))
{
  const auto k = static_cast<int>(V_->getNumVectors());
  if (inverse_scale != nullptr)
    for (int j = 0; j < k; ++j)
      V_->getVectorNonConst(j)->elementWiseMultiply(1.0, *inverse_scale, *motions.getVector(j),
                                                    0.0);
  Q_ = orthonormal(*V_);
  load_.assign(k, 0.0);

  // Full pivoting on a copy W of V̂: the largest entry among the columns not yet used and
  // the rows not yet pinned, then that column eliminated from the others.
  const auto &map = *V_->getMap();
  const auto &comm = *map.getComm();
  MultiVector W(*V_, Teuchos::Copy);
  std::vector<char> used(k, 0);
  std::vector<char> pinned(map.getNodeNumElements(), 0);
  for (int s = 0; s < k; ++s)
  {
    double best = -1.0;
    LO best_row = -1;
    int best_column = -1;
    for (int j = 0; j < k; ++j)
    {
      if (used[j])
        continue;
      const auto w = W.getData(j);
      for (LO i = 0; i < static_cast<LO>(w.size()); ++i)
        if (!pinned[i] && std::abs(w[i]) > best)
        {
          best = std::abs(w[i]);
          best_row = i;
          best_column = j;
        }
    }
    double global_best = 0.0;
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, best, Teuchos::outArg(global_best));
    const int mine = best == global_best && best_row >= 0 ? comm.getRank() : comm.getSize();
    int owner = 0;
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(owner));
    KILN_ASSERT(global_best > 0.0, "the free motions are not independent");
    // The owner's pivot: its global id, column and the row of W and of V̂.
    std::vector<double> message(2 + 2 * static_cast<std::size_t>(k), 0.0);
    if (comm.getRank() == owner)
    {
      pinned[best_row] = 1;
      message[0] = static_cast<double>(map.getGlobalElement(best_row));
      message[1] = best_column;
      for (int j = 0; j < k; ++j)
      {
        message[2 + j] = W.getData(j)[best_row];
        message[2 + k + j] = V_->getData(j)[best_row];
      }
    }
    Teuchos::broadcast(comm, owner, static_cast<int>(message.size()), message.data());
    pins_.push_back(static_cast<GO>(message[0]));
    const int column = static_cast<int>(message[1]);
    used[column] = 1;
    V_pins_.insert(V_pins_.end(), message.begin() + 2 + k, message.end());
    const double pivot = message[2 + column];
    for (int j = 0; j < k; ++j)
      if (!used[j])
        W.getVectorNonConst(j)->update(-message[2 + j] / pivot, *W.getVector(column), 1.0);
  }
}

void FreeMotionPins::pin(Matrix &J) const
{
  const auto &rows = *J.getRowMap();
  const auto &columns = *J.getColMap();
  const LO invalid = Teuchos::OrdinalTraits<LO>::invalid();
  std::vector<char> pinned_column(columns.getNodeNumElements(), 0);
  for (const GO p : pins_)
    if (const LO c = columns.getLocalElement(p); c != invalid)
      pinned_column[c] = 1;
  J.resumeFill();
  {
    const auto local = J.getLocalMatrixHost();
    for (LO row = 0; row < static_cast<LO>(local.numRows()); ++row)
    {
      const GO gid = rows.getGlobalElement(row);
      const bool pinned_row = std::find(pins_.begin(), pins_.end(), gid) != pins_.end();
      for (auto e = local.graph.row_map(row); e < local.graph.row_map(row + 1); ++e)
      {
        const LO c = local.graph.entries(e);
        const bool diagonal = columns.getGlobalElement(c) == gid;
        if (pinned_row && diagonal)
          local.values(e) = local.values(e) > 0.0 ? local.values(e) : 1.0;
        else if (pinned_row || pinned_column[c])
          local.values(e) = 0.0;
      }
    }
  }
  J.fillComplete(J.getDomainMap(), J.getRangeMap());
}

void FreeMotionPins::residual(Vector &f)
{
  for (int j = 0; j < size(); ++j)
    load_[j] = V_->getVector(j)->dot(f);
  const LO invalid = Teuchos::OrdinalTraits<LO>::invalid();
  for (const GO p : pins_)
    if (f.getMap()->getLocalElement(p) != invalid)
      f.replaceGlobalValue(p, 0.0);
}

void FreeMotionPins::project(Vector &x) const
{
  for (int j = 0; j < size(); ++j)
  {
    const auto q = Q_->getVector(j);
    x.update(-q->dot(x), *q, 1.0);
  }
}

double FreeMotionPins::pin_residual() const
{
  // F̂_p = V̂_p^{-T} (V̂^T F̂): solve V̂_p^T y = load.
  const int k = size();
  if (k == 0)
    return 0.0;
  std::vector<double> A(static_cast<std::size_t>(k) * k); // V̂_p^T, column-major
  for (int s = 0; s < k; ++s)
    for (int j = 0; j < k; ++j)
      A[static_cast<std::size_t>(s) * k + j] = V_pins_[static_cast<std::size_t>(s) * k + j];
  std::vector<double> y = load_;
  std::vector<int> pivots(k);
  int info = 0;
  Teuchos::LAPACK<int, double>().GESV(k, 1, A.data(), k, pivots.data(), y.data(), k, &info);
  KILN_ASSERT(info == 0, "the pins' rows of the free motions are singular");
  double sum = 0.0;
  for (const double v : y)
    sum += v * v;
  return std::sqrt(sum);
}

std::string FreeMotionPins::imbalance() const
{
  std::ostringstream s;
  s.precision(4);
  for (int j = 0; j < size(); ++j)
  {
    // F = internal - external forces, and the internal ones have no part along a free
    // motion: -V^T F is the load's.
    const bool translation = names_[j].rfind("translation", 0) == 0;
    const bool rotation = names_[j].rfind("rotation", 0) == 0;
    s << (j == 0 ? "" : ", ") << -load_[j]
      << (translation ? " N along the "
          : rotation  ? " N m about the axis of the "
                      : " (N or N m) for the ")
      << names_[j];
  }
  return s.str();
}
} // namespace internal
} // namespace kiln
