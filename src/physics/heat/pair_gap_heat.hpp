#pragma once
/// The heat across the gap of one contact pair between separately meshed bodies (issue 30,
/// doc/heat.md "Heat across the gap of a mortar pairing"), as a term of a run: the pair's
/// MortarGapHeat cells, built at set-up in the reference configuration and rebuilt in the
/// current one X + u at each search of the pair (as the pair's rows, within the margins of
/// set-up), each assembled by the rank that owns the cell of its secondary face.
#include "mesh/mesh.hpp"
#include "physics/heat/contact_conductance_kernel.hpp"
#include "physics/heat/mortar_gap_heat.hpp"

#include <Teuchos_ParameterList.hpp>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace kiln
{
class ContactSurface;
class Material;
class MaterialMap;
class NodalFields;

class PairGapHeat
{
public:
  /// Receives a cell's local system; nodes[i] is the mesh node of local node i.
  using Sink = std::function<void(const std::vector<int> &nodes, LocalSystem &local)>;

  /// The cells of the pair of side sets (as MortarPairing's: the primary faces facing each
  /// secondary face within `search_distance` [m]) with the validated "Heat Transfer" sublist
  /// `heat_transfer`; `where` names that sublist in messages. Without an active term, no cells.
  /// With a "Gap Pressure Coefficient" h_p > 0 the contact conductance h_p max(p, 0) of the split
  /// gap's "Contact Dependent" model (ContactConductanceKernel, its pressure p from the cells of
  /// each cell's two faces and their materials: those of `materials`, or `material` alone if it
  /// is null; `material` must then be given) adds to the conductance, and each cell's local
  /// nodes are its faces' then the other nodes of the faces' two mesh cells. An InputError
  /// names the parameter and the material if one beside the pair is viscoplastic.
  /// The margins (margin_blocks(), links()) are the faces facing each secondary face within
  /// `search_distance` + `sliding_distance` [m] at set-up (as MortarPairing::margins()): the
  /// cells rebuild() may make.
  PairGapHeat(const Mesh &mesh, int primary_side_set, int secondary_side_set,
              double search_distance, double sliding_distance,
              const Teuchos::ParameterList &heat_transfer, const std::string &where,
              const Material *material = nullptr, const MaterialMap *materials = nullptr);

  /// Whether a term is on (else no cells and nothing to assemble).
  bool active() const { return heat_.active(); }
  /// Whether the temperature rows read the displacement (the gas term).
  bool depends_on_displacement() const { return heat_.depends_on_displacement(); }
  const std::vector<MortarGapCell> &cells() const { return set_.cells; }
  /// Per cell: its mesh nodes (the secondary face's, then the primary face's, then with a
  /// contact conductance the other nodes of their mesh cells), and the mesh cell of its
  /// secondary face (whose owner assembles it).
  const std::vector<int> &cell_nodes(const std::size_t k) const { return set_.nodes[k]; }
  int owning_cell(const std::size_t k) const { return set_.owning_cells[k]; }
  /// The blocks (owning cell, nodes) of every cell a search within the margins can make: one
  /// per (secondary face, primary face facing it within the margin), its nodes as
  /// cell_nodes()'. For Couplings::cell_blocks: the Jacobian graph holds every rebuilt cell.
  std::vector<std::pair<int, std::vector<int>>> margin_blocks() const;
  /// The links (secondary node, node) of margin_blocks(), for DofManager's partner links: a
  /// rank that holds a secondary node then holds every node a cell of its faces can touch.
  std::vector<std::pair<int, int>> links() const;

  /// The mesh nodes of the two surfaces, increasing: rebuild() reads u at these.
  const std::vector<int> &surface_nodes() const { return surface_nodes_; }
  /// Rebuilds the cells in the current configuration X + u (`u` per surface_nodes() entry
  /// [m], the same on every rank) reached at `time` [s], the pair's search redone. Throws
  /// RunError naming the pair (`name`), the secondary face's nodes, the time and what to
  /// change if a cell pairs a secondary face with a primary face outside its margin (the
  /// small-sliding limit); the cells are then unchanged.
  void rebuild(const std::vector<Point> &u, double time, const std::string &name);
  /// The u given to the last rebuild() (per surface_nodes() entry), empty if none: what a
  /// checkpoint keeps so that a restart rebuilds the same cells.
  const std::vector<Point> &searched_displacement() const { return set_.u; }

  /// The cells in force, to put back with restore() (a step refused after a search).
  struct CellSet
  {
    std::vector<MortarGapCell> cells;
    std::vector<std::vector<int>> nodes;
    std::vector<int> owning_cells;
    std::vector<int> n_secondary; ///< per cell: its secondary face's nodes
    /// With a contact conductance, per cell: the mesh cells of its secondary and primary
    /// faces, and the local node of each of their nodes.
    std::vector<std::array<int, 2>> mesh_cells;
    std::vector<std::array<std::vector<int>, 2>> cell_locals;
    std::vector<Point> u; ///< the displacement they were built at (empty: the reference)
  };
  const CellSet &cell_set() const { return set_; }
  void restore(CellSet set) { set_ = std::move(set); }

  /// Adds the local system of every cell whose owning_cell() `owns_cell` marks to `sink`, at
  /// the temperatures and displacements of `fields` (slots.u < 0: the reference positions).
  void evaluate(const NodalFields &fields, const FieldSlots &slots, int n_fields, bool jacobian,
                const std::vector<char> &owns_cell, const Sink &sink) const;
  /// The heat across the cells `owns_cell` marks, secondary to primary side [W] (this rank's
  /// share: sum over the ranks).
  double heat_flow(const NodalFields &fields, const FieldSlots &slots,
                   const std::vector<char> &owns_cell) const;
  /// Adds to `flow` (a value per mesh node) the heat across the cells `owns_cell` marks at each
  /// secondary node i, Σ_q w_q N_i(xi_s) q, secondary to primary side [W] (this rank's share:
  /// sum over the ranks); the nodes' sum is heat_flow().
  void add_node_heat_flow(const NodalFields &fields, const FieldSlots &slots,
                          const std::vector<char> &owns_cell, std::vector<double> &flow) const;

private:
  /// The cells in the configuration X + u (`u` per surface_nodes() entry; null: X).
  CellSet build(const std::vector<Point> *u) const;
  /// The local nodes of a cell of faces (s, m) of the two surfaces, its two mesh cells and,
  /// with a contact conductance, the local node of each node of the two cells.
  std::vector<int> block_nodes(const ContactSurface &secondary, const ContactSurface &primary,
                               int s, int m, std::array<int, 2> &mesh_cells,
                               std::array<std::vector<int>, 2> &locals) const;

  /// Calls `visit` with each block of margin_blocks(): its owning cell, the count of its
  /// secondary face's nodes (first among its nodes) and its nodes.
  void visit_margin_blocks(const std::function<void(int owning_cell, int n_secondary,
                                                    std::vector<int> nodes)> &visit) const;
  /// The local nodes' T [K], u [m] and x = X + u [m] of cell k.
  void cell_state(const NodalFields &fields, const FieldSlots &slots, std::size_t k,
                  std::vector<double> &T, std::vector<Point> &u, std::vector<Point> &x) const;
  /// The contact conductance of cell k at T and u (none without h_p).
  std::unique_ptr<MortarGapHeat::ContactTerm>
  contact_term(std::size_t k, const std::vector<double> &T, const std::vector<Point> &u) const;

  const Mesh &mesh_;
  int primary_side_set_;
  int secondary_side_set_;
  double search_distance_;
  std::string where_;
  MortarGapHeat heat_;
  /// The contact conductance (h0 = 0: h_p max(p, 0) alone), with h_p > 0.
  std::unique_ptr<const ContactConductanceKernel> contact_;
  /// Per secondary face, the primary faces facing it within the margin at set-up, increasing.
  std::vector<std::vector<int>> margin_faces_;
  std::vector<int> surface_nodes_;
  CellSet set_;
};
} // namespace kiln
