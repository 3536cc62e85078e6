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
  return evaluate(model, in, old_state, std::vector<double>(old_state.size(), 0.0));
}

Evaluation evaluate(const kiln::ConstitutiveModel &model, const kiln::PointInput &in,
                    const std::vector<double> &old_state, const std::vector<double> &start)
{
  Evaluation e;
  e.state = start;
  model.evaluate(in, old_state.data(), e.state.data(), e.response);
  return e;
}

namespace
{
/// max |a − b| / max(max |b|, floor) over the entries.
template <class Array>
double relative_difference(const Array &a, const Array &b, const double floor = 1e-300)
{
  double difference = 0.0, scale = floor;
  for (std::size_t i = 0; i < b.size(); ++i)
  {
    difference = std::max(difference, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(b[i]));
  }
  return difference / scale;
}
} // namespace

double start_dependence(const kiln::ConstitutiveModel &model, const kiln::PointInput &in,
                        const std::vector<double> &old_state,
                        const std::vector<std::vector<double>> &starts)
{
  const Evaluation cold = evaluate(model, in, old_state);
  double worst = 0.0;
  for (const std::vector<double> &start : starts)
  {
    const Evaluation warm = evaluate(model, in, old_state, start);
    worst = std::max(worst, relative_difference(warm.response.stress, cold.response.stress));
    worst = std::max(worst, relative_difference(warm.state, cold.state));
    if (!in.derivatives)
      continue;
    const kiln::IsotropicTangent &w = warm.response.isotropic, &c = cold.response.isotropic;
    const std::array<double, 3> w_moduli{w.lambda, w.shear, w.rank_one};
    const std::array<double, 3> c_moduli{c.lambda, c.shear, c.rank_one};
    worst = std::max(worst, relative_difference(w_moduli, c_moduli));
    worst = std::max(worst, relative_difference(w.n, c.n));
    worst = std::max(worst, relative_difference(warm.response.stress_temperature_derivative,
                                                cold.response.stress_temperature_derivative));
  }
  return worst;
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
    const kiln::VoigtMatrix form = analytic.isotropic.matrix();
    double form_error = 0.0;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        form_error = std::max(form_error, std::abs(form[i][j] - analytic.tangent[i][j]));
    errors.isotropic = form_error / tangent_scale;
  }
  return errors;
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
