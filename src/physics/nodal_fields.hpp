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
};
} // namespace kiln
