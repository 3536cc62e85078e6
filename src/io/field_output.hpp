#pragma once
/// The fields of a state written at an output time (doc/output-format.md).
#include "io/results_writer.hpp"
#include "physics/coupled_problem.hpp"

#include <Teuchos_Comm.hpp>

#include <vector>

namespace kiln
{
/// From the problem's state x: the nodal temperature and displacement, the cell averages of
/// stress, strain and thermal strain, and at the gap the opening, the normal traction and
/// the contact state (NaN off the gap), each for the fields the layout has.
class FieldOutput
{
public:
  using Vector = NonlinearProblem::Vector;
  /// Keeps references to its arguments.
  FieldOutput(CoupledProblem &problem, const Mesh &mesh, const DofManager &dofs);
  /// Writes the fields of x as one step of `writer` (collective).
  void write(ResultsWriter &writer, double time, int cycle, double dt, const Vector &x);

private:
  /// The gap opening (gap_opening()) of the displaced positions at the owned nodes (NaN off
  /// the gap); u_owned: the displacement of the owned nodes.
  std::vector<double> gap_opening(const std::vector<Point> &u_owned) const;

  CoupledProblem &problem_;
  const Mesh &mesh_;
  const DofManager &dofs_;
};
} // namespace kiln
