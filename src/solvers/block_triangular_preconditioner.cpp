#include "solvers/block_triangular_preconditioner.hpp"

#include "base/parameters.hpp"
#include "solvers/package_parameters.hpp"

#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_CrsMatrix.hpp>

#include <memory>
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
using Graph = Tpetra::CrsGraph<>;
using MV = Tpetra::MultiVector<double>;
using Op = Tpetra::Operator<double>;
using Map = Tpetra::Map<>;
using LO = Map::local_ordinal_type;
using GO = Map::global_ordinal_type;
using Node = Map::node_type;

/// Unknowns per node: the temperature (slot 0), then the three displacements.
constexpr int n_fields = 4;

/// The map of the global ids `gids` (this rank's), over J's communicator.
RCP<const Map> block_map(const std::vector<GO> &gids, const Map &like)
{
  return rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                     Teuchos::ArrayView<const GO>(gids.data(), gids.size()), 0, like.getComm()));
}

} // namespace

/// J split into J_TT, J_uT and J_uu (J_Tu dropped), with maps of their own: node n's
/// temperature is unknown n of the T block, its displacement component s unknown 3n + s of the
/// u block. The blocks' graphs are made once; update() copies J's values into the blocks in
/// place, so that a hierarchy built on a block reads them on its finest level, as MueLu on J
/// reads J's.
class BlockSplit
{
public:
  explicit BlockSplit(const Matrix &J)
  {
    const Map &rows = *J.getRowMap();
    const Map &cols = *J.getColMap();
    std::vector<GO> t_gids, u_gids;
    for (LO l = 0; l < static_cast<LO>(rows.getNodeNumElements()); ++l)
    {
      const GO g = rows.getGlobalElement(l);
      const int s = static_cast<int>(g % n_fields);
      (s == 0 ? t_rows : u_rows).push_back(l);
      (s == 0 ? t_gids : u_gids).push_back(block_gid(g));
    }
    t_map = block_map(t_gids, rows);
    u_map = block_map(u_gids, rows);

    const auto n_cols = static_cast<LO>(cols.getNodeNumElements());
    col_is_t_.resize(n_cols);
    std::vector<LO> col_lid(n_cols);
    std::vector<GO> tc_gids, uc_gids;
    for (LO c = 0; c < n_cols; ++c)
    {
      const GO g = cols.getGlobalElement(c);
      col_is_t_[c] = g % n_fields == 0;
      std::vector<GO> &list = col_is_t_[c] ? tc_gids : uc_gids;
      col_lid[c] = static_cast<LO>(list.size());
      list.push_back(block_gid(g));
    }
    const RCP<const Map> tc_map = block_map(tc_gids, cols);
    const RCP<const Map> uc_map = block_map(uc_gids, cols);

    // Two passes over J's entries: count each block's row lengths, then fill its indices (in
    // J's order, which keeps them sorted).
    const auto local = J.getLocalMatrixHost();
    const auto &ptr = local.graph.row_map;
    const auto &ind = local.graph.entries;
    const auto pointers = [&](const std::vector<LO> &block_rows, const bool t_columns)
    {
      Teuchos::ArrayRCP<std::size_t> p(block_rows.size() + 1, 0);
      for (std::size_t i = 0; i < block_rows.size(); ++i)
      {
        std::size_t n = 0;
        for (auto k = ptr(block_rows[i]); k < ptr(block_rows[i] + 1); ++k)
          n += col_is_t_[ind(k)] == t_columns ? 1 : 0;
        p[i + 1] = p[i] + n;
      }
      return p;
    };
    const auto indices = [&](const std::vector<LO> &block_rows, const bool t_columns,
                             const Teuchos::ArrayRCP<std::size_t> &p)
    {
      Teuchos::ArrayRCP<LO> c(p[block_rows.size()]);
      std::size_t n = 0;
      for (const LO l : block_rows)
        for (auto k = ptr(l); k < ptr(l + 1); ++k)
          if (col_is_t_[ind(k)] == t_columns)
            c[n++] = col_lid[ind(k)];
      return c;
    };
    const auto block = [&](const std::vector<LO> &block_rows, const bool t_columns,
                           const RCP<const Map> &row_map, const RCP<const Map> &col_map,
                           const RCP<const Map> &domain)
    {
      const Teuchos::ArrayRCP<std::size_t> p = pointers(block_rows, t_columns);
      auto graph = rcp(new Graph(row_map, col_map, p, indices(block_rows, t_columns, p)));
      graph->fillComplete(domain, row_map);
      typename Matrix::local_matrix_device_type::values_type values("block values",
                                                                    p[block_rows.size()]);
      auto m = rcp(new Matrix(graph, values));
      if (!m->isFillComplete())
        m->fillComplete(domain, row_map);
      return m;
    };
    tt = block(t_rows, true, t_map, tc_map, t_map);
    ut = block(u_rows, true, u_map, tc_map, t_map);
    uu = block(u_rows, false, u_map, uc_map, u_map);
  }

