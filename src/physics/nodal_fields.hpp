#pragma once
/// The fields the kernels see at the nodes, and the time state of the step being solved.
#include "discretization/assembler.hpp"
#include "discretization/nodal_constraints.hpp"

#include <Tpetra_Vector.hpp>

#include <vector>

namespace kiln
{
/// At every overlap node: T [K], Tdot = a T + b [K/s] and u [m] from the unknowns x, with the
/// constrained unknowns at their prescribed values (NodalConstraints::temperature,
/// displacement); T_ref without a temperature, 0 without a displacement. The time state is
/// the time t of the step's end and Tdot = a x + b (TransientProblem).
class NodalFields
{
public:
  using Vector = Tpetra::Vector<>;
  NodalFields(const DofManager &dofs, const Assembler &assembler,
              const NodalConstraints &constraints, double reference_temperature);

  /// t [s], a [1/s] and b (owned) for the next updates.
  void set_time_derivative(double time, double a, const Vector &b);
  double time() const { return time_; }
  double a() const { return a_; }
  /// Replaces a only (CoupledProblem::jacobian_with); the next update() uses it.
  void set_a(const double a) { a_ = a; }

  /// Whether set_time_history() keeps the past temperatures (a kernel reads them: the
  /// enthalpy's capacity term); default false, which costs nothing.
  void keep_history(const bool keep) { keep_history_ = keep; }
  /// b = Σ_k weights[k] past[k] (owned; TransientProblem::set_time_history): the past
  /// temperatures at every overlap node, if keep_history(); set_time_derivative() forgets them.
  void set_time_history(const std::vector<double> &weights,
                        const std::vector<const Vector *> &past);
  /// The number of past states kept (0: none), their weights [1/s] and temperatures [K].
  int n_past() const { return static_cast<int>(weights_.size()); }
  double past_weight(const int k) const { return weights_[k]; }
  double T_past(const int k, const int node) const { return T_past_[k][overlap_index_[node]]; }

  /// The state x (owned) was accepted (a step's end, the initial state, a checkpoint's):
  /// its temperatures at every overlap node, with the prescribed values of the constraints'
  /// time, are T at t_n for the steps that follow (the constitutive models'
  /// PointInput::temperature_old). Kept until the next call; set_time_derivative() keeps
  /// them. Without a temperature nothing is kept. Collective.
  void set_accepted(const Vector &x);
  /// Whether set_accepted() has been called with a temperature.
  bool has_accepted() const { return !T_accepted_.empty(); }
  double T_accepted(const int node) const { return T_accepted_[overlap_index_[node]]; }

  /// The fields at x (overlap values).
  void update(const Vector &x_overlap);
  /// The position of a mesh node among the overlap nodes, or -1.
  int index(const int node) const { return overlap_index_[node]; }
  double T(const int node) const { return T_[overlap_index_[node]]; }
  double T_dot(const int node) const { return T_dot_[overlap_index_[node]]; }
  const Point &u(const int node) const { return u_[overlap_index_[node]]; }

private:
  const DofManager &dofs_;
  const Assembler &assembler_;
  const NodalConstraints &constraints_;
  int F_;
  int T_slot_;
  int u_slot_;
  double reference_temperature_;
  std::vector<int> overlap_index_; ///< per mesh node
  double time_ = 0.0;
  double a_ = 0.0;
  Teuchos::RCP<Vector> b_overlap_;
  std::vector<double> T_, T_dot_; ///< per overlap node
  std::vector<Point> u_;          ///< per overlap node
  bool keep_history_ = false;
  std::vector<double> weights_;             ///< of the past states kept
  std::vector<std::vector<double>> T_past_; ///< per past state, per overlap node
  Teuchos::RCP<Vector> past_overlap_;       ///< a past state's overlap values (scratch)
  std::vector<double> T_accepted_;          ///< per overlap node (empty: none accepted)
};
} // namespace kiln
