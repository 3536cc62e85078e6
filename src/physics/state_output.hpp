#pragma once
/// What a state of the coupled problem shows for output and tests: nodal values, cell
/// averages, the contact values per node and pair, the heat across the gap per pair, and the
/// figures of a time history.
#include "contact/interface_strategy.hpp"
#include "discretization/dof_manager.hpp"
#include "physics/heat/thermal_physics.hpp"
#include "physics/kernel.hpp"
#include "physics/mechanics/mechanical_physics.hpp"
#include "physics/nodal_fields.hpp"
#include "physics/residual_terms.hpp"
#include "physics/state_summary.hpp"

#include <functional>
#include <memory>
#include <vector>

namespace kiln
{
/// The output quantities of the state the fields hold: CoupledProblem prepares the state at x
/// (NodalFields at x, and with interfaces their decision at x), then asks this for its values.
/// It reads the problem's pieces and changes none of them. Each call is collective where noted.
class StateOutput
{
public:
  /// `thermal` and `mechanics`: null for a layout without the field; `interfaces`: the
  /// problem's strategies across the gap (empty without contact).
  StateOutput(const Mesh &mesh, const DofManager &dofs, const FieldSlots &slots,
              const NodalFields &fields, const ThermalPhysics *thermal,
              const MechanicalPhysics *mechanics, const ResidualTerms &terms,
              const std::vector<std::unique_ptr<InterfaceStrategy>> &interfaces);

  /// Physical values of the owned nodes (DofManager::owned_nodes() order), with the
  /// prescribed values of the last set time where constrained.
  std::vector<double> node_temperatures() const;
  std::vector<Point> node_displacements() const;
  /// Volume averages over each owned cell (owned_cells() order). Needs the displacement.
  std::vector<ElasticityKernel::CellAverages> cell_averages() const;
  /// Per owned cell: averages of σ, ε, the von Mises stress and the plastic strain and rate
  /// at the step's end (the state being computed, which the last step accepted).
  std::vector<ElasticityKernel::PointAverages> point_averages() const;
  /// Contact per mesh node, on every rank, at the interfaces' decision (CoupledProblem::
  /// contact_output()); all NaN without interfaces. Collective.
  using ContactOutput = InterfaceStrategy::NodeValues;
  ContactOutput contact_output() const;
  /// The heat across the gap per pair of Mesh::gap_pairs, on every rank (CoupledProblem::
  /// gap_heat_flow()) [W]; NaN without temperature. Collective.
  std::vector<double> gap_heat_flow() const;
  /// The figures of the state for a time history (with interfaces, at their decision).
  /// Collective.
  StateSummary summary() const;

private:
  /// Calls `visit` on each owned cell (owned order) with its kernel, values, nodal T and u,
  /// and its output history (BlockElasticityKernel::output_history).
  using CellVisitor = std::function<void(const ElasticityKernel &, const ElementValues &,
                                         const std::vector<double> &, const std::vector<Point> &,
                                         const ElasticityKernel::PointHistory &)>;
  void for_each_owned_cell(const CellVisitor &visit) const;

  const Mesh &mesh_;
  const DofManager &dofs_;
  FieldSlots slots_;
  const NodalFields &fields_;
  const ThermalPhysics *thermal_;
  const MechanicalPhysics *mechanics_;
  const ResidualTerms &terms_;
  const std::vector<std::unique_ptr<InterfaceStrategy>> &interfaces_;
};
} // namespace kiln