  /// Which diagonal blocks' values an update() changed.
  struct Changes
  {
    bool tt = false;
    bool uu = false;
  };

  /// Copies J's values into the blocks (J's graph must be the one they were made from), and
  /// says which diagonal blocks' values changed (to the bit; a NaN counts as a change).
  Changes update(const Matrix &J) const
  {
    const auto local = J.getLocalMatrixHost();
    const auto &ptr = local.graph.row_map;
    const auto &ind = local.graph.entries;
    const auto &values = local.values;
    const auto tt_values = tt->getLocalValuesView();
    const auto ut_values = ut->getLocalValuesView();
    const auto uu_values = uu->getLocalValuesView();
    std::size_t n_tt = 0, n_ut = 0, n_uu = 0;
    Changes changes;
    const auto copy = [](double &to, const double from, bool &changed)
    {
      changed = changed || !(to == from);
      to = from;
    };
    for (const LO l : t_rows)
      for (auto k = ptr(l); k < ptr(l + 1); ++k)
        if (col_is_t_[ind(k)])
          copy(tt_values(n_tt++), values(k), changes.tt);
    for (const LO l : u_rows)
      for (auto k = ptr(l); k < ptr(l + 1); ++k)
        if (col_is_t_[ind(k)])
          ut_values(n_ut++) = values(k);
        else
          copy(uu_values(n_uu++), values(k), changes.uu);
    return changes;
  }

  RCP<Matrix> tt, ut, uu;
  RCP<const Map> t_map, u_map;
  std::vector<LO> t_rows, u_rows; ///< J's local rows of each block, in the block's order

private:
  /// The id in its block of J's unknown g.
  static GO block_gid(const GO g)
  {
    const GO node = g / n_fields;
    const int s = static_cast<int>(g % n_fields);
    return s == 0 ? node : 3 * node + s - 1;
  }
  std::vector<char> col_is_t_; ///< per column of J: a temperature
};

namespace
{
/// D^{-1} of a diagonal matrix: the temperature block while the temperature is held (every
/// row an identity row), where MueLu finds no node to aggregate.
class DiagonalInverse final : public Op
{
public:
  explicit DiagonalInverse(const Matrix &A) : inverse_(A.getRowMap())
  {
    A.getLocalDiagCopy(inverse_);
    inverse_.reciprocal(inverse_);
  }
  RCP<const Map> getDomainMap() const override { return inverse_.getMap(); }
  RCP<const Map> getRangeMap() const override { return inverse_.getMap(); }
  void apply(const MV &X, MV &Y, Teuchos::ETransp, double alpha, double beta) const override
  {
    Y.elementWiseMultiply(alpha, inverse_, X, beta);
  }

private:
  Tpetra::Vector<double> inverse_;
};

/// Whether A's only nonzero values are on its diagonal, on every rank. Collective.
bool is_diagonal(const Matrix &A)
{
  const auto local = A.getLocalMatrixHost();
  const Map &rows = *A.getRowMap();
  const Map &cols = *A.getColMap();
  int off_diagonal = 0;
  for (LO l = 0; l < static_cast<LO>(local.numRows()) && off_diagonal == 0; ++l)
  {
    const GO g = rows.getGlobalElement(l);
    for (auto k = local.graph.row_map(l); k < local.graph.row_map(l + 1); ++k)
      if (local.values(k) != 0.0 && cols.getGlobalElement(local.graph.entries(k)) != g)
      {
        off_diagonal = 1;
        break;
      }
  }
  int any = 0;
  Teuchos::reduceAll(*rows.getComm(), Teuchos::REDUCE_MAX, off_diagonal, Teuchos::outArg(any));
  return any == 0;
}

/// MueLu's hierarchy for A, or D^{-1} if A is diagonal.
RCP<Op> block_preconditioner(const RCP<Matrix> &A, ParameterList &muelu)
{
  if (is_diagonal(*A))
    return rcp(new DiagonalInverse(*A));
  return MueLu::CreateTpetraPreconditioner<double, LO, GO, Node>(Teuchos::rcp_implicit_cast<Op>(A),
                                                                 muelu);
}

/// z = P r: z_T = M_T r_T, z_u = M_u (r_u - J_uT z_T), M_T and M_u the blocks' hierarchies.
class BlockTriangularOperator final : public Op
{
public:
  BlockTriangularOperator(RCP<const Map> map, std::shared_ptr<const BlockSplit> split, RCP<Op> t,
                          RCP<Op> u)
      : map_(std::move(map)), split_(std::move(split)), t_(std::move(t)), u_(std::move(u)),
        t_timer_(Teuchos::TimeMonitor::getNewTimer("Kiln: 8 block T")),
        u_timer_(Teuchos::TimeMonitor::getNewTimer("Kiln: 8 block u"))
  {
  }

