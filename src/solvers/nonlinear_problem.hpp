#pragma once
/// What the Newton solver sees of a problem: a residual F(x) and its Jacobian
/// on Tpetra objects. The Assembler-based physics implements it; the solver
/// (NewtonSolver) knows nothing of meshes or physics.
#include <Teuchos_RCP.hpp>
#include <Tpetra_CrsGraph.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

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
  /// Optional: coordinates of the owned rows' nodes and the number of
  /// unknowns per node, for multigrid (MueLu aggregation, repartitioning,
  /// near-null space). Default: none.
  virtual Teuchos::RCP<const Tpetra::MultiVector<double>> node_coordinates() const
  {
    return Teuchos::null;
  }
};
} // namespace kiln
