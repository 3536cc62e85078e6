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
/// the contact state (NaN off the gap), each for the fields the layout has. The gap fields
/// are given per pair (ResultsWriter::write_gap_field()) and per node; a node in several
/// pairs (where gaps cross) shows its pair of the first gap (Mesh::gap_side_sets order). At
/// the node j of a contact pair's row (Mechanics/Contact/Pairs) the node fields gap_opening,
/// contact_pressure and contact_active show the row's g_j, P_j and state, and gap_heat_flux at
/// each node of a pair's secondary surface the heat across the pair's gap there (its node's
/// heat flow, CoupledProblem::pair_node_heat_flow, over its share of the surface's area; 0 on a
/// pair without Heat Transfer).
class FieldOutput
{
public:
  using Vector = NonlinearProblem::Vector;
  /// Keeps references to its arguments.
  FieldOutput(CoupledProblem &problem, const Mesh &mesh, const DofManager &dofs);
  /// Writes the fields of x as one step of `writer` (collective).
  void write(ResultsWriter &writer, double time, int cycle, double dt, const Vector &x);

private:
  /// The gap opening (gap_opening()) of the displaced positions per pair of Mesh::gap_pairs;
  /// u_owned: the displacement of the owned nodes.
  std::vector<double> gap_opening(const std::vector<Point> &u_owned) const;
  /// A gap field of the pairs to `writer`: per pair, then at the owned nodes (the pair of
  /// shown_pair_; elsewhere `at_rows`, per mesh node the contact pairs' row values, if given;
  /// NaN off the gap and the rows).
  void write_gap_field(ResultsWriter &writer, const std::string &name,
                       const std::vector<double> &per_pair,
                       const std::vector<double> *at_rows = nullptr) const;

  CoupledProblem &problem_;
  const Mesh &mesh_;
  const DofManager &dofs_;
  /// Per mesh node, the pair (Mesh::gap_pairs) whose values its gap fields show: of the first
  /// gap it lies on; -1 off the gap.
  std::vector<int> shown_pair_;
  /// Per mesh node, its share of the secondary surface's area of the first contact pair
  /// (Mesh::contact_pairs) it lies on [m^2]; 0 off them.
  std::vector<double> pair_node_area_;
};
} // namespace kiln
