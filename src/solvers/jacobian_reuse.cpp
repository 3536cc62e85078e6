#include "solvers/jacobian_reuse.hpp"

#include "base/errors.hpp"
#include "base/hash.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Thyra_DefaultPreconditioner.hpp>
#include <Thyra_LinearOpBase.hpp>

#include <algorithm>
#include <stdexcept>

namespace kiln
{
namespace internal
{
using Teuchos::RCP;

namespace
{
/// The preconditioner operator handed to the linear solver: it forwards to the operator the
/// wrapped factory built until release(). The linear solver holds the operator it was given
/// until it is given the next one, which is built after the last one; so without this the
/// two hierarchies (or factorizations) would live side by side while the new one is built.
class ReleasableOp final : public Thyra::LinearOpBase<double>
{
public:
  explicit ReleasableOp(RCP<const Thyra::LinearOpBase<double>> op)
      : op_(op.assert_not_null()), range_(op_->range()), domain_(op_->domain())
  {
  }
  void release() { op_ = Teuchos::null; }
  RCP<const Thyra::VectorSpaceBase<double>> range() const override { return range_; }
  RCP<const Thyra::VectorSpaceBase<double>> domain() const override { return domain_; }

protected:
  bool opSupportedImpl(Thyra::EOpTransp M_trans) const override
  {
    return !op_.is_null() && Thyra::opSupported(*op_, M_trans);
  }
  void applyImpl(const Thyra::EOpTransp M_trans, const Thyra::MultiVectorBase<double> &X,
                 const Teuchos::Ptr<Thyra::MultiVectorBase<double>> &Y, const double alpha,
                 const double beta) const override
  {
    if (op_.is_null())
      throw std::logic_error("kiln: a preconditioner was applied after the next one "
                             "replaced it (ReusingPreconditionerFactory)");
    Thyra::apply(*op_, M_trans, X, Y, alpha, beta);
  }

private:
  RCP<const Thyra::LinearOpBase<double>> op_;
  RCP<const Thyra::VectorSpaceBase<double>> range_, domain_;
};

Thyra::DefaultPreconditioner<double> &default_preconditioner(Thyra::PreconditionerBase<double> &p)
{
  auto *d = dynamic_cast<Thyra::DefaultPreconditioner<double> *>(&p);
  if (d == nullptr)
    throw std::logic_error("kiln: ReusingPreconditionerFactory needs a factory whose "
                           "preconditioners are Thyra::DefaultPreconditioner");
  return *d;
}
} // namespace

bool JacobianReuse::can_keep(NonlinearProblem &problem, const NonlinearProblem::Vector &x,
                             const NonlinearProblem::Matrix &J)
{
  // Reuse off: false on every rank alike; the dependencies and their reduction only serve
  // varying(), if it is asked.
  if (!enabled_ && !track_varying_)
  {
    pending_.clear();
    return false;
  }
  pending_ = problem.jacobian_dependencies(x);
  // Whether the Jacobian varies, alike on every rank (a rank without dependencies counts).
  int constant_here = pending_.empty() ? 0 : 1;
  int constant = 0;
  Teuchos::reduceAll(*J.getComm(), Teuchos::REDUCE_MIN, constant_here, Teuchos::outArg(constant));
  varying_ = constant == 0;
  if (!enabled_)
  {
    pending_.clear();
    return false;
  }
  pending_preconditioner_.clear();
  if (within_solve_ && pending_.empty())
    pending_preconditioner_ = problem.preconditioner_dependencies(x);
  // A varying Jacobian is not kept: false on every rank (some rank has no dependencies).
  const int same_here = !pending_.empty() && &J == matrix_ && pending_ == dependencies_ ? 1 : 0;
  int same = 0;
  if (!varying_)
    Teuchos::reduceAll(*J.getComm(), Teuchos::REDUCE_MIN, same_here, Teuchos::outArg(same));
  if (same == 1)
    ++counts_.jacobians_kept;
  return same == 1;
}

void JacobianReuse::evaluated(const NonlinearProblem::Matrix &J, const std::size_t smooth)
{
  const bool same_matrix = &J == matrix_;
  matrix_ = &J;
  dependencies_ = std::move(pending_);
  pending_.clear();
  smooth_ = smooth;
  ++counts_.jacobians_evaluated;
  const bool begun = solve_begun_;
  solve_begun_ = false;
  const double last_norm = jacobian_residual_norm_;
  jacobian_residual_norm_ = residual_norm_;
  if (!restored_.empty() && restore(J, smooth))
    return;
  if (enabled_ && tolerance_ > 0.0 && same_matrix)
  {
    const int serves_here = serves(version_dependencies_, dependencies_, smooth) ? 1 : 0;
    int served = 0;
    Teuchos::reduceAll(*J.getComm(), Teuchos::REDUCE_MIN, serves_here, Teuchos::outArg(served));
    if (served == 1)
      return;
  }
  // Every condition but the dependencies' is the same on every rank; those are reduced.
  if (enabled_ && within_solve_ && same_matrix && !begun && serves_within_solve(J, last_norm))
    return;
  // The first Jacobian of a solve, with the preconditioner of the solve before (not stale).
  if (enabled_ && within_solve_ && across_steps_ && same_matrix && begun && !stale_ &&
      serves_within_solve(J, last_norm, /*first_of_solve=*/true))
    return;
  solve_began_version_ = true;
  version_dependencies_ = dependencies_;
  version_preconditioner_ = std::move(pending_preconditioner_);
  pending_preconditioner_.clear();
  version_failed_solves_ = failed_solves_ ? failed_solves_() : 0;
  ++version_;
}

void JacobianReuse::end_solve(const bool converged, const int newton_iterations,
                              const int linear_iterations)
{
  if (!across_steps_)
    return;
  if (!converged)
  {
    stale_ = true;
    return;
  }
  if (newton_iterations <= 0)
    return;
  const double per_iteration = static_cast<double>(linear_iterations) / newton_iterations;
  if (solve_began_version_)
  {
    fresh_krylov_ = per_iteration;
    stale_ = false;
  }
  else if (per_iteration > staleness_ * std::max(fresh_krylov_, 1.0))
    stale_ = true;
}

bool JacobianReuse::serves_within_solve(const NonlinearProblem::Matrix &J, const double last_norm,
                                        const bool first_of_solve) const
{
  // The failure count and the norms are the same on every rank (global quantities).
  if (failed_solves_ && failed_solves_() != version_failed_solves_)
    return false;
  // Newton far from its quadratic regime (||F|| not halved): the tangent moves too much for
  // an older preconditioner.
  if (!first_of_solve && !(residual_norm_ <= 0.5 * last_norm))
    return false;
  // A Jacobian that varies (no dependencies of its own) whose preconditioner dependencies
  // are those of the version's first; with the preconditioner kept across steps, the smooth
  // ones (a) within the Preconditioner Reuse Tolerance of them (a solve does not change them).
  const bool same = across_steps_
                        ? serves(version_preconditioner_, pending_preconditioner_, smooth_)
                        : pending_preconditioner_ == version_preconditioner_;
  const int here = dependencies_.empty() && !pending_preconditioner_.empty() && same ? 1 : 0;
  int everywhere = 0;
  Teuchos::reduceAll(*J.getComm(), Teuchos::REDUCE_MIN, here, Teuchos::outArg(everywhere));
  return everywhere == 1;
}

namespace
{
/// FNV-1a of d[from..], in 52 bits (a double holds it exactly).
double hash_from(const std::vector<double> &d, const std::size_t from)
{
  const std::size_t n = d.size() > from ? d.size() - from : 0;
  return static_cast<double>(fnv1a(d.data() + from, n) & ((std::uint64_t{1} << 52) - 1));
}
} // namespace

// The record: k, the k smooth dependencies of the version's start, the k of the build, then
// the hash of the other dependencies (the same for both: a version keeps them).
std::vector<double> JacobianReuse::origin() const
{
  if (!enabled_ || tolerance_ <= 0.0 || built_version_ != version_ || version_ == 0 ||
      smooth_ == 0 || built_.size() < smooth_ || version_dependencies_.size() != built_.size())
    return {};
  std::vector<double> record{static_cast<double>(smooth_)};
  record.insert(record.end(), version_dependencies_.begin(),
                version_dependencies_.begin() + static_cast<std::ptrdiff_t>(smooth_));
  record.insert(record.end(), built_.begin(),
                built_.begin() + static_cast<std::ptrdiff_t>(smooth_));
  record.push_back(hash_from(built_, smooth_));
  return record;
}

bool JacobianReuse::restore(const NonlinearProblem::Matrix &J, const std::size_t smooth)
{
  const std::vector<double> record = std::move(restored_);
  restored_.clear();
  std::vector<double> version, built;
  int here = 0;
  if (enabled_ && tolerance_ > 0.0 && smooth > 0 && record.size() == 2 * smooth + 2 &&
      record[0] == static_cast<double>(smooth) && dependencies_.size() >= smooth &&
      record.back() == hash_from(dependencies_, smooth))
  {
    const auto at = [&](const std::size_t i)
    { return record.begin() + static_cast<std::ptrdiff_t>(i); };
    const auto rest = dependencies_.begin() + static_cast<std::ptrdiff_t>(smooth);
    version.assign(at(1), at(1 + smooth));
    version.insert(version.end(), rest, dependencies_.end());
    built.assign(at(1 + smooth), at(1 + 2 * smooth));
    built.insert(built.end(), rest, dependencies_.end());
    here = serves(version, dependencies_, smooth) ? 1 : 0;
  }
  int everywhere = 0;
  Teuchos::reduceAll(*J.getComm(), Teuchos::REDUCE_MIN, here, Teuchos::outArg(everywhere));
  if (everywhere == 0)
    return false;
  version_dependencies_ = std::move(version);
  ++version_;
  // Built where the dependencies already are: from J as it is.
  build_at_ =
      built == dependencies_
          ? std::vector<double>{}
          : std::vector<double>(built.begin(), built.begin() + static_cast<std::ptrdiff_t>(smooth));
  built_ = std::move(built);
  return true;
}

void JacobianReuse::build(const std::function<void()> &build)
{
  const std::vector<double> at = std::move(build_at_);
  build_at_.clear();
  if (!at.empty() && jacobian_with_ && jacobian_with_(at))
  {
    build();
    const std::vector<double> now(dependencies_.begin(),
                                  dependencies_.begin() + static_cast<std::ptrdiff_t>(smooth_));
    const bool again = jacobian_with_(now);
    KILN_ASSERT(again, "the Jacobian could not be evaluated again");
    (void)again;
    // built_ was set by restore().
  }
  else
  {
    build();
    built_ = dependencies_;
  }
  built_version_ = version_;
}

bool JacobianReuse::serves(const std::vector<double> &built, const std::vector<double> &now,
                           const std::size_t smooth) const
{
  if (built.empty() || built.size() != now.size() || smooth > now.size())
    return false;
  // Each coefficient within a factor 1 + tolerance of its value at the build, either way.
  for (std::size_t i = 0; i < smooth; ++i)
    if (now[i] != built[i] && !(now[i] * built[i] > 0.0 &&
                                std::max(now[i] / built[i], built[i] / now[i]) <= 1.0 + tolerance_))
      return false;
  return std::equal(built.begin() + smooth, built.end(), now.begin() + smooth);
}

ReusingPreconditionerFactory::ReusingPreconditionerFactory(
    RCP<Thyra::PreconditionerFactoryBase<double>> factory, RCP<JacobianReuse> reuse)
    : factory_(factory.assert_not_null()), reuse_(reuse.assert_not_null())
{
}

bool ReusingPreconditionerFactory::isCompatible(
    const Thyra::LinearOpSourceBase<double> &fwdOpSrc) const
{
  return factory_->isCompatible(fwdOpSrc);
}

RCP<Thyra::PreconditionerBase<double>> ReusingPreconditionerFactory::createPrec() const
{
  return factory_->createPrec();
}

void ReusingPreconditionerFactory::initializePrec(
    const RCP<const Thyra::LinearOpSourceBase<double>> &fwdOpSrc,
    Thyra::PreconditionerBase<double> *precOp, const Thyra::ESupportSolveUse supportSolveUse) const
{
  const Thyra::LinearOpBase<double> *op = fwdOpSrc->getOp().get();
  const int evaluated = reuse_->counts().jacobians_evaluated;
  if (reuse_->enabled() && precOp == built_.prec && op == built_.op &&
      reuse_->version() == built_.version)
  {
    ++reuse_->counts().preconditioners_kept;
    const auto *refreshing = dynamic_cast<const RefreshingPreconditionerFactory *>(factory_.get());
    if (refreshing != nullptr && evaluated != built_.evaluated)
      refreshing->refresh(*fwdOpSrc);
    built_.evaluated = evaluated;
    return;
  }
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Kiln: 7 preconditioner set-up"));
  // The last preconditioner goes before the new one is built (ReleasableOp).
  Thyra::DefaultPreconditioner<double> &prec = default_preconditioner(*precOp);
  built_ = {};
  if (!Teuchos::rcp_dynamic_cast<const ReleasableOp>(prec.getUnspecifiedPrecOp()).is_null())
    Teuchos::rcp_dynamic_cast<ReleasableOp>(prec.getNonconstUnspecifiedPrecOp(), true)->release();
  prec.uninitialize();
  reuse_->build([&] { factory_->initializePrec(fwdOpSrc, precOp, supportSolveUse); });
  const RCP<Thyra::LinearOpBase<double>> built =
      Teuchos::rcp(new ReleasableOp(prec.getUnspecifiedPrecOp()));
  prec.initializeUnspecified(built);
  // After a restore (JacobianReuse::build) the operator holds other values than those built
  // from, and a hierarchy's finest level reads the operator's: so do the copies.
  if (const auto *refreshing =
          dynamic_cast<const RefreshingPreconditionerFactory *>(factory_.get()))
    refreshing->refresh(*fwdOpSrc);
  built_ = {precOp, op, reuse_->version(), evaluated};
  ++reuse_->counts().preconditioners_built;
}

void ReusingPreconditionerFactory::uninitializePrec(
    Thyra::PreconditionerBase<double> *prec, RCP<const Thyra::LinearOpSourceBase<double>> *fwdOpSrc,
    Thyra::ESupportSolveUse *supportSolveUse) const
{
  if (prec == built_.prec)
    built_ = {};
  factory_->uninitializePrec(prec, fwdOpSrc, supportSolveUse);
}

void ReusingPreconditionerFactory::setParameterList(const RCP<Teuchos::ParameterList> &paramList)
{
  factory_->setParameterList(paramList);
}
RCP<Teuchos::ParameterList> ReusingPreconditionerFactory::getNonconstParameterList()
{
  return factory_->getNonconstParameterList();
}
RCP<Teuchos::ParameterList> ReusingPreconditionerFactory::unsetParameterList()
{
  return factory_->unsetParameterList();
}
RCP<const Teuchos::ParameterList> ReusingPreconditionerFactory::getParameterList() const
{
  return factory_->getParameterList();
}
RCP<const Teuchos::ParameterList> ReusingPreconditionerFactory::getValidParameters() const
{
  return factory_->getValidParameters();
}
} // namespace internal
} // namespace kiln
