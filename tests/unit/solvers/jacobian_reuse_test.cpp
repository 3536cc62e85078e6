// Tests src/solvers/jacobian_reuse.cpp, ReusingPreconditionerFactory: when it builds a new
// preconditioner into a preconditioner object, the operator it built there before is gone
// before the wrapped factory builds the next one, even though the linear solver still holds
// the operator it was handed (it is handed the next one only after the build): two
// hierarchies never live side by side. The handle the solver held then refuses to be applied;
// the new one applies the new operator. (JacobianReuse's keeping is tested through the
// Newton solver, tests/unit/solvers/newton_solver_test.cpp.)
// KILN_TEST_NP: 1
#include "solvers/jacobian_reuse.hpp"

#include <Thyra_DefaultIdentityLinearOp.hpp>
#include <Thyra_DefaultLinearOpSource.hpp>
#include <Thyra_DefaultPreconditioner.hpp>
#include <Thyra_DefaultScaledAdjointLinearOp.hpp>
#include <Thyra_DefaultSpmdVectorSpace.hpp>
#include <Thyra_MultiVectorStdOps.hpp>
#include <Thyra_VectorBase.hpp>
#include <Thyra_VectorStdOps.hpp>
#include <gtest/gtest.h>

#include <stdexcept>

namespace
{
using kiln::internal::JacobianReuse;
using kiln::internal::ReusingPreconditionerFactory;
using Teuchos::RCP;
using Teuchos::rcp;

/// Builds c I (c = 1, 2, 3, ...) into a DefaultPreconditioner, and records whether the
/// operator it built before was still alive when it was asked for the next.
class CountingFactory final : public Thyra::PreconditionerFactoryBase<double>
{
public:
  mutable int builds = 0;
  mutable bool last_alive_at_build = false;

  bool isCompatible(const Thyra::LinearOpSourceBase<double> &) const override { return true; }
  RCP<Thyra::PreconditionerBase<double>> createPrec() const override
  {
    return rcp(new Thyra::DefaultPreconditioner<double>);
  }
  void initializePrec(const RCP<const Thyra::LinearOpSourceBase<double>> &source,
                      Thyra::PreconditionerBase<double> *prec,
                      Thyra::ESupportSolveUse) const override
  {
    last_alive_at_build = last_.is_valid_ptr() && !last_.is_null();
    ++builds;
    const RCP<const Thyra::LinearOpBase<double>> op =
        Thyra::scale<double>(builds, Thyra::identity(source->getOp()->domain()));
    last_ = op.create_weak();
    dynamic_cast<Thyra::DefaultPreconditioner<double> &>(*prec).initializeUnspecified(op);
  }
  void uninitializePrec(Thyra::PreconditionerBase<double> *prec,
                        RCP<const Thyra::LinearOpSourceBase<double>> *,
                        Thyra::ESupportSolveUse *) const override
  {
    dynamic_cast<Thyra::DefaultPreconditioner<double> &>(*prec).uninitialize();
  }
  void setParameterList(const RCP<Teuchos::ParameterList> &) override {}
  RCP<Teuchos::ParameterList> getNonconstParameterList() override { return Teuchos::null; }
  RCP<Teuchos::ParameterList> unsetParameterList() override { return Teuchos::null; }

private:
  mutable RCP<const Thyra::LinearOpBase<double>> last_; ///< weak
};

/// The first entry of op applied to the vector of ones.
double applied(const Thyra::LinearOpBase<double> &op)
{
  const auto x = Thyra::createMember(op.domain()), y = Thyra::createMember(op.range());
  Thyra::assign(x.ptr(), 1.0);
  Thyra::apply<double>(op, Thyra::NOTRANS, *x, y.ptr());
  return Thyra::get_ele(*y, 0);
}

TEST(ReusingPreconditionerFactory, TheLastPreconditionerGoesBeforeTheNextIsBuilt)
{
  const auto inner = rcp(new CountingFactory);
  // Reuse off: every initializePrec() builds.
  ReusingPreconditionerFactory factory(inner, rcp(new JacobianReuse(false)));
  const auto space = Thyra::defaultSpmdVectorSpace<double>(4);
  const auto source = Thyra::defaultLinearOpSource<double>(Thyra::identity<double>(space));
  const auto prec = factory.createPrec();

  factory.initializePrec(source, prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  // What the linear solver holds until it is given the next preconditioner.
  const RCP<const Thyra::LinearOpBase<double>> held = prec->getUnspecifiedPrecOp();
  EXPECT_EQ(applied(*held), 1.0);

  factory.initializePrec(source, prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(inner->builds, 2);
  EXPECT_FALSE(inner->last_alive_at_build);
  EXPECT_EQ(applied(*prec->getUnspecifiedPrecOp()), 2.0);
  EXPECT_THROW(applied(*held), std::logic_error);

  // uninitializePrec() and a build into an emptied preconditioner work as before.
  factory.uninitializePrec(prec.get(), nullptr, nullptr);
  EXPECT_TRUE(prec->getUnspecifiedPrecOp().is_null());
  factory.initializePrec(source, prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_FALSE(inner->last_alive_at_build);
  EXPECT_EQ(applied(*prec->getUnspecifiedPrecOp()), 3.0);
}
} // namespace
