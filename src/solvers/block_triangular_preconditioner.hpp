#pragma once
/// Private to src/solvers: the preconditioner "Block Triangular" for the coupled system of
/// temperature and displacement (doc/solvers.md). Its Jacobian is block lower-triangular,
///
///     J = [ J_TT   0   ]   (the heat equation does not read u; the force rows read T
///         [ J_uT  J_uu ]    through the thermal strain),
///
/// so J^{-1} r is z_T = J_TT^{-1} r_T, then z_u = J_uu^{-1} (r_u - J_uT z_T). The
/// preconditioner applies this with a MueLu hierarchy for each diagonal block (one
/// unknown per node for T, three with the six rigid-body modes for u) in place of the
/// inverses, one V-cycle each. Each block's hierarchy works on a quarter or three quarters of the
/// unknowns and a twelfth or seven tenths of the entries of J. Entries of J_Tu (a gap conductance
/// that reads the displacement) are left out: the outer Krylov solver then corrects for them. A new
/// preconditioner builds anew only the hierarchy of a block whose values changed since it was
/// built: the displacement block does not depend on the time step, the temperature block not on the
/// contact set.
#include "solvers/crs_preconditioner_factory.hpp"
#include "solvers/jacobian_reuse.hpp"

#include <Teuchos_ParameterList.hpp>
#include <Thyra_PreconditionerFactoryBase.hpp>
#include <Tpetra_CrsMatrix_fwd.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>

#include <memory>

namespace kiln
{
namespace internal
{
/// With temperature and displacement and at least this many unknowns, Block Triangular is
/// the default Preconditioner Type; below, MueLu on the whole system, whose single
/// hierarchy costs less there (doc/solvers.md).
constexpr long long block_triangular_from = 50000;

/// A block's MueLu list: Kiln's defaults for `equations` unknowns per node (1: temperature,
/// 3: displacement), then `common` (the MueLu list of both blocks), then `own` (the block's
/// sublist); the smoother's defaults last. The displacement block is smoothed by Chebyshev
/// unless `common` or `own` gives a "smoother: type" or "smoother: params" in the input
/// (an entry not marked as a default).
Teuchos::ParameterList block_muelu_list(const Teuchos::ParameterList &common,
                                        const Teuchos::ParameterList &own, int equations);

class BlockSplit;

class BlockTriangularPreconditionerFactory final : public CrsPreconditionerFactory,
                                                   public RefreshingPreconditionerFactory
{
public:
  using MultiVector = Tpetra::MultiVector<double>;

  /// For the blocks' hierarchies: the problem's node coordinates and near-null space
  /// (unknowns as the solver sees them: the constant temperature first, then the six
  /// rigid-body modes; either may be null), and the MueLu parameters of the Stratimikos list
  /// (Kiln's defaults and the input's), which both blocks take before their own sublists.
  void set_hints(Teuchos::RCP<const MultiVector> coordinates,
                 Teuchos::RCP<const MultiVector> near_null_space,
                 const Teuchos::ParameterList &muelu);

  void initializePrec(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> &fwdOpSrc,
                      Thyra::PreconditionerBase<double> *precOp,
                      Thyra::ESupportSolveUse supportSolveUse) const override;
  /// The blocks of a kept preconditioner take the new values of the operator.
  void refresh(const Thyra::LinearOpSourceBase<double> &fwdOpSrc) const override;
  Teuchos::RCP<const Teuchos::ParameterList> getValidParameters() const override;

  /// How many hierarchies (or diagonal inverses) of each block initializePrec() has built.
  /// A block whose values have not changed since its hierarchy was built keeps it.
  struct Builds
  {
    int temperature = 0;
    int displacement = 0;
  };
  Builds builds() const { return builds_; }

private:
  /// New parameters: both blocks are built anew.
  void parameters_changed() override { t_stale_ = u_stale_ = true; }
  /// The preconditioner of the temperature (`temperature` true) or the displacement block,
  /// built anew.
  Teuchos::RCP<Tpetra::Operator<double>> build_block(bool temperature) const;
  /// Copies J's values into the blocks and marks a block whose values changed (on any rank)
  /// for a new hierarchy. Collective.
  void note_changes(const Tpetra::CrsMatrix<double> &J) const;

  Teuchos::RCP<const MultiVector> coordinates_;
  Teuchos::RCP<const MultiVector> near_null_space_;
  Teuchos::ParameterList muelu_;
  /// The blocks of the operator last built from, kept while its graph is the same.
  mutable std::shared_ptr<BlockSplit> split_;
  mutable const void *split_graph_ = nullptr;
  /// Each block's hierarchy, and whether the block's values have changed since it was built
  /// (then the next initializePrec() builds it anew). The displacement block does not depend
  /// on the time step and the temperature block not on the contact set, so a new
  /// preconditioner usually rebuilds only one of them.
  mutable Teuchos::RCP<Tpetra::Operator<double>> t_op_, u_op_;
  mutable bool t_stale_ = true, u_stale_ = true;
  mutable Builds builds_;
};
} // namespace internal
} // namespace kiln
