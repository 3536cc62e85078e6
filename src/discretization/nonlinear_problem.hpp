#pragma once
/// What the Newton solver sees of a problem: a residual F(x) and its Jacobian
/// on Tpetra objects. The Assembler-based physics implements it; the solver
/// (NewtonSolver, TimeStepper) knows nothing of meshes or physics.
#include <Teuchos_RCP.hpp>
#include <Tpetra_CrsGraph.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace kiln
{
class NonlinearProblem
{
public:
  using Map = Tpetra::Map<>;
  using Vector = Tpetra::Vector<>;
  using Matrix = Tpetra::CrsMatrix<>;
  using Graph = Tpetra::CrsGraph<>;

  virtual ~NonlinearProblem() = default;
  /// The owned map of x and F (one-to-one).
  virtual Teuchos::RCP<const Map> solution_map() const = 0;
  /// The Jacobian's graph (fill-complete, row map = solution_map()); built once.
  virtual Teuchos::RCP<const Graph> jacobian_graph() const = 0;
  /// f = F(x) if f is not null; J = dF/dx if J is not null (J has
  /// jacobian_graph() as its static graph, fill-complete on entry and exit).
  /// Collective: every rank calls it with the same pattern of nulls.
  virtual void evaluate(const Vector &x, Vector *f, Matrix *J) = 0;
  /// Optional: what the Jacobian at x depends on, for reuse. Two states whose vectors are
  /// equal and non-empty have the same Jacobian, so the solver keeps the matrix it holds
  /// and its preconditioner instead of evaluating them again (doc/solvers.md). The vector
  /// is this rank's part; the solver compares on every rank. Collective. Default: empty
  /// (the Jacobian may change with x or t: never reused).
  virtual std::vector<double> jacobian_dependencies(const Vector & /*x*/) { return {}; }
  /// Whether jacobian_dependencies() is empty at every state (the Jacobian varies with x: a
  /// viscoplastic model, a property of T), known without a state or a solve (a restarted
  /// run answers as the run it continues). This rank's answer. Default: true.
  virtual bool jacobian_varies() const { return true; }
  /// Optional: how many leading entries of jacobian_dependencies() are coefficients the
  /// Jacobian varies with smoothly (the time-derivative coefficient a). A Jacobian whose
  /// coefficients differ from those a preconditioner was built for by a small relative
  /// amount, the other entries equal, is still evaluated anew, but may keep that
  /// preconditioner (Solver/"Preconditioner Reuse Tolerance"). Default: none.
  virtual std::size_t smooth_dependencies() const { return 0; }
  /// Optional, with smooth_dependencies(): J = the Jacobian at x with the smooth coefficients
  /// `smooth` in place of the problem's own, every other dependency as at the last
  /// evaluation at x (x must be the state of that evaluation); the problem's own coefficients
  /// and state stay as they were. So a restarted run can build its first preconditioner from
  /// the Jacobian an uninterrupted run built the preconditioner it keeps from
  /// (Solver/"Preconditioner Reuse Tolerance"). Returns false, J untouched, if it cannot.
  /// Collective. Default: false.
  virtual bool jacobian_with(const std::vector<double> & /*smooth*/, const Vector & /*x*/,
                             Matrix & /*J*/)
  {
    return false;
  }
  /// Optional, for a problem whose Jacobian varies with x (jacobian_dependencies() empty):
  /// what a preconditioner of its Jacobian depends on beyond values that change smoothly
  /// with x (for Kiln's problems the time-derivative coefficient, the constraints and the
  /// contact decision; not a constitutive tangent). While this is the same on every rank as
  /// at the first Jacobian of a Newton solve, the later Jacobians of that solve are
  /// evaluated anew but may keep the first one's preconditioner (Solver/"Keep
  /// Preconditioner Within Solve"). Collective. Default: empty (never kept).
  virtual std::vector<double> preconditioner_dependencies(const Vector & /*x*/) { return {}; }
  /// Called instead of evaluate(x, nullptr, J) when the solver keeps the Jacobian it holds
  /// (the dependencies at x are those of its last evaluation). Collective. Default: nothing.
  virtual void jacobian_kept(const Vector & /*x*/) {}
  /// Optional: coordinates of the owned rows' nodes and the number of
  /// unknowns per node, for multigrid (MueLu aggregation, repartitioning,
  /// near-null space). Default: none.
  virtual Teuchos::RCP<const Tpetra::MultiVector<double>> node_coordinates() const
  {
    return Teuchos::null;
  }
  /// Optional: a basis of the operator's near-null space on solution_map() (for MueLu:
  /// the constant temperature, the rigid-body modes), in the unknowns x. Default: none.
  virtual Teuchos::RCP<const Tpetra::MultiVector<double>> near_null_space() const
  {
    return Teuchos::null;
  }
  /// Optional: a basis of the rigid motions the problem leaves free, one column each, in the
  /// unknowns x: its Jacobian's null space on both sides (J v = 0 and v^T J = 0), and F(x + v t)
  /// = F(x). The solver then gives the solution with no component in them and refuses a
  /// residual whose part along them does not vanish (a net force along a free motion: no
  /// solution). Default: none.
  virtual Teuchos::RCP<const Tpetra::MultiVector<double>> free_motions() const
  {
    return Teuchos::null;
  }
  /// Optional: after a converged solve with free motions (their part projected out of x), the
  /// problem's own step to its minimum-norm solution where more motions than those leave the
  /// solution undetermined (contact: the motions open pairs leave free, within g >= 0;
  /// doc/contact.md). Default: none. Collective.
  virtual void to_minimum_norm(Vector &x) { (void)x; }
  /// Optional: each free motion in words ("translation along z"), for messages.
  virtual std::vector<std::string> free_motion_names() const { return {}; }
  /// Optional: the scale c of every unknown. The solver then works on x̂ = x / c with the
  /// rows multiplied by c (F̂ = c F, Ĵ = diag(c) J diag(c)), so that fields of different
  /// units reach the Krylov solver and the multigrid with comparable rows and unknowns;
  /// the tolerances of the Newton solver apply to F̂. Default: none (c = 1).
  virtual Teuchos::RCP<const Vector> unknown_scale() const { return Teuchos::null; }
};

/// A problem with a time derivative: F(x, xdot, t) with xdot = a x + b, the
/// form every implicit one-step or multistep method takes (backward Euler:
/// a = 1/dt, b = -x_n/dt). The time stepper sets t, a and b before each
/// solve; evaluate() then includes dxdot/dx = a in the Jacobian. A steady
/// solve sets a = 0 and b = 0.
class TransientProblem : public NonlinearProblem
{
public:
  /// t [s], a [1/s], b (on solution_map(), unit of x per s) for the next evaluate() calls.
  virtual void set_time_derivative(double time, double a, const Vector &b) = 0;
  /// Optional: the past states b is made of, b = Σ_k weights[k] past[k] (the time stepper's
  /// x_n, and x_{n-1} with BDF2), for a term that differentiates a nonlinear function g of x
  /// in time as a g(x) + Σ_k weights[k] g(past[k]) (the enthalpy: doc/heat.md). Called after
  /// set_time_derivative, which forgets the last history. Default: ignored.
  virtual void set_time_history(const std::vector<double> & /*weights*/,
                                const std::vector<const Vector *> & /*past*/)
  {
  }
  /// Optional: 1 for the unknowns with a time derivative, 0 for the others (quasi-static
  /// displacement); the local error estimate of the time stepper counts the first only.
  /// Default: none (every unknown counts).
  virtual Teuchos::RCP<const Vector> time_error_mask() const { return Teuchos::null; }
  /// Called once a step ending at `time` is accepted with the state x (collective).
  /// Default: nothing.
  virtual void step_accepted(double /*time*/, const Vector & /*x*/) {}
  /// Called once an attempted step is given up (its Newton solve failed or its error estimate
  /// was too large; it is retried with a smaller step, or the run stops): what the problem
  /// computed for it is forgotten, and the next attempt starts from the last accepted state
  /// (collective). Default: nothing.
  virtual void step_rejected() {}
  /// Optional: after a converged solve of a step, the largest increment over the step of the
  /// equivalent inelastic (plastic) strain at any point, on every rank alike (collective);
  /// the time stepper cuts a step where it exceeds its tolerance. Default: 0 (none).
  virtual double inelastic_strain_increment() const { return 0.0; }
};
} // namespace kiln
