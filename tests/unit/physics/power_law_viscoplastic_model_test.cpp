// Tests src/physics/materials/power_law_viscoplastic_model.cpp and the radial return of
// von_mises_viscoplastic_model.cpp: the point of Truchas' viscoplastic-1d over 5 steps, the
// consistent tangent and dsigma/dT against finite differences (elastic and flowing points,
// several temperatures and strains), invariance under rotation, no flow without a deviator,
// the relaxed limit of n = 0, a local solve that fails, and the input checks.
// KILN_TEST_NP: 1
#include "physics/materials/power_law_viscoplastic_model.hpp"

#include "base/errors.hpp"
#include "physics/materials/constitutive_models.hpp"
#include "support/constitutive_model_check.hpp"
#include "support/parameter_lists.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

using testing::HasSubstr;

namespace
{
using kiln_test::point;

Teuchos::ParameterList power_law(const double A, const double n, const double Q = 0.0,
                                 const double R = 8.314462618, const double Tref = 0.0)
{
  Teuchos::ParameterList p;
  p.set("Type", "Power Law");
  p.set("Lame Lambda", 2e9);
  p.set("Shear Modulus", 1e9);
  p.set("Thermal Expansion", 1e-5);
  p.set("Reference Temperature", 100.0);
  p.set("Power Law A", A);
  p.set("Power Law n", n);
  p.set("Power Law Q", Q);
  p.set("Power Law R", R);
  p.set("Power Law Tref", Tref);
  return p;
}

std::unique_ptr<kiln::ConstitutiveModel> make(const Teuchos::ParameterList &p)
{
  return kiln::create_constitutive_model(p, "test.xml", "Kiln/Model");
}

std::string error_of(const Teuchos::ParameterList &p)
{
  return kiln_test::input_error_message([&] { make(p); });
}

const kiln::Voigt uniaxial{2e-3, 0, 0, 0, 0, 0};
const kiln::Voigt shear{0, 0, 0, 1.5e-3, 0, 0};
const kiln::Voigt general{1.5e-3, -4e-4, 3e-4, 6e-4, -2e-4, 4e-4};

// Truchas' viscoplastic-1d: strain 1e-3 along a rotated x, lambda = 2e9, mu = 1e9, A = 1e-12,
// n = 0.5, Q = 0, R = 1, T = T_ref = 100: sigma = (4e6, 2e6, 2e6) in the rotated frame, von
// Mises 2e6, plastic strain rate sqrt(2)e-9 along x (and -half across), plastic strain
// t times it; 5 steps of 0.1 s (test.py, with its tolerances tightened).
TEST(PowerLawViscoplasticModel, ReproducesTruchasViscoplastic1d)
{
  const auto model = make(power_law(1e-12, 0.5, 0.0, 1.0));
  const auto R = kiln_test::rotation({0.0, 0.6, 0.8}, 0.7);
  const auto R_back = kiln_test::rotation({0.0, 0.6, 0.8}, -0.7);
  const kiln::PointInput in = point(kiln_test::rotate(R, {1e-3, 0, 0, 0, 0, 0}), 100.0, 0.1);
  std::vector<double> state(model->n_state());
  model->initial_state(state.data());
  const double rate = std::sqrt(2.0) * 1e-9;
  for (int step = 1; step <= 5; ++step)
  {
    const kiln_test::Evaluation e = kiln_test::evaluate(*model, in, state);
    state = e.state;
    const kiln::Voigt stress = kiln_test::rotate(R_back, e.response.stress);
    const kiln::Voigt expected_stress{4e6, 2e6, 2e6, 0, 0, 0};
    for (int i = 0; i < 6; ++i)
      EXPECT_NEAR(stress[i], expected_stress[i], 1e-5 * 4e6) << "step " << step << " " << i;
    EXPECT_NEAR(kiln_test::von_mises_of(e.response.stress), 2e6, 1e-5 * 2e6);
    EXPECT_NEAR(model->plastic_strain_rate(state.data()), rate, 1e-6 * rate);
    const double t = 0.1 * step;
    EXPECT_NEAR(model->equivalent_plastic_strain(state.data()), t * rate, 1e-6 * t * rate);
    const kiln::Voigt plastic =
        kiln_test::rotate(R_back, {state[0], state[1], state[2], state[3], state[4], state[5]});
    const kiln::Voigt expected_plastic{t * rate, -t * rate / 2, -t * rate / 2, 0, 0, 0};
    for (int i = 0; i < 6; ++i)
      EXPECT_NEAR(plastic[i], expected_plastic[i], 1e-6 * t * rate) << "step " << step << " " << i;
  }
}

// Relaxation at a fixed shear strain with n = 1: the von Mises stress obeys q' = -3G A q, so
// q = q0 exp(-3G A t); backward Euler gives q_k = q0 / (1 + 3G A dt)^k exactly, first order in
// dt. The state carries the plastic strain from step to step.
TEST(PowerLawViscoplasticModel, RelaxationIsBackwardEuler)
{
  const double G = 1e9, A = 1e-10; // 3 G A = 0.3 /s
  const auto model = make(power_law(A, 1.0));
  const kiln::PointInput at_rest = point(shear, 100.0, 0.0);
  const double q0 = kiln_test::von_mises_of(
      kiln_test::evaluate(*model, at_rest, std::vector<double>(8)).response.stress);
  double previous_error = 0.0;
  for (const int n_steps : {10, 20, 40})
  {
    const double dt = 2.0 / n_steps;
    std::vector<double> state(8, 0.0);
    double q = 0.0;
    for (int k = 1; k <= n_steps; ++k)
    {
      const kiln_test::Evaluation e = kiln_test::evaluate(*model, point(shear, 100.0, dt), state);
      state = e.state;
      q = kiln_test::von_mises_of(e.response.stress);
      EXPECT_NEAR(q, q0 / std::pow(1.0 + 3.0 * G * A * dt, k), 1e-10 * q0) << k;
    }
    // The plastic strain is what the stress lost: 2G eps_p,xy = sigma_xy(0) - sigma_xy(t).
    EXPECT_NEAR(state[3], (q0 - q) / (std::sqrt(3.0) * 2.0 * G), 1e-10 * state[3]);
    const double error = std::abs(q - q0 * std::exp(-3.0 * G * A * 2.0));
    if (previous_error > 0.0)
    {
      EXPECT_NEAR(previous_error / error, 2.0, 0.1) << n_steps; // first order
    }
    previous_error = error;
  }
}

TEST(PowerLawViscoplasticModel, TangentsMatchFiniteDifferences)
{
  // n = 3 with an Arrhenius factor: at T = 600 K the rate at 2 MPa is about 1e-4 /s, so a 1 s
  // step relaxes a good part of the deviator; alpha = 0 in one case isolates dg/dT.
  const double Q = 1e5, R = 8.314462618;
  const double A = 1e-4 / std::pow(2e6, 3) / std::exp(-Q / (R * 600.0));
  for (const double alpha : {1e-5, 0.0})
  {
    Teuchos::ParameterList p = power_law(A, 3.0, Q, R);
    p.set("Thermal Expansion", alpha);
    const auto model = make(p);
    const std::vector<double> old_state{1e-4, -5e-5, -5e-5, 2e-5, 0, -1e-5, 1.3e-4, 0};
    for (const kiln::Voigt &strain : {uniaxial, shear, general})
      for (const double T : {500.0, 600.0, 700.0})
        for (const double dt : {0.0, 1.0})
        {
          const kiln::PointInput in = point(strain, T, dt);
          const auto errors = kiln_test::derivative_errors(*model, in, old_state, 1e-9, 1e-3);
          EXPECT_LT(errors.tangent, 1e-6) << "T " << T << " dt " << dt << " alpha " << alpha;
          EXPECT_GE(errors.isotropic, 0.0);   // the isotropic form is given ...
          EXPECT_LT(errors.isotropic, 1e-12); // ... and equals the tangent
          EXPECT_LT(errors.temperature, 1e-6) << "T " << T << " dt " << dt << " alpha " << alpha;
          if (dt > 0.0)
          {
            EXPECT_GT(
                model->plastic_strain_rate(kiln_test::evaluate(*model, in, old_state).state.data()),
                1e-7);
          }
        }
  }
}

TEST(PowerLawViscoplasticModel, FlowingPointsWithSmallExponentMatchFiniteDifferences)
{
  const auto model = make(power_law(1e-8, 0.5));
  for (const kiln::Voigt &strain : {uniaxial, shear, general})
  {
    const kiln::PointInput in = point(strain, 300.0, 2.0);
    const auto errors =
        kiln_test::derivative_errors(*model, in, std::vector<double>(8, 0.0), 1e-9, 1e-3);
    EXPECT_LT(errors.tangent, 1e-6);
    EXPECT_GE(errors.isotropic, 0.0);   // the isotropic form is given ...
    EXPECT_LT(errors.isotropic, 1e-12); // ... and equals the tangent
    EXPECT_LT(errors.temperature, 1e-6);
  }
}

// A residual evaluation (PointInput::derivatives false: no tangent) gives the same stress and
// state as a full one, at flowing and elastic points.
TEST(PowerLawViscoplasticModel, EvaluationWithoutDerivativesGivesTheSameStressAndState)
{
  const auto model = make(power_law(1e-8, 0.5));
  const std::vector<double> old_state{1e-4, -5e-5, -5e-5, 2e-5, 0, -1e-5, 1.3e-4, 0};
  for (const kiln::Voigt &strain : {uniaxial, shear, general})
    for (const double dt : {0.0, 2.0})
    {
      kiln::PointInput in = point(strain, 300.0, dt);
      const kiln_test::Evaluation full = kiln_test::evaluate(*model, in, old_state);
      in.derivatives = false;
      const kiln_test::Evaluation residual = kiln_test::evaluate(*model, in, old_state);
      EXPECT_EQ(full.response.stress, residual.response.stress) << dt;
      EXPECT_EQ(full.state, residual.state) << dt;
      if (dt > 0.0)
      {
        EXPECT_GT(full.state[7], 0.0);
      }
    }
}

// The local solve may start from what new_state holds on entry (the point's last evaluation):
// the response is the same to the local tolerance from an exact, a near, a far or a nonsense
// start, at flowing and relaxing points, with and without derivatives.
TEST(PowerLawViscoplasticModel, ResponseDoesNotDependOnTheStart)
{
  const std::vector<double> old_state{1e-4, -5e-5, -5e-5, 2e-5, 0, -1e-5, 1.3e-4, 0};
  for (const double n : {0.5, 3.0, 0.0})
  {
    const auto model = make(power_law(n == 3.0 ? 1e-20 : 1e-8, n));
    for (const kiln::Voigt &strain : {uniaxial, shear, general})
      for (const bool derivatives : {true, false})
      {
        kiln::PointInput in = point(strain, 300.0, 2.0);
        in.derivatives = derivatives;
        const kiln_test::Evaluation cold = kiln_test::evaluate(*model, in, old_state);
        const double rate = cold.state[7];
        std::vector<std::vector<double>> starts;
        for (const double r :
             {rate, rate * (1.0 + 1e-9), rate * 1.1, rate * 0.9, rate * 1e-8, rate * 1e8, -rate,
              std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
        {
          std::vector<double> start = cold.state;
          start[7] = r;
          starts.push_back(start);
        }
        starts.push_back(std::vector<double>(8, 1e30));
        EXPECT_LT(kiln_test::start_dependence(*model, in, old_state, starts), 1e-11)
            << "n " << n << " derivatives " << derivatives;
        if (n > 0.0)
        {
          EXPECT_GT(rate, 0.0);
        }
      }
  }
}

// The local solve reads the law's logarithm (log_flow_rate_at, one log instead of a power): it is
// ln g, g'/g and (dg/dT)/g of flow_rate_at, and -inf where g = 0 (A = 0, or q = 0 with n > 0).
TEST(PowerLawViscoplasticModel, LogFormIsTheLogarithmOfTheRate)
{
  for (const double A : {0.0, 1e-8})
    for (const double n : {0.0, 0.5, 3.0})
      for (const double Q : {0.0, 1e5})
      {
        const auto model = make(power_law(A * (n == 3.0 ? 1e-12 : 1.0), n, Q));
        const auto &law = dynamic_cast<const kiln::VonMisesViscoplasticModel &>(*model);
        const auto factors = law.temperature_factors(600.0);
        for (const double q : {0.0, 1e5, 2e6})
        {
          const auto g = law.flow_rate(q, 600.0);
          const auto log_g = law.log_flow_rate_at(q, factors);
          std::ostringstream where;
          where << "A " << A << " n " << n << " Q " << Q << " q " << q;
          if (g.value == 0.0)
          {
            EXPECT_EQ(log_g.value, -std::numeric_limits<double>::infinity()) << where.str();
            continue;
          }
          EXPECT_NEAR(log_g.value, std::log(g.value), 1e-14 * std::abs(std::log(g.value)))
              << where.str();
          EXPECT_NEAR(log_g.d_stress, g.d_stress / g.value, 1e-14 * std::abs(g.d_stress / g.value))
              << where.str();
          EXPECT_NEAR(log_g.d_temperature, g.d_temperature / g.value,
                      1e-14 * std::abs(g.d_temperature / g.value))
              << where.str();
        }
      }
}

TEST(PowerLawViscoplasticModel, InvariantUnderRotation)
{
  const auto model = make(power_law(1e-20, 3.0));
  const auto R = kiln_test::rotation({0.48, 0.6, 0.64}, 1.1);
  const std::vector<double> old_state{1e-4, -5e-5, -5e-5, 2e-5, 0, -1e-5, 1.3e-4, 0};
  const kiln::Voigt old_plastic{old_state[0], old_state[1], old_state[2],
                                old_state[3], old_state[4], old_state[5]};
  const kiln::Voigt rotated_plastic = kiln_test::rotate(R, old_plastic);
  std::vector<double> rotated_state(rotated_plastic.begin(), rotated_plastic.end());
  rotated_state.push_back(old_state[6]);
  rotated_state.push_back(old_state[7]);

  const kiln_test::Evaluation e =
      kiln_test::evaluate(*model, point(general, 400.0, 1.0), old_state);
  const kiln_test::Evaluation r =
      kiln_test::evaluate(*model, point(kiln_test::rotate(R, general), 400.0, 1.0), rotated_state);
  const kiln::Voigt expected_stress = kiln_test::rotate(R, e.response.stress);
  const kiln::Voigt expected_plastic = kiln_test::rotate(
      R, {e.state[0], e.state[1], e.state[2], e.state[3], e.state[4], e.state[5]});
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_NEAR(r.response.stress[i], expected_stress[i], 1e-9 * 1e7) << i;
    EXPECT_NEAR(r.state[i], expected_plastic[i], 1e-9 * 1e-4) << i;
  }
  EXPECT_NEAR(r.state[6], e.state[6], 1e-12 * e.state[6]);
  EXPECT_GT(e.state[7], 1e-6); // it flows
  EXPECT_NEAR(r.state[7], e.state[7], 1e-9 * e.state[7]);
}

TEST(PowerLawViscoplasticModel, NoFlowWithoutDeviatoricStress)
{
  const auto model = make(power_law(1e-3, 1.0));
  // A hydrostatic strain and a thermal strain: no deviator.
  const kiln::PointInput in = point({1e-3, 1e-3, 1e-3, 0, 0, 0}, 500.0, 10.0);
  const kiln_test::Evaluation e = kiln_test::evaluate(*model, in, std::vector<double>(8, 0.0));
  for (int i = 0; i < 8; ++i)
    EXPECT_EQ(e.state[i], 0.0) << i;
  EXPECT_NEAR(e.response.stress[0], e.response.stress[1], 1e-9);
  EXPECT_EQ(e.response.tangent[3][3], 2e9);
}

// n = 0 (allowed by Truchas): the rate A does not vanish with the stress; when A dt exceeds
// what the deviator can give, it relaxes to zero, and the tangent is the bulk part alone.
TEST(PowerLawViscoplasticModel, ZeroExponentRelaxesTheDeviator)
{
  const auto model = make(power_law(1.0, 0.0));
  const kiln::PointInput in = point(general, 300.0, 1.0);
  const kiln_test::Evaluation e = kiln_test::evaluate(*model, in, std::vector<double>(8, 0.0));
  EXPECT_NEAR(kiln_test::von_mises_of(e.response.stress), 0.0, 1e-6);
  const double K = 2e9 + 2e9 / 3.0;
  EXPECT_NEAR(e.response.tangent[0][1], K, 1e-6 * K);
  EXPECT_NEAR(e.response.tangent[3][3], 0.0, 1e-6 * K);
  const auto errors =
      kiln_test::derivative_errors(*model, in, std::vector<double>(8, 0.0), 1e-9, 1e-3);
  EXPECT_LT(errors.tangent, 1e-6);
  EXPECT_GE(errors.isotropic, 0.0);   // the isotropic form is given ...
  EXPECT_LT(errors.isotropic, 1e-12); // ... and equals the tangent
  EXPECT_LT(errors.temperature, 1e-6);
}

TEST(PowerLawViscoplasticModel, LocalSolveThatDoesNotConvergeIsAStepFailure)
{
  Teuchos::ParameterList p = power_law(1e-10, 3.0);
  p.set("Local Iterations", 1);
  const auto model = make(p);
  try
  {
    kiln_test::evaluate(*model, point(general, 300.0, 1.0), std::vector<double>(8, 0.0));
    FAIL() << "no StepFailure";
  }
  catch (const kiln::StepFailure &e)
  {
    EXPECT_THAT(e.what(), HasSubstr("\"Power Law\" viscoplastic model at a quadrature point "
                                    "with T = 300 K"));
    EXPECT_THAT(e.what(), HasSubstr("did not converge in 1 iterations"));
    EXPECT_THAT(e.what(), HasSubstr("a smaller time step or a looser \"Local Tolerance\" may "
                                    "help; the step is cut"));
  }
}

TEST(PowerLawViscoplasticModel, TemperatureAtOrBelowTrefIsAStepFailure)
{
  const auto model = make(power_law(1e-20, 3.0, 1e5, 8.314, 250.0));
  try
  {
    kiln_test::evaluate(*model, point(general, 250.0, 1.0), std::vector<double>(8));
    FAIL() << "no StepFailure";
  }
  catch (const kiln::StepFailure &e)
  {
    EXPECT_THAT(e.what(), HasSubstr("with T = 250 K"));
    EXPECT_THAT(e.what(), HasSubstr("needs T > \"Power Law Tref\" = 250 K; the step is cut"));
  }
  // No flow to compute (dt = 0): no error.
  EXPECT_NO_THROW(kiln_test::evaluate(*model, point(general, 250.0, 0.0), std::vector<double>(8)));
  // A strain that is not a number (a diverging Newton iterate) fails the step too.
  auto nan_point = point(general, 300.0, 1.0);
  nan_point.strain[0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(kiln_test::evaluate(*model, nan_point, std::vector<double>(8)), kiln::StepFailure);
}

TEST(PowerLawViscoplasticModel, BadParametersAreInputErrors)
{
  EXPECT_THAT(error_of(power_law(-1.0, 1.0)),
              HasSubstr("test.xml: Kiln/Model/\"Power Law A\" = -1: must be >= 0"));
  EXPECT_THAT(error_of(power_law(1.0, -0.5)),
              HasSubstr("test.xml: Kiln/Model/\"Power Law n\" = -0.5: must be >= 0"));
  EXPECT_THAT(error_of(power_law(1.0, 1.0, 1e5, 0.0)),
              HasSubstr("test.xml: Kiln/Model/\"Power Law R\": = 0, but the \"Power Law\" "
                        "viscoplastic model divides by it"));
  Teuchos::ParameterList missing = power_law(1.0, 1.0);
  missing.remove("Power Law A");
  EXPECT_THAT(error_of(missing), HasSubstr("test.xml: Kiln/Model/\"Power Law A\": is required by "
                                           "the \"Power Law\" viscoplastic model"));
  Teuchos::ParameterList negative_K = power_law(1.0, 1.0);
  negative_K.set("Lame Lambda", -1e9);
  EXPECT_THAT(error_of(negative_K), HasSubstr("\"Lame Lambda\": = -1e+09 Pa gives the bulk "
                                              "modulus"));
  Teuchos::ParameterList tolerance = power_law(1.0, 1.0);
  tolerance.set("Local Tolerance", 0.1);
  EXPECT_THAT(error_of(tolerance), HasSubstr("\"Local Tolerance\" = 0.1: must be in"));
}
} // namespace
