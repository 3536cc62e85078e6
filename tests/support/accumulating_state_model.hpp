#pragma once
/// A constitutive model with state for the tests of the state at quadrature points
/// (QuadratureState: commit, restore, checkpoints, continuation), and a problem that evaluates
/// it at every point of every owned cell during the Newton iterations, as a kernel with a
/// stateful model does.
#include "discretization/nonlinear_problem.hpp"
#include "discretization/quadrature_state.hpp"
#include "physics/materials/constitutive_model.hpp"

#include <Teuchos_RCP.hpp>

#include <string>
#include <vector>

namespace kiln_test
{
/// Three components: the steps accepted since the start ("accepted_steps", +1 per
/// evaluation from the old state), the sum of the strain eps_xx over them ("strain_sum") and
/// the integral of the temperature over time, sum of T Δt ("temperature_time_integral",
/// starting from 1). A state committed once per accepted step counts them exactly; one
/// committed on a rejected attempt, or not restored, or read back wrong, does not. The stress
/// is E ε with E = 1 (a diagonal tangent).
class AccumulatingStateModel final : public kiln::ConstitutiveModel
{
public:
  int n_state() const override { return 3; }
  void initial_state(double *state) const override;
  std::vector<std::string> state_names() const override;
  double thermal_strain(double /*temperature*/) const override { return 0.0; }
  void evaluate(const kiln::PointInput &in, const double *old_state, double *new_state,
                kiln::PointResponse &out) const override;
};

/// Whether both copies of `a` and `b` hold the same bits at every point (and the same layout).
bool same_bits(const kiln::QuadratureState &a, const kiln::QuadratureState &b);

/// A TransientProblem that forwards everything to `problem` and, after each evaluation with a
/// residual, evaluates `model` at every point of every cell of `state` (old -> current) with
/// the input: eps_xx = 1e-3 (global cell + 1) + 1e-4 q, T = |x|_inf (the same on any number
/// of ranks), T_old as at the last accepted step, Δt from it (the time of the last
/// set_time_derivative). The state's commit and restore are `problem`'s (step_accepted,
/// step_rejected), as in a run. With `fail_attempt` > 0, the residual of the first evaluation
/// of that attempted step (counting set_time_derivative calls from 1) is NaN on every rank,
/// so that Newton fails and the step is retried.
class StateDrivingProblem final : public kiln::TransientProblem
{
public:
  StateDrivingProblem(Teuchos::RCP<kiln::TransientProblem> problem,
                      const kiln::ConstitutiveModel &model, kiln::QuadratureState &state,
                      int fail_attempt = 0);

  Teuchos::RCP<const Map> solution_map() const override { return problem_->solution_map(); }
  Teuchos::RCP<const Graph> jacobian_graph() const override { return problem_->jacobian_graph(); }
  void evaluate(const Vector &x, Vector *f, Matrix *J) override;
  std::vector<double> jacobian_dependencies(const Vector &x) override
  {
    return problem_->jacobian_dependencies(x);
  }
  std::size_t smooth_dependencies() const override { return problem_->smooth_dependencies(); }
  bool jacobian_with(const std::vector<double> &smooth, const Vector &x, Matrix &J) override
  {
    return problem_->jacobian_with(smooth, x, J);
  }
  void jacobian_kept(const Vector &x) override { problem_->jacobian_kept(x); }
  Teuchos::RCP<const Vector> unknown_scale() const override { return problem_->unknown_scale(); }
  Teuchos::RCP<const Vector> time_error_mask() const override
  {
    return problem_->time_error_mask();
  }
  void set_time_derivative(double time, double a, const Vector &b) override;
  void step_accepted(double time, const Vector &x) override;
  void step_rejected() override;

  /// The time and T of the last accepted step (a continued run sets them from its checkpoint).
  void set_accepted(double time, double temperature);
  int rejections() const { return rejections_; }

private:
  Teuchos::RCP<kiln::TransientProblem> problem_;
  const kiln::ConstitutiveModel &model_;
  kiln::QuadratureState &state_;
  int fail_attempt_;
  int attempts_ = 0;
  bool fail_next_ = false;
  int rejections_ = 0;
  double time_ = 0.0;
  double accepted_time_ = 0.0;
  double accepted_temperature_ = 0.0;
};
} // namespace kiln_test
