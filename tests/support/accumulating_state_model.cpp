#include "support/accumulating_state_model.hpp"

#include <cstring>
#include <limits>

namespace kiln_test
{
void AccumulatingStateModel::initial_state(double *state) const
{
  state[0] = 0.0;
  state[1] = 0.0;
  state[2] = 1.0;
}

std::vector<std::string> AccumulatingStateModel::state_names() const
{
  return {"accepted_steps", "strain_sum", "temperature_time_integral"};
}

void AccumulatingStateModel::evaluate(const kiln::PointInput &in, const double *old_state,
                                      double *new_state, kiln::PointResponse &out) const
{
  new_state[0] = old_state[0] + 1.0;
  new_state[1] = old_state[1] + in.strain[0];
  new_state[2] = old_state[2] + in.temperature * in.time_step;
  out = kiln::PointResponse{};
  for (int i = 0; i < 6; ++i)
  {
    out.stress[i] = in.strain[i];
    out.tangent[i][i] = 1.0;
  }
}

bool same_bits(const kiln::QuadratureState &a, const kiln::QuadratureState &b)
{
  if (a.n_points() != b.n_points() || a.n_state() != b.n_state() || a.cells() != b.cells())
    return false;
  const std::size_t bytes = sizeof(double) * static_cast<std::size_t>(a.n_state());
  for (int c = 0; c < a.n_cells(); ++c)
    for (int q = 0; q < a.n_points(c); ++q)
      if (std::memcmp(a.old(c, q), b.old(c, q), bytes) != 0 ||
          std::memcmp(a.current(c, q), b.current(c, q), bytes) != 0)
        return false;
  return true;
}

StateDrivingProblem::StateDrivingProblem(Teuchos::RCP<kiln::TransientProblem> problem,
                                         const kiln::ConstitutiveModel &model,
                                         kiln::QuadratureState &state, const int fail_attempt)
    : problem_(std::move(problem)), model_(model), state_(state), fail_attempt_(fail_attempt)
{
}

void StateDrivingProblem::evaluate(const Vector &x, Vector *f, Matrix *J)
{
  problem_->evaluate(x, f, J);
  if (f == nullptr)
    return;
  kiln::PointInput in;
  in.temperature = x.normInf();
  in.temperature_old = accepted_temperature_;
  in.time_step = time_ - accepted_time_;
  kiln::PointResponse out;
  for (int c = 0; c < state_.n_cells(); ++c)
    for (int q = 0; q < state_.n_points(c); ++q)
    {
      in.strain[0] = 1e-3 * (state_.cells()[c] + 1) + 1e-4 * q;
      model_.evaluate(in, state_.old(c, q), state_.current(c, q), out);
    }
  if (fail_next_)
  {
    fail_next_ = false;
    f->putScalar(std::numeric_limits<double>::quiet_NaN());
  }
}

void StateDrivingProblem::set_time_derivative(const double time, const double a, const Vector &b)
{
  problem_->set_time_derivative(time, a, b);
  time_ = time;
  fail_next_ = ++attempts_ == fail_attempt_;
}

void StateDrivingProblem::step_accepted(const double time, const Vector &x)
{
  problem_->step_accepted(time, x);
  accepted_time_ = time;
  accepted_temperature_ = x.normInf();
}

void StateDrivingProblem::step_rejected()
{
  problem_->step_rejected();
  ++rejections_;
}

void StateDrivingProblem::set_accepted(const double time, const double temperature)
{
  accepted_time_ = time;
  accepted_temperature_ = temperature;
}
} // namespace kiln_test
