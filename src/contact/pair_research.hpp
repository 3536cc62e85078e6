#pragma once
/// The search of a contact pair redone during a run (issue 30; doc/contact.md, "Small
/// sliding"): after an accepted step where a row has slid beyond its slip_limit since the last
/// search, the pair's rows are rebuilt by MortarPairing in the current configuration X + u,
/// within the partners linked at set-up (the margins).
#include "contact/contact_row.hpp"
#include "contact/mortar_pairing.hpp"
#include "mesh/contact_surface.hpp"
#include "mesh/mesh.hpp"

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace kiln
{
class PairResearch
{
public:
  /// The pair of side sets `primary_side_set` and `secondary_side_set` of `mesh` with its
  /// options (as given to MortarPairing at set-up), `where` its path in messages, `name` its
  /// name ("pair \"slide\""), `margins` the set-up pairing's MortarPairing::margins() (per
  /// row of the set-up's rows, whose nodes the rows keep).
  PairResearch(const Mesh &mesh, int primary_side_set, int secondary_side_set,
               const MortarPairingOptions &options, std::string where, std::string name,
               std::vector<std::vector<int>> margins);

  /// The links (j, k) of the set-up rows `rows` (of the margins' rows) to their margins, for
  /// DofManager: a superset of partner_links(rows).
  std::vector<std::pair<int, int>> links(const std::vector<ContactRow> &rows) const;

  /// The mesh nodes of the two surfaces, increasing: rows_at() takes u at these only.
  const std::vector<int> &surface_nodes() const { return surface_nodes_; }
  /// The index of mesh node `node` in surface_nodes(); `node` must be one of them.
  std::size_t surface_index(int node) const;

  /// The rows of the pair searched again at the state `u` (the displacement of the two
  /// surfaces [m], one per node of surface_nodes() in its order, the same on every rank:
  /// gather_displacement) reached at `time` [s], replacing `current`
  /// (the rows in force, of the same nodes as at set-up). Each new row keeps its node, its
  /// normal n_j (the axis its node's frame was closed with at set-up) and its slip limit; takes
  /// the new partners, weights and area D_jj; and has g0 redefined so that the gap is
  /// continuous at u: g0' = g0 + n_j . (d - d'), d = u_j - sum_k w_jk u_k with the old and the
  /// new weights, so that g0' + n_j . d' = g0 + n_j . d; its slip0 is d'. Throws RunError
  /// (the same on every rank: the mesh and u are) naming the pair, the node, the time and
  /// what to change if a node with a row is no longer covered, a node without one has become
  /// covered, or a new partner lies outside the node's margin: the small-sliding limit.
  std::vector<ContactRow> rows_at(const std::vector<ContactRow> &current,
                                  const std::vector<Point> &u, double time) const;

private:
  const Mesh &mesh_;
  MortarPairingOptions options_;
  std::string where_;
  std::string name_;
  std::vector<std::vector<int>> margins_;
  /// The two surfaces as built at construction (in X): a search redone moves copies of them.
  ContactSurface primary_;
  ContactSurface secondary_;
  std::vector<int> surface_nodes_;
};

/// The relative displacement d = u_j - sum_k w_jk u_k of `row` [m].
Point row_relative_displacement(const ContactRow &row, const std::function<Point(int node)> &u);
} // namespace kiln