  RCP<const Map> getDomainMap() const override { return map_; }
  RCP<const Map> getRangeMap() const override { return map_; }

  void apply(const MV &X, MV &Y, Teuchos::ETransp mode, double alpha, double beta) const override
  {
    TEUCHOS_TEST_FOR_EXCEPTION(mode != Teuchos::NO_TRANS, std::logic_error,
                               "the block triangular preconditioner has no transpose");
    const BlockSplit &s = *split_;
    const std::size_t n_vectors = X.getNumVectors();
    if (rt_.is_null() || rt_->getNumVectors() != n_vectors)
    {
      rt_ = rcp(new MV(s.t_map, n_vectors, false));
      zt_ = rcp(new MV(s.t_map, n_vectors, false));
      ru_ = rcp(new MV(s.u_map, n_vectors, false));
      zu_ = rcp(new MV(s.u_map, n_vectors, false));
    }
    for (std::size_t j = 0; j < n_vectors; ++j)
    {
      const auto x = X.getData(j);
      auto t = rt_->getDataNonConst(j);
      auto u = ru_->getDataNonConst(j);
      for (std::size_t i = 0; i < s.t_rows.size(); ++i)
        t[i] = x[s.t_rows[i]];
      for (std::size_t i = 0; i < s.u_rows.size(); ++i)
        u[i] = x[s.u_rows[i]];
    }
    {
      Teuchos::TimeMonitor monitor(*t_timer_);
      t_->apply(*rt_, *zt_);
    }
    s.ut->apply(*zt_, *ru_, Teuchos::NO_TRANS, -1.0, 1.0);
    {
      Teuchos::TimeMonitor monitor(*u_timer_);
      u_->apply(*ru_, *zu_);
    }
    for (std::size_t j = 0; j < n_vectors; ++j)
    {
      auto y = Y.getDataNonConst(j);
      const auto t = zt_->getData(j);
      const auto u = zu_->getData(j);
      // beta = 0 ignores what Y held (it may be uninitialized)
      const auto put = [&](const LO l, const double z)
      { y[l] = beta == 0.0 ? alpha * z : alpha * z + beta * y[l]; };
      for (std::size_t i = 0; i < s.t_rows.size(); ++i)
        put(s.t_rows[i], t[i]);
      for (std::size_t i = 0; i < s.u_rows.size(); ++i)
        put(s.u_rows[i], u[i]);
    }
  }

private:
  RCP<const Map> map_;
  std::shared_ptr<const BlockSplit> split_;
  RCP<Op> t_, u_;
  RCP<Teuchos::Time> t_timer_, u_timer_;
  mutable RCP<MV> rt_, zt_, ru_, zu_; ///< work vectors of apply()
};

/// Rows `rows` of the columns [first, first + count) of `modes`, on `map`.
RCP<MV> restrict_modes(const MV &modes, std::size_t first, std::size_t count,
                       const std::vector<LO> &rows, const RCP<const Map> &map)
{
  auto out = rcp(new MV(map, count, false));
  for (std::size_t j = 0; j < count; ++j)
  {
    const auto from = modes.getData(first + j);
    auto to = out->getDataNonConst(j);
    for (std::size_t i = 0; i < rows.size(); ++i)
      to[i] = from[rows[i]];
  }
  return out;
}
} // namespace

ParameterList block_muelu_list(const ParameterList &common, const ParameterList &own, int equations)
{
  ParameterList stratimikos;
  stratimikos.set("Preconditioner Type", "MueLu");
  ParameterList &muelu = stratimikos.sublist("Preconditioner Types").sublist("MueLu");
  muelu.setParameters(muelu_defaults());
  muelu.set("number of equations", equations);
  muelu.setParameters(common);
  // The displacement block is smoothed by Chebyshev unless the input names a smoother or
  // sets its parameters: a polynomial in D^-1 A is the same on any number of ranks, where
  // Gauss-Seidel is Jacobi across them. 64^3 contact box to 60 s: np 1 / np 2 159 / 162
  // GMRES iterations against 181 / 208, np 2 60.3-60.7 s against 61.9-66.2 s, one rank's
  // time the same (doc/solvers.md, "Block Triangular").
  const auto smoother_given = [](const ParameterList &list)
  { return given_in_input(list, "smoother: type") || given_in_input(list, "smoother: params"); };
  if (equations == 3 && !smoother_given(common) && !smoother_given(own))
    muelu.set("smoother: type", "CHEBYSHEV");
  muelu.setParameters(own);
  add_smoother_defaults(stratimikos);
  return muelu;
}

