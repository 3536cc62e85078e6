#pragma once
/// Checks of a ConstitutiveModel at one point: its tangent and ∂σ/∂T against central finite
/// differences of evaluate(), and Voigt vectors rotated to another frame.
#include "physics/materials/constitutive_model.hpp"

#include <array>
#include <vector>

namespace kiln_test
{
/// The relative errors of the analytic derivatives: max |FD − analytic| / max |analytic| over
/// the entries of the tangent, and likewise over ∂σ/∂T (absolute errors where they are 0).
struct DerivativeErrors
{
  double tangent = 0.0;
  double temperature = 0.0;
  /// max |tangent of the isotropic form − tangent| / max |tangent| (PointResponse::isotropic);
  /// −1 when the model gives no isotropic form.
  double isotropic = -1.0;
};

/// Central differences of evaluate() at `in` from `old_state` (n_state() entries), with
/// steps `strain_step` on each strain component and `temperature_step` on T.
DerivativeErrors derivative_errors(const kiln::ConstitutiveModel &model, const kiln::PointInput &in,
                                   const std::vector<double> &old_state, double strain_step,
                                   double temperature_step);

/// A point at strain, temperature T (now and at the last step) and time step dt.
kiln::PointInput point(const kiln::Voigt &strain, double T, double dt);

/// The response and new state of one evaluation.
struct Evaluation
{
  kiln::PointResponse response;
  std::vector<double> state;
};
Evaluation evaluate(const kiln::ConstitutiveModel &model, const kiln::PointInput &in,
                    const std::vector<double> &old_state);
/// The same with `new_state` holding `start` on entry (a last evaluation's state, which a model
/// may start its local iteration from).
Evaluation evaluate(const kiln::ConstitutiveModel &model, const kiln::PointInput &in,
                    const std::vector<double> &old_state, const std::vector<double> &start);

/// How much the response at `in` depends on what `new_state` holds on entry: the largest
/// relative difference, over the stress, the new state and (with derivatives) the isotropic
/// form and ∂σ/∂T, between an evaluation from zeros and evaluations from `starts` (each
/// n_state() entries: the state of a last evaluation, exact, perturbed or nonsense).
double start_dependence(const kiln::ConstitutiveModel &model, const kiln::PointInput &in,
                        const std::vector<double> &old_state,
                        const std::vector<std::vector<double>> &starts);

/// R a R^T for the symmetric tensor a in Voigt form (tensor shears), R a rotation.
kiln::Voigt rotate(const std::array<std::array<double, 3>, 3> &R, const kiln::Voigt &a);
/// A rotation by `angle` [rad] about the unit `axis`.
std::array<std::array<double, 3>, 3> rotation(const std::array<double, 3> &axis, double angle);
/// sqrt(3/2 s:s), s the deviator of a (Voigt, tensor shears).
double von_mises_of(const kiln::Voigt &a);
} // namespace kiln_test
