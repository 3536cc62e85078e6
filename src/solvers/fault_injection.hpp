#pragma once
/// A testing aid: faults injected into the problem the solvers see, to test what a run does
/// when one rank's assembly throws or the residual is not a number (doc/user-guide.md,
/// "Faults"). Set by the input's Kiln/Debug sublist; without it (Fault = "None") the problem
/// is not wrapped at all.
#include "discretization/nonlinear_problem.hpp"

#include <Teuchos_FancyOStream.hpp>
#include <Teuchos_ParameterList.hpp>

#include <string>

namespace kiln
{
/// A TransientProblem that forwards everything to the problem it wraps and, in the chosen
/// residual evaluations on the chosen rank, after the wrapped evaluation (so that every rank
/// has taken part in its collective steps):
/// - "Exception In Assembly": throws a RunError on that rank only, as a kernel's exception
///   would leave evaluate() on one rank (the solvers turn it into the same RunError on every
///   rank: evaluate_collectively);
/// - "NaN In Residual": sets the first residual entry of that rank to NaN;
/// - "Step Failure In Assembly": throws a StepFailure on that rank only, as a constitutive
///   model whose local solve does not converge (the time stepper cuts the step).
/// The evaluations counted are those with a residual (f not null) at a time (of the last
/// set_time_derivative, 0 before the first) at or after "Time".
class FaultInjection final : public TransientProblem
{
public:
  static Teuchos::ParameterList valid_parameters();
  /// `problem` itself if `debug` (the validated Kiln/Debug list) asks for no fault; else
  /// `problem` wrapped, with a warning on `out`. `where` names the list in messages
  /// ("in.xml: Kiln/Debug").
  static Teuchos::RCP<TransientProblem> wrap(Teuchos::RCP<TransientProblem> problem,
                                             const Teuchos::ParameterList &debug,
                                             const std::string &where, Teuchos::FancyOStream &out);
  FaultInjection(Teuchos::RCP<TransientProblem> problem, const Teuchos::ParameterList &debug,
                 const std::string &where);

  Teuchos::RCP<const Map> solution_map() const override { return problem_->solution_map(); }
  Teuchos::RCP<const Graph> jacobian_graph() const override { return problem_->jacobian_graph(); }
  void evaluate(const Vector &x, Vector *f, Matrix *J) override;
  std::vector<double> jacobian_dependencies(const Vector &x) override
  {
    return problem_->jacobian_dependencies(x);
  }
  bool jacobian_varies() const override { return problem_->jacobian_varies(); }
  std::vector<double> preconditioner_dependencies(const Vector &x) override
  {
    return problem_->preconditioner_dependencies(x);
  }
  std::size_t smooth_dependencies() const override { return problem_->smooth_dependencies(); }
  bool jacobian_with(const std::vector<double> &smooth, const Vector &x, Matrix &J) override
  {
    return problem_->jacobian_with(smooth, x, J);
  }
  void jacobian_kept(const Vector &x) override { problem_->jacobian_kept(x); }
  Teuchos::RCP<const Tpetra::MultiVector<double>> node_coordinates() const override
  {
    return problem_->node_coordinates();
  }
  Teuchos::RCP<const Tpetra::MultiVector<double>> near_null_space() const override
  {
    return problem_->near_null_space();
  }
  Teuchos::RCP<const Vector> unknown_scale() const override { return problem_->unknown_scale(); }
  Teuchos::RCP<const Tpetra::MultiVector<double>> free_motions() const override
  {
    return problem_->free_motions();
  }
  std::vector<std::string> free_motion_names() const override
  {
    return problem_->free_motion_names();
  }
  void set_time_derivative(double time, double a, const Vector &b) override;
  void set_time_history(const std::vector<double> &weights,
                        const std::vector<const Vector *> &past) override
  {
    problem_->set_time_history(weights, past);
  }
  Teuchos::RCP<const Vector> time_error_mask() const override
  {
    return problem_->time_error_mask();
  }
  void step_accepted(double time, const Vector &x) override { problem_->step_accepted(time, x); }
  void step_rejected() override { problem_->step_rejected(); }
  double inelastic_strain_increment() const override
  {
    return problem_->inelastic_strain_increment();
  }

  /// Residual evaluations corrupted so far (on every rank alike).
  int n_faults() const { return faults_; }

private:
  Teuchos::RCP<TransientProblem> problem_;
  std::string where_;
  std::string fault_;
  int rank_;
  double time_;
  int evaluations_; ///< how many to corrupt, -1: all
  double now_ = 0.0;
  int faults_ = 0;
};
} // namespace kiln
