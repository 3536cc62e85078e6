#pragma once
/// Ownership and Tpetra maps for the unknowns of the monolithic system.
///
/// Cells are owned as the partitioner says; nodes as node_owners() says (the rank
/// of its cells, or one of two ranks that share it). With F unknowns per node (DofLayout: 1 for
/// heat conduction alone, 3 for displacement alone, 4 for both), unknowns by global id:
///   F n + s          node n, slot s of the node's fields in the order temperature,
///                    displacement x, y, z (the fields the layout has: DofLayout::slot)
/// Owned maps hold this rank's unknowns; overlap maps add those of every node
/// touched by its cells and by the gap faces whose side-a cell it owns, and (with
/// contact) the twin of every touched gap node, for assembly and for gathering: with a
/// pairing's rows, a touched node j or partner k brings the whole row (j and all its partners).
#include "mesh/mesh.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>

#include <utility>
#include <vector>

namespace kiln
{
using Map = Tpetra::Map<>;
using GO = Map::global_ordinal_type;
using LO = Map::local_ordinal_type;

enum class Field : int
{
  T = 0,
  ux = 1,
  uy = 2,
  uz = 3
};
/// A Tpetra map holding `gids` on this rank (in this order).
Teuchos::RCP<const Map> make_map(const std::vector<GO> &gids,
                                 const Teuchos::RCP<const Teuchos::Comm<int>> &comm);

/// Which unknowns the system has.
struct DofLayout
{
  bool temperature = true;  ///< a temperature unknown per node
  bool displacement = true; ///< three displacement unknowns per node
  /// Contact across the gap: the pressures are condensed into the pairs' displacement
  /// unknowns, which mix the two nodes of a pair (CoupledProblem), so every gap node couples
  /// with its twin's couplings. No unknowns of its own.
  bool contact = true;

  int n_node_fields() const { return (temperature ? 1 : 0) + (displacement ? 3 : 0); }
  /// The index of field f among a node's unknowns, or -1 if the layout lacks it.
  int slot(const Field f) const
  {
    if (f == Field::T)
      return temperature ? 0 : -1;
    if (!displacement)
      return -1;
    return static_cast<int>(f) - (temperature ? 0 : 1);
  }
  bool has(const Field f) const { return slot(f) >= 0; }
};

class DofManager
{
public:
  /// `partner_links`: the links (j, k) of a pairing's rows, node j to its partner k
  /// (partner_links() of contact/contact_interface.hpp), besides the split gaps' pairs
  /// (Mesh::gap_pairs): with contact, a node's partners are its twins, both ways.
  DofManager(const Mesh &mesh, const std::vector<int> &cell_rank,
             const Teuchos::RCP<const Teuchos::Comm<int>> &comm, DofLayout layout = {},
             const std::vector<std::pair<int, int>> &partner_links = {});

  const DofLayout &layout() const { return layout_; }
  int n_node_fields() const { return n_node_fields_; }

  const std::vector<int> &owned_cells() const { return owned_cells_; }
  const std::vector<int> &owned_nodes() const { return owned_nodes_; }
  const std::vector<int> &overlap_nodes() const { return overlap_nodes_; }
  const std::vector<int> &node_owner() const { return node_owner_; }

  /// The global id of field f of node n; the layout must have f.
  GO dof(const int node, const Field f) const { return node_dof(node, layout_.slot(f)); }
  /// The global id of unknown `slot` (0 <= slot < n_node_fields()) of node n.
  GO node_dof(const int node, const int slot) const
  {
    return static_cast<GO>(n_node_fields_) * node + slot;
  }
  /// The partners of node n: its twins across the gaps (one on a single gap,
  /// more where gaps cross; none off the gaps) and its partners in the rows of pairings (a
  /// row's node j and its partners k, both ways), as [begin, end).
  std::pair<const int *, const int *> partners(const int node) const
  {
    return {twin_nodes_.data() + twin_offsets_[node], twin_nodes_.data() + twin_offsets_[node + 1]};
  }

  Teuchos::RCP<const Map> owned_node_map() const { return owned_node_map_; }
  Teuchos::RCP<const Map> overlap_node_map() const { return overlap_node_map_; }
  Teuchos::RCP<const Map> owned_dof_map() const { return owned_dof_map_; }
  Teuchos::RCP<const Map> overlap_dof_map() const { return overlap_dof_map_; }
  /// owned -> overlap (gather ghost values)
  Teuchos::RCP<const Tpetra::Import<>> dof_importer() const { return dof_importer_; }
  /// overlap -> owned (sum assembled contributions)
  Teuchos::RCP<const Tpetra::Export<>> dof_exporter() const { return dof_exporter_; }

  GO n_global_dofs() const;
  std::size_t n_owned_dofs() const;

private:
  DofLayout layout_;
  int n_node_fields_;
  std::vector<int> owned_cells_;
  std::vector<int> owned_nodes_;
  std::vector<int> overlap_nodes_;
  std::vector<int> twin_offsets_; ///< per mesh node, into twin_nodes_ (CSR)
  std::vector<int> twin_nodes_;
  std::vector<int> node_owner_;
  Teuchos::RCP<const Map> owned_node_map_;
  Teuchos::RCP<const Map> overlap_node_map_;
  Teuchos::RCP<const Map> owned_dof_map_;
  Teuchos::RCP<const Map> overlap_dof_map_;
  Teuchos::RCP<const Tpetra::Import<>> dof_importer_;
  Teuchos::RCP<const Tpetra::Export<>> dof_exporter_;
};
} // namespace kiln
