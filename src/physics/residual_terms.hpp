#pragma once
/// Every term of the residual, evaluated element by element.
#include "discretization/dof_manager.hpp"
#include "physics/boundary_condition.hpp"
#include "physics/kernel.hpp"
#include "physics/nodal_fields.hpp"

#include <functional>
#include <memory>
#include <vector>

namespace kiln
{
class PairGapHeat;
/// The terms a rank assembles (MOOSE's kernels, BCs and interface kernels of a system): the
/// cell kernels on its owned cells, the boundary conditions with face terms on their faces of
/// owned cells, and the interface kernel on the gap faces whose side-a cell it owns. Each
/// evaluation fills one LocalSystem per cell or face from the nodal fields and hands it to a
/// sink, which distributes and adds it.
class ResidualTerms
{
public:
  /// Receives a local system; nodes[i] is the mesh node of local node i.
  using Sink = std::function<void(const std::vector<int> &nodes, LocalSystem &local)>;

  ResidualTerms(const Mesh &mesh, const DofManager &dofs, FieldSlots slots);

  void add_cell_kernel(const CellKernel &kernel);
  /// The face terms of `conditions` (those not constraints), in order.
  void add_boundary_conditions(const std::vector<std::unique_ptr<BoundaryCondition>> &conditions);
  void set_interface_kernel(const InterfaceKernel &kernel);
  /// The heat across a contact pair's gap: its cells whose secondary face's cell is owned.
  void add_pair_heat(const PairGapHeat &heat);

  /// Evaluates every term at `fields` into systems with or without a Jacobian. An exception
  /// of a term on some ranks becomes, once every rank has evaluated its terms, the same
  /// RunError on every rank, naming the rank and the cell or face. Collective.
  void evaluate(const NodalFields &fields, bool jacobian, const Sink &sink) const;
  /// Whether every term's Jacobian is constant (CellKernel::constant_jacobian()).
  bool constant_jacobian() const;
  /// The gap-face terms alone (the heat across the gap, for output).
  void evaluate_gap_faces(const NodalFields &fields, bool jacobian, const Sink &sink) const;
  /// The terms of the pairs' gaps alone (add_pair_heat()), for a sink that does not add the
  /// partners of their nodes (Couplings::cell_blocks); evaluate() leaves them out.
  void evaluate_pair_heat(const NodalFields &fields, bool jacobian, const Sink &sink) const;
  /// The heat across each pair's gap (add_pair_heat() order), secondary to primary side,
  /// summed over the ranks [W]. Collective.
  std::vector<double> pair_heat_flow(const NodalFields &fields) const;
  /// The heat across the pairs' gaps at each secondary node (PairGapHeat::add_node_heat_flow),
  /// a value per mesh node, summed over the pairs and the ranks (0 off their surfaces) [W].
  /// Collective.
  std::vector<double> pair_node_heat_flow(const NodalFields &fields) const;
  /// The Mesh::gap_faces that evaluate_gap_faces() gives the sink, in the order of its calls.
  const std::vector<int> &evaluated_gap_faces() const { return gap_faces_; }

private:
  void evaluate_cells(const NodalFields &fields, bool jacobian, const Sink &sink) const;
  void evaluate_faces(const NodalFields &fields, bool jacobian, const Sink &sink) const;

  struct BoundaryFace
  {
    int cell;
    int face;
    const BoundaryCondition *condition;
  };
  const Mesh &mesh_;
  const DofManager &dofs_;
  FieldSlots slots_;
  std::vector<char> owns_cell_;
  std::vector<const CellKernel *> cell_kernels_;
  std::vector<BoundaryFace> faces_;
  const InterfaceKernel *interface_kernel_ = nullptr;
  std::vector<int> gap_faces_;              ///< gap faces whose side-a cell is owned
  std::vector<std::vector<int>> gap_nodes_; ///< per gap face: the kernel's nodes
  std::vector<const PairGapHeat *> pair_heat_;
};
} // namespace kiln
