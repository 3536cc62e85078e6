#pragma once
/// The pairing across the gap: its rows (secondary node, partners and weights, area, normal,
/// initial gap), their complementarity constants and owners.
#include "contact/contact_row.hpp"
#include "discretization/dof_manager.hpp"
#include "mesh/mesh.hpp"

#include <string>
#include <utility>
#include <vector>

namespace kiln
{
/// The rows a kind condenses into (doc/contact.md, "Separately meshed bodies (issue 30):
/// design", "The shape"). Two sources:
/// - a split gap (Mesh::gap_pairs whose `gap` it is): per pair (a, b) the row of node b with
///   the one partner a of weight 1, D = A (∫φ_a over side a's gap faces), g0 = 0 and n from a
///   to b; its kinds keep the symmetric multiplier (R_b - R_a)/(2A) (split());
/// - a list of rows (a mortar pairing of two side sets): several partners, a geometric g0;
///   the multiplier of row j is R_(j,n)/D_jj.
/// A row belongs to the rank that owns its node j. The interface kinds (InterfaceStrategy)
/// claim their axes in the nodes' frames and decide the rows' conditions.
class ContactInterface
{
public:
  struct Row : ContactRow
  {
    double c = 0.0; ///< the complementarity constant c = s (lambda + 2G)/sqrt(D_jj) [Pa/m]
    /// The split gap's node a (the one partner); node b is `node`.
    int a() const { return partners.front(); }
  };

  /// The rows of gap `gap` (an index into Mesh::gap_side_sets). `modulus` is lambda + 2G
  /// [Pa], `scale` the input's "Complementarity Scale".
  ContactInterface(const Mesh &mesh, const DofManager &dofs, int gap, double modulus, double scale);
  /// The rows of a pairing (e.g. MortarPairing's), named `name` in messages. The DofManager
  /// must have been given their partner_links().
  ContactInterface(const Mesh &mesh, const DofManager &dofs, std::vector<ContactRow> rows,
                   double modulus, double scale, std::string name);

  /// Replaces a pairing's rows by `rows` of the same nodes in the same order (its search
  /// redone during a run, PairResearch); c follows the new areas. Their partners must be among
  /// the links the DofManager was given (the margins). Counts a search.
  void replace_rows(std::vector<ContactRow> rows);
  /// The searches that made the rows: 1 at set-up, one more per replace_rows().
  int searches() const { return searches_; }
  /// Sets the count of searches (a restart, from the checkpoint).
  void set_searches(const int searches) { searches_ = searches; }

  const Mesh &mesh() const { return mesh_; }
  const std::vector<Row> &rows() const { return rows_; }
  int n_rows() const { return static_cast<int>(rows_.size()); }
  /// The rows whose node j this rank owns, increasing.
  const std::vector<int> &owned_rows() const { return owned_rows_; }
  /// The gap side set index of a split gap, or -1 for a pairing's rows.
  int gap() const { return gap_; }
  /// Whether the rows are a split gap's (one partner, the symmetric multiplier).
  bool split() const { return gap_ >= 0; }
  /// The pairing's name in messages (the split gap's: "gap side set <id>").
  const std::string &name() const { return name_; }
  /// lambda + 2G [Pa] (the problem's scale of the pressures).
  double modulus() const { return modulus_; }
  /// The rows with `node` among their partners (several where gaps cross), as [begin, end).
  std::pair<const int *, const int *> rows_of_partner(const int node) const
  {
    return {rows_of_partner_.data() + offsets_[node], rows_of_partner_.data() + offsets_[node + 1]};
  }
  /// The row whose node j is `node`, or -1.
  int row_of_node(const int node) const { return row_of_node_[node]; }

private:
  void index(const DofManager &dofs);
  void index_partners();

  const Mesh &mesh_;
  int gap_ = -1;
  std::string name_;
  std::vector<Row> rows_;
  std::vector<int> owned_rows_;
  std::vector<int> offsets_;         ///< per mesh node, into rows_of_partner_ (CSR)
  std::vector<int> rows_of_partner_; ///< the rows of each partner node, increasing
  std::vector<int> row_of_node_;     ///< per mesh node, its row as node j, or -1
  int searches_ = 1;
  double modulus_ = 0.0; ///< lambda + 2G [Pa]
  double c_scale_ = 0.0; ///< a pairing's s (lambda + 2G) [Pa]: c = this / sqrt(D_jj)
};

/// A pressure P [Pa] of a pair in contact is above round-off if P > round_off_strain times the
/// interface's lambda + 2G (the pressures of round-off at which the bodies touch before they
/// close with "Free Motions" = "Minimum Norm" are at most 1.1e-6 Pa on the split-and-pair
/// contact box, the smallest real ones there kPa; 1e-12 of lambda + 2G is 0.27 Pa for steel).
constexpr double round_off_strain = 1e-12;
/// Whether a pair in contact with pressure `P` [Pa] carries a load above round-off at an
/// interface of lambda + 2G = `modulus` [Pa].
inline bool carries_load(const double P, const double modulus)
{
  return P > round_off_strain * modulus;
}

/// The links (j, k) of rows to their partners, for DofManager (which makes both ways).
std::vector<std::pair<int, int>> partner_links(const std::vector<ContactRow> &rows);
} // namespace kiln
