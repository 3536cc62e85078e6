#pragma once
/// Ownership and Tpetra maps for the unknowns of the monolithic system.
///
/// Cells are owned as the partitioner says; a node is owned by the lowest rank
/// among its cells; a gap pair (and its contact unknown) by the owner of its
/// node_a. With F unknowns per node (DofLayout: 1 for heat conduction alone,
/// 4 with displacement), unknowns by global id:
///   F n + f          node n, field f (0 temperature, 1-3 displacement x, y, z)
///   F N + k          the contact unknown of gap pair k (N = number of nodes),
///                    when the layout has contact
/// Owned maps hold this rank's unknowns; overlap maps add those of every node
/// (and pair) touched by its cells and by the gap faces whose side-a cell it
/// owns, for assembly and for gathering.
#include "mesh/mesh.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>

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
  int n_node_fields = 4; ///< 1: temperature; 4: temperature and displacement
  bool contact = true;   ///< one contact unknown per gap pair
};

class DofManager
{
public:
  DofManager(const Mesh &mesh, const std::vector<int> &cell_rank,
             const Teuchos::RCP<const Teuchos::Comm<int>> &comm, DofLayout layout = {});

  const DofLayout &layout() const { return layout_; }
  int n_node_fields() const { return layout_.n_node_fields; }

  const std::vector<int> &owned_cells() const { return owned_cells_; }
  const std::vector<int> &owned_nodes() const { return owned_nodes_; }
  const std::vector<int> &overlap_nodes() const { return overlap_nodes_; }
  const std::vector<int> &owned_pairs() const { return owned_pairs_; }
  const std::vector<int> &node_owner() const { return node_owner_; }

  GO dof(const int node, const Field f) const
  {
    return static_cast<GO>(layout_.n_node_fields) * node + static_cast<int>(f);
  }
  GO contact_dof(const int pair) const
  {
    return static_cast<GO>(layout_.n_node_fields) * n_nodes_ + pair;
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
  int n_nodes_;
  std::vector<int> owned_cells_;
  std::vector<int> owned_nodes_;
  std::vector<int> overlap_nodes_;
  std::vector<int> owned_pairs_;
  std::vector<int> node_owner_;
  Teuchos::RCP<const Map> owned_node_map_;
  Teuchos::RCP<const Map> overlap_node_map_;
  Teuchos::RCP<const Map> owned_dof_map_;
  Teuchos::RCP<const Map> overlap_dof_map_;
  Teuchos::RCP<const Tpetra::Import<>> dof_importer_;
  Teuchos::RCP<const Tpetra::Export<>> dof_exporter_;
};
} // namespace kiln
