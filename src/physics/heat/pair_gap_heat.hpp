#pragma once
/// The heat across the gap of one contact pair between separately meshed bodies (issue 30,
/// doc/heat.md "Heat across the gap of a mortar pairing"), as a term of a run: the pair's
/// MortarGapHeat cells, built once at set-up in the reference configuration (as the pair's
/// rows), each assembled by the rank that owns the cell of its secondary face.
#include "mesh/mesh.hpp"
#include "physics/heat/mortar_gap_heat.hpp"

#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace kiln
{
class NodalFields;

class PairGapHeat
{
public:
  /// Receives a cell's local system; nodes[i] is the mesh node of local node i.
  using Sink = std::function<void(const std::vector<int> &nodes, LocalSystem &local)>;

  /// The cells of the pair of side sets (as MortarPairing's: the primary faces facing each
  /// secondary face within `search_distance` [m]) with the validated "Heat Transfer" sublist
  /// `heat_transfer`; `where` names that sublist in messages. Without an active term, no cells.
  PairGapHeat(const Mesh &mesh, int primary_side_set, int secondary_side_set,
              double search_distance, const Teuchos::ParameterList &heat_transfer,
              const std::string &where);

  /// Whether a term is on (else no cells and nothing to assemble).
  bool active() const { return heat_.active(); }
  /// Whether the temperature rows read the displacement (the gas term).
  bool depends_on_displacement() const { return heat_.depends_on_displacement(); }
  const std::vector<MortarGapCell> &cells() const { return cells_; }
  /// Per cell: its mesh nodes (the secondary face's, then the primary face's), and the mesh
  /// cell of its secondary face (whose owner assembles it).
  const std::vector<int> &cell_nodes(const std::size_t k) const { return nodes_[k]; }
  int owning_cell(const std::size_t k) const { return owning_cells_[k]; }
  /// The links (secondary node, primary node) of the cells, for DofManager's partner links:
  /// a rank that holds a secondary node then holds the primary nodes of its cells.
  std::vector<std::pair<int, int>> links() const;

  /// Adds the local system of every cell whose owning_cell() `owns_cell` marks to `sink`, at
  /// the temperatures and displacements of `fields` (slots.u < 0: the reference positions).
  void evaluate(const NodalFields &fields, const FieldSlots &slots, int n_fields, bool jacobian,
                const std::vector<char> &owns_cell, const Sink &sink) const;
  /// The heat across the cells `owns_cell` marks, secondary to primary side [W] (this rank's
  /// share: sum over the ranks).
  double heat_flow(const NodalFields &fields, const FieldSlots &slots,
                   const std::vector<char> &owns_cell) const;

private:
  void cell_state(const NodalFields &fields, const FieldSlots &slots, std::size_t k,
                  std::vector<double> &T, std::vector<Point> &x) const;

  const Mesh &mesh_;
  MortarGapHeat heat_;
  std::vector<MortarGapCell> cells_;
  std::vector<std::vector<int>> nodes_;
  std::vector<int> owning_cells_;
  std::vector<int> n_secondary_; ///< per cell: its secondary face's nodes
};
} // namespace kiln
