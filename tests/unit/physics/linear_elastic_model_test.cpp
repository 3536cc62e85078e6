// Tests src/physics/materials/linear_elastic_model.cpp: the stress is the elasticity kernel's
// Hooke's law (hooke_stress in elasticity_kernel.cpp), the tangent and dsigma/dT agree with
// finite differences, and the model is constant and stateless.
// KILN_TEST_NP: 1
#include "physics/materials/linear_elastic_model.hpp"

#include "physics/mechanics/elasticity_kernel.hpp"
#include "support/constitutive_model_check.hpp"
#include "support/reference_cells.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
const double lambda = 5.2e10, G = 2.6e10, alpha = 2.2e-5, T_ref = 298.0;

TEST(LinearElasticModel, StressIsHookesLawWithThermalStrain)
{
  const kiln::LinearElasticModel model(lambda, G, alpha, T_ref);
  kiln::PointInput in;
  in.strain = {1e-3, -2e-4, 3e-4, 5e-4, -1e-4, 2e-4};
  in.temperature = 350.0;
  const kiln::PointResponse out = kiln_test::evaluate(model, in, {}).response;
  // The formula of hooke_stress: 2G eps + (lambda tr eps - (3 lambda + 2G) alpha dT) I.
  const double dT = in.temperature - T_ref;
  const double volumetric =
      lambda * (in.strain[0] + in.strain[1] + in.strain[2]) - (3.0 * lambda + 2.0 * G) * alpha * dT;
  for (int i = 0; i < 6; ++i)
    EXPECT_NEAR(out.stress[i], 2.0 * G * in.strain[i] + (i < 3 ? volumetric : 0.0), 1e-12 * 1e8)
        << i;
  EXPECT_DOUBLE_EQ(out.tangent[3][3], 2.0 * G);
  EXPECT_DOUBLE_EQ(out.tangent[0][0], lambda + 2.0 * G);
  EXPECT_DOUBLE_EQ(out.tangent[0][1], lambda);
  EXPECT_DOUBLE_EQ(out.tangent[0][3], 0.0);
  EXPECT_DOUBLE_EQ(out.stress_temperature_derivative[0], -(3.0 * lambda + 2.0 * G) * alpha);
  EXPECT_DOUBLE_EQ(out.stress_temperature_derivative[3], 0.0);
  EXPECT_TRUE(model.constant_linear());
  EXPECT_EQ(model.n_state(), 0);
  EXPECT_TRUE(model.state_names().empty());
}

// The same stress as the elasticity kernel's: u = eps x on the unit cube, uniform T, the
// kernel's cell average (hooke_stress at each Gauss point).
TEST(LinearElasticModel, StressIsTheElasticityKernels)
{
  const kiln::LinearElasticModel model(lambda, G, alpha, T_ref);
  const kiln::ElasticityKernel kernel(lambda, G, alpha, T_ref);
  const kiln::Voigt strain{1e-3, -2e-4, 3e-4, 5e-4, -1e-4, 2e-4};
  static constexpr int index[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
  const kiln::HexNodes x = kiln_test::unit_cube();
  std::array<kiln::Point, 8> u{};
  for (int i = 0; i < 8; ++i)
    for (int d = 0; d < 3; ++d)
      for (int k = 0; k < 3; ++k)
        u[i][d] += strain[index[d][k]] * x[i][k];
  std::array<double, 8> T;
  T.fill(350.0);
  kiln::ElementValues fe;
  kiln_test::reinit(fe, x);
  const kiln::Voigt expected = kernel.cell_averages(fe, u, T).stress;
  kiln::PointInput in;
  in.strain = strain;
  in.temperature = 350.0;
  const kiln::Voigt stress = kiln_test::evaluate(model, in, {}).response.stress;
  for (int i = 0; i < 6; ++i)
    EXPECT_NEAR(stress[i], expected[i], 1e-12 * 1e8) << i;
}

TEST(LinearElasticModel, DerivativesMatchFiniteDifferences)
{
  const kiln::LinearElasticModel model(lambda, G, alpha, T_ref);
  for (const kiln::Voigt &strain :
       {kiln::Voigt{1e-3, 0, 0, 0, 0, 0}, kiln::Voigt{0, 0, 0, 1e-3, 0, 0},
        kiln::Voigt{1e-3, -2e-4, 3e-4, 5e-4, -1e-4, 2e-4}})
    for (const double T : {200.0, 298.0, 900.0})
    {
      kiln::PointInput in;
      in.strain = strain;
      in.temperature = T;
      const auto errors = kiln_test::derivative_errors(model, in, {}, 1e-8, 1e-2);
      EXPECT_LT(errors.tangent, 1e-6) << T;
      EXPECT_GE(errors.isotropic, 0.0);   // the isotropic form is given ...
      EXPECT_LT(errors.isotropic, 1e-12); // ... and equals the tangent
      EXPECT_LT(errors.temperature, 1e-6) << T;
    }
}
} // namespace
