// Tests src/physics/materials/mts_viscoplastic_model.cpp: the rate law against Truchas'
// formula in its three ranges, the consistent tangent and dsigma/dT against finite differences
// (elastic and flowing points, several temperatures and strains), invariance under rotation,
// and Truchas' parameter checks.
// KILN_TEST_NP: 1
#include "physics/materials/mts_viscoplastic_model.hpp"

#include "base/errors.hpp"
#include "physics/materials/constitutive_models.hpp"
#include "support/constitutive_model_check.hpp"
#include "support/parameter_lists.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

using testing::HasSubstr;

namespace
{
using kiln_test::point;

// The aluminium of Truchas' viscoplastic-ring (the defaults).
Teuchos::ParameterList mts()
{
  Teuchos::ParameterList p;
  p.set("Type", "MTS");
  p.set("Lame Lambda", 5.2e10);
  p.set("Shear Modulus", 2.6e10);
  p.set("Thermal Expansion", 2.2e-5);
  p.set("Reference Temperature", 298.0);
  return p;
}

std::unique_ptr<kiln::MtsViscoplasticModel> make(const Teuchos::ParameterList &user)
{
  auto model = kiln::create_constitutive_model(user, "test.xml", "Kiln/Model");
  return std::unique_ptr<kiln::MtsViscoplasticModel>(
      dynamic_cast<kiln::MtsViscoplasticModel *>(model.release()));
}

// Truchas' strain_rate_mts_st, written out.
double truchas_rate(const double q, const double T)
{
  const double mu = 28.815e9 - 3.44e9 / (std::exp(215.0 / T) - 1.0);
  const double tmp0 = mu * 107.2e6 / 28.815e9;
  const double tmp1 = mu * std::pow(2.86e-10, 3) * 3.6 / (1.38e-23 * T);
  if (q < 10e6)
    return 1e7 * std::exp(-tmp1) / std::pow(10e6, 5) * std::pow(q, 5);
  if (q > tmp0 + 10e6)
    return 1e7;
  const double x = (q - 10e6) / tmp0;
  return 1e7 * std::exp(-tmp1 * std::pow(1.0 - std::pow(x, 0.5), 1.5));
}

TEST(MtsViscoplasticModel, RateIsTruchasFormulaAndItsDerivatives)
{
  const auto model = make(mts());
  for (const double T : {400.0, 600.0})
    for (const double q : {5e6, 30e6, 60e6, 90e6, 200e6})
    {
      const auto g = model->flow_rate(q, T);
      EXPECT_NEAR(g.value, truchas_rate(q, T), 1e-12 * truchas_rate(q, T)) << q << " " << T;
      const double hq = 1e-6 * q, hT = 1e-4;
      const double dq = (truchas_rate(q + hq, T) - truchas_rate(q - hq, T)) / (2 * hq);
      const double dT = (truchas_rate(q, T + hT) - truchas_rate(q, T - hT)) / (2 * hT);
      EXPECT_NEAR(g.d_stress, dq, 1e-6 * std::abs(dq) + 1e-300) << q << " " << T;
      EXPECT_NEAR(g.d_temperature, dT, 1e-6 * std::abs(dT) + 1e-300) << q << " " << T;
    }
}

TEST(MtsViscoplasticModel, TangentsMatchFiniteDifferences)
{
  // Uniaxial strain e gives a trial von Mises stress 2 G e: 2.3e-3 gives 120 MPa, above
  // sigma_a + sigma_hat; rates of 1e-3 to 1e-1 /s near 50-65 MPa at 600 K.
  const kiln::Voigt uniaxial{2.3e-3, 0, 0, 0, 0, 0};
  const kiln::Voigt shear{0, 0, 0, 1.0e-3, 0, 0};
  const kiln::Voigt general{1.2e-3, -4e-4, 3e-4, 6e-4, -2e-4, 4e-4};
  const kiln::Voigt low{1.5e-4, 0, 0, 0, 0, 0}; // 7.8 MPa < sigma_a
  for (const double alpha : {2.2e-5, 0.0})
  {
    Teuchos::ParameterList p = mts();
    p.set("Thermal Expansion", alpha);
    const auto model = make(p);
    // Below sigma_a the rate is about exp(-200): with alpha = 0, dsigma/dT is ~1e-80 Pa/K, below
    // what differences of the stress resolve; that point is checked with alpha only.
    const std::vector<kiln::Voigt> strains =
        alpha > 0.0 ? std::vector<kiln::Voigt>{uniaxial, shear, general, low}
                    : std::vector<kiln::Voigt>{uniaxial, shear, general};
    for (std::size_t s = 0; s < strains.size(); ++s)
      for (const double T : {500.0, 600.0, 700.0})
        for (const double dt : {0.0, 1.0})
        {
          const kiln::PointInput in = point(strains[s], T, dt);
          // An earlier plastic strain (deviatoric) shifts the trial stress.
          const std::vector<double> old_state{2e-4, -1e-4, -1e-4, 5e-5, 0, -3e-5, 2.5e-4, 0};
          const auto errors = kiln_test::derivative_errors(*model, in, old_state, 1e-10, 1e-3);
          EXPECT_LT(errors.tangent, 1e-6)
              << "strain " << s << " T " << T << " dt " << dt << " alpha " << alpha;
          EXPECT_GE(errors.isotropic, 0.0);   // the isotropic form is given ...
          EXPECT_LT(errors.isotropic, 1e-12); // ... and equals the tangent
          EXPECT_LT(errors.temperature, 1e-6)
              << "strain " << s << " T " << T << " dt " << dt << " alpha " << alpha;
        }
    // The flowing points do flow.
    const auto e = kiln_test::evaluate(*model, point(uniaxial, 600.0, 1.0), std::vector<double>(8));
    EXPECT_GT(e.state[7], 1e-5);
    EXPECT_LT(kiln_test::von_mises_of(e.response.stress), 0.9 * 2.0 * 2.6e10 * 2.3e-3);
  }
}

// The local solve's start (what new_state holds on entry) does not change the response beyond
// the local tolerance, for the exponential law too (PowerLawViscoplasticModel's test).
TEST(MtsViscoplasticModel, ResponseDoesNotDependOnTheStart)
{
  const auto model = make(mts());
  const std::vector<double> old_state{2e-4, -1e-4, -1e-4, 5e-5, 0, -3e-5, 2.5e-4, 0};
  for (const kiln::Voigt &strain :
       {kiln::Voigt{2.3e-3, 0, 0, 0, 0, 0}, kiln::Voigt{1.2e-3, -4e-4, 3e-4, 6e-4, -2e-4, 4e-4}})
    for (const double T : {500.0, 600.0, 700.0})
    {
      const kiln::PointInput in = point(strain, T, 1.0);
      const kiln_test::Evaluation cold = kiln_test::evaluate(*model, in, old_state);
      const double rate = cold.state[7];
      EXPECT_GT(rate, 0.0) << T;
      std::vector<std::vector<double>> starts;
      for (const double r : {rate, rate * 1.05, rate * 0.5, rate * 1e-12, rate * 1e3, -rate,
                             std::numeric_limits<double>::quiet_NaN()})
      {
        std::vector<double> start = cold.state;
        start[7] = r;
        starts.push_back(start);
      }
      EXPECT_LT(kiln_test::start_dependence(*model, in, old_state, starts), 1e-11) << T;
    }
}

TEST(MtsViscoplasticModel, InvariantUnderRotation)
{
  const auto model = make(mts());
  const auto R = kiln_test::rotation({0.48, 0.6, 0.64}, 1.1);
  const kiln::Voigt strain{1.2e-3, -4e-4, 3e-4, 6e-4, -2e-4, 4e-4};
  const auto e = kiln_test::evaluate(*model, point(strain, 600.0, 1.0), std::vector<double>(8));
  const auto r = kiln_test::evaluate(*model, point(kiln_test::rotate(R, strain), 600.0, 1.0),
                                     std::vector<double>(8));
  const kiln::Voigt expected = kiln_test::rotate(R, e.response.stress);
  for (int i = 0; i < 6; ++i)
    EXPECT_NEAR(r.response.stress[i], expected[i], 1e-9 * 1e8) << i;
  EXPECT_GT(e.state[6], 0.0);
  EXPECT_NEAR(r.state[6], e.state[6], 1e-9 * e.state[6]);
}

TEST(MtsViscoplasticModel, TruchasParameterChecksAreInputErrors)
{
  for (const char *positive :
       {"MTS b", "MTS g_0i", "MTS k", "MTS mu_0", "MTS p_i", "MTS q_i", "MTS sig_i", "MTS temp_0"})
  {
    Teuchos::ParameterList p = mts();
    p.set(positive, 0.0);
    EXPECT_THAT(
        kiln_test::input_error_message([&] { make(p); }),
        HasSubstr("test.xml: Kiln/Model/\"" + std::string(positive) + "\" = 0: must be > 0"));
  }
  for (const char *nonnegative : {"MTS edot_0i", "MTS sig_a"})
  {
    Teuchos::ParameterList p = mts();
    p.set(nonnegative, -1.0);
    EXPECT_THAT(
        kiln_test::input_error_message([&] { make(p); }),
        HasSubstr("test.xml: Kiln/Model/\"" + std::string(nonnegative) + "\" = -1: must be >= 0"));
  }
}

// With sigma_a = 0 Truchas' law has a rate at zero stress (epsdot_0i exp(-G0)); a point
// without a deviator still does not flow (no direction).
TEST(MtsViscoplasticModel, NoFlowWithoutDeviatoricStress)
{
  Teuchos::ParameterList p = mts();
  p.set("MTS sig_a", 0.0);
  const auto model = make(p);
  EXPECT_GT(model->flow_rate(0.0, 600.0).value, 0.0);
  const auto e = kiln_test::evaluate(*model, point({1e-3, 1e-3, 1e-3, 0, 0, 0}, 600.0, 1.0),
                                     std::vector<double>(8));
  for (int i = 0; i < 8; ++i)
    EXPECT_EQ(e.state[i], 0.0) << i;
  EXPECT_EQ(e.response.tangent[3][3], 2.0 * 2.6e10);
}

TEST(MtsViscoplasticModel, NonpositiveShearModulusIsAStepFailure)
{
  Teuchos::ParameterList p = mts();
  p.set("MTS D", 1e12);
  const auto model = make(p);
  try
  {
    kiln_test::evaluate(*model, point({2e-3, 0, 0, 0, 0, 0}, 600.0, 1.0), std::vector<double>(8));
    FAIL() << "no StepFailure";
  }
  catch (const kiln::StepFailure &e)
  {
    EXPECT_THAT(e.what(), HasSubstr("\"MTS\" viscoplastic model at a quadrature point"));
    EXPECT_THAT(e.what(), HasSubstr("must be > 0 (\"MTS D\" too large"));
  }
}
} // namespace