void BlockTriangularPreconditionerFactory::set_hints(RCP<const MultiVector> coordinates,
                                                     RCP<const MultiVector> near_null_space,
                                                     const ParameterList &muelu)
{
  coordinates_ = std::move(coordinates);
  near_null_space_ = std::move(near_null_space);
  muelu_ = muelu;
  // What Kiln gives a hierarchy of the whole system; each block gets its own.
  for (const char *name : {"Coordinates", "Nullspace", "number of equations"})
    muelu_.remove(name, false);
  t_stale_ = u_stale_ = true;
}

void BlockTriangularPreconditionerFactory::initializePrec(
    const RCP<const Thyra::LinearOpSourceBase<double>> &fwdOpSrc,
    Thyra::PreconditionerBase<double> *precOp, Thyra::ESupportSolveUse) const
{
  uninitializePrec(precOp, nullptr, nullptr);
  const RCP<const Matrix> J = crs_matrix(*fwdOpSrc, true);
  if (split_ == nullptr || split_graph_ != J->getCrsGraph().get())
  {
    // The last blocks and hierarchies go before the new ones are made.
    t_op_ = u_op_ = Teuchos::null;
    split_ = nullptr;
    split_ = std::make_shared<BlockSplit>(*J);
    split_graph_ = J->getCrsGraph().get();
    t_stale_ = u_stale_ = true;
  }
  note_changes(*J);
  for (const bool temperature : {true, false})
  {
    RCP<Op> &op = temperature ? t_op_ : u_op_;
    bool &stale = temperature ? t_stale_ : u_stale_;
    if (!stale)
      continue;
    // The old hierarchy goes before the new one is built (the linear solver's hold on the
    // last operator is released by ReusingPreconditionerFactory).
    op = Teuchos::null;
    op = build_block(temperature);
    stale = false;
    ++(temperature ? builds_.temperature : builds_.displacement);
  }
  set_operator(*precOp, *J, rcp(new BlockTriangularOperator(J->getRowMap(), split_, t_op_, u_op_)));
}

RCP<Tpetra::Operator<double>>
BlockTriangularPreconditionerFactory::build_block(const bool temperature) const
{
  const BlockSplit &split = *split_;
  const ParameterList &p = *getParameterList();
  ParameterList list = temperature ? block_muelu_list(muelu_, p.sublist("Temperature"), 1)
                                   : block_muelu_list(muelu_, p.sublist("Displacement"), 3);
  if (!coordinates_.is_null())
    // MueLu reads them without changing them; it takes a non-const pointer.
    list.sublist("user data").set("Coordinates", Teuchos::rcp_const_cast<MV>(coordinates_));
  if (!near_null_space_.is_null() && near_null_space_->getNumVectors() == n_fields + 3)
    list.sublist("user data")
        .set("Nullspace", temperature
                              ? restrict_modes(*near_null_space_, 0, 1, split.t_rows, split.t_map)
                              : restrict_modes(*near_null_space_, 1, 6, split.u_rows, split.u_map));
  return block_preconditioner(temperature ? split.tt : split.uu, list);
}

void BlockTriangularPreconditionerFactory::note_changes(const Matrix &J) const
{
  const BlockSplit::Changes changes = split_->update(J);
  // A hierarchy's set-up is collective: a block changed on one rank is rebuilt on all.
  const int local[2] = {changes.tt ? 1 : 0, changes.uu ? 1 : 0};
  int global[2] = {0, 0};
  Teuchos::reduceAll(*J.getComm(), Teuchos::REDUCE_MAX, 2, local, global);
  t_stale_ = t_stale_ || global[0] != 0;
  u_stale_ = u_stale_ || global[1] != 0;
}

void BlockTriangularPreconditionerFactory::refresh(
    const Thyra::LinearOpSourceBase<double> &fwdOpSrc) const
{
  const RCP<const Matrix> J = crs_matrix(fwdOpSrc, true);
  if (split_ != nullptr && split_graph_ == J->getCrsGraph().get())
    note_changes(*J);
}

RCP<const ParameterList> BlockTriangularPreconditionerFactory::getValidParameters() const
{
  static const RCP<const ParameterList> valid = []
  {
    auto p = rcp(new ParameterList("Block Triangular"));
    p->sublist("Temperature", false,
               "MueLu parameters for the temperature block (Kiln's MueLu defaults with one "
               "unknown per node, then these)")
        .disableRecursiveValidation();
    p->sublist("Displacement", false,
               "MueLu parameters for the displacement block (Kiln's MueLu defaults with three "
               "unknowns per node, the six rigid-body modes and, unless the input sets "
               "\"smoother: type\" or \"smoother: params\", CHEBYSHEV smoothing; then these)")
        .disableRecursiveValidation();
    return p;
  }();
  return valid;
}
} // namespace internal
} // namespace kiln
