#include "support/constitutive_model_check.hpp"

#include <algorithm>
#include <cmath>

namespace kiln_test
{
kiln::PointInput point(const kiln::Voigt &strain, const double T, const double dt)
{
  kiln::PointInput in;
  in.strain = strain;
  in.temperature = T;
  in.temperature_old = T;
  in.time_step = dt;
  return in;
}

Evaluation evaluate(const kiln::ConstitutiveModel &model, const kiln::PointInput &in,
                    const std::vector<double> &old_state)
{
  Evaluation e;
  e.state.assign(old_state.size(), 0.0);
  model.evaluate(in, old_state.data(), e.state.data(), e.response);
  return e;
}

DerivativeErrors derivative_errors(const kiln::ConstitutiveModel &model, const kiln::PointInput &in,
                                   const std::vector<double> &old_state, const double strain_step,
                                   const double temperature_step)
{
  const kiln::PointResponse analytic = evaluate(model, in, old_state).response;
  double tangent_scale = 0.0, tangent_error = 0.0;
  for (int j = 0; j < 6; ++j)
  {
    kiln::PointInput plus = in, minus = in;
    plus.strain[j] += strain_step;
    minus.strain[j] -= strain_step;
    const kiln::Voigt sp = evaluate(model, plus, old_state).response.stress;
    const kiln::Voigt sm = evaluate(model, minus, old_state).response.stress;
    for (int i = 0; i < 6; ++i)
    {
      const double fd = (sp[i] - sm[i]) / (2.0 * strain_step);
      tangent_scale = std::max(tangent_scale, std::abs(analytic.tangent[i][j]));
      tangent_error = std::max(tangent_error, std::abs(fd - analytic.tangent[i][j]));
    }
  }
  kiln::PointInput plus = in, minus = in;
  plus.temperature += temperature_step;
  minus.temperature -= temperature_step;
  const kiln::Voigt sp = evaluate(model, plus, old_state).response.stress;
  const kiln::Voigt sm = evaluate(model, minus, old_state).response.stress;
  double temperature_scale = 0.0, temperature_error = 0.0;
  for (int i = 0; i < 6; ++i)
  {
    const double fd = (sp[i] - sm[i]) / (2.0 * temperature_step);
    temperature_scale =
        std::max(temperature_scale, std::abs(analytic.stress_temperature_derivative[i]));
    temperature_error =
        std::max(temperature_error, std::abs(fd - analytic.stress_temperature_derivative[i]));
  }
  // Relative where the derivative is nonzero (a zero dsigma/dT: alpha = 0 and no flow).
  DerivativeErrors errors{tangent_scale > 0.0 ? tangent_error / tangent_scale : tangent_error,
                          temperature_scale > 0.0 ? temperature_error / temperature_scale
                                                  : temperature_error};
  if (analytic.isotropic.valid)
  {
    const kiln::VoigtMatrix form = tangent_of(analytic.isotropic);
    double form_error = 0.0;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        form_error = std::max(form_error, std::abs(form[i][j] - analytic.tangent[i][j]));
    errors.isotropic = form_error / tangent_scale;
  }
  return errors;
}

kiln::VoigtMatrix tangent_of(const kiln::IsotropicTangent &form)
{
  kiln::VoigtMatrix C{};
  for (int I = 0; I < 6; ++I)
    for (int J = 0; J < 6; ++J)
      C[I][J] = (I < 3 && J < 3 ? form.lambda : 0.0) + (I == J ? 2.0 * form.shear : 0.0) +
                form.rank_one * form.n[I] * form.n[J] * (J < 3 ? 1.0 : 2.0);
  return C;
}

kiln::Voigt rotate(const std::array<std::array<double, 3>, 3> &R, const kiln::Voigt &a)
{
  static constexpr int index[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
  kiln::Voigt result{};
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j)
    {
      double sum = 0.0;
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          sum += R[i][k] * a[index[k][l]] * R[j][l];
      result[index[i][j]] = sum;
    }
  return result;
}

std::array<std::array<double, 3>, 3> rotation(const std::array<double, 3> &axis, const double angle)
{
  // Rodrigues: R = cos I + sin [n]x + (1 - cos) n n^T.
  const double c = std::cos(angle), s = std::sin(angle);
  const auto &n = axis;
  return {{{c + n[0] * n[0] * (1 - c), n[0] * n[1] * (1 - c) - n[2] * s,
            n[0] * n[2] * (1 - c) + n[1] * s},
           {n[1] * n[0] * (1 - c) + n[2] * s, c + n[1] * n[1] * (1 - c),
            n[1] * n[2] * (1 - c) - n[0] * s},
           {n[2] * n[0] * (1 - c) - n[1] * s, n[2] * n[1] * (1 - c) + n[0] * s,
            c + n[2] * n[2] * (1 - c)}}};
}

double von_mises_of(const kiln::Voigt &a)
{
  return std::sqrt(0.5 * ((a[0] - a[1]) * (a[0] - a[1]) + (a[1] - a[2]) * (a[1] - a[2]) +
                          (a[2] - a[0]) * (a[2] - a[0])) +
                   3.0 * (a[3] * a[3] + a[4] * a[4] + a[5] * a[5]));
}
} // namespace kiln_test
