#pragma once
/// The row algebra shared by the interface kinds: per pair and per claimed axis, a condition
/// C(P, c g) = 0 condensed into the pair's own rows (doc/contact.md).
#include "contact/complementarity_function.hpp"
#include "contact/interface_strategy.hpp"

#include <string>
#include <vector>

namespace kiln
{
/// Per pair (a, b) of a split gap's ContactInterface and per axis d the kind claims (the normal
/// n, from a to b, first; a kind may claim more), with the opening g = d.(u_b - u_a) and the
/// multiplier that balances the pair's assembled rows, P = (R_b - R_a)/(2A) along d (d.u being
/// an unknown of each node), a condition C(P, c g) = 0 decided by the kind (law()). An axis
/// whose rows are combined has rows R_a + R_b - A C(P, c g) (the multiplier cancels; minus the
/// row of b, which makes the row's diagonal the pair's stiffness) and A C(P, c g); the others
/// keep theirs (P = 0: the sides move apart freely along d). The Jacobian is the exact
/// generalized derivative of these rows: the element systems' rows are combined alike
/// (combine_rows()), plus the terms of A C in g (add_terms()).
///
/// The rows of a pairing (several partners k with weights w_jk; doc/contact.md, "Condensation
/// with the dual basis"): axes claimed in node j's frame only, g = (d.n) g0 + d.(u_j - sum_k
/// w_jk u_k), P = R_(j,d)/D_jj, rows (j, d) <- D_jj C and, for each partner k and each free
/// axis q of k's frame (t its dual axes), (k, q) <- R_(k,q) + w_jk (d.t_(k,q)) (R_(j,d) -
/// D_jj C). A partner shared with another interface is not supported (the rows of one would
/// overwrite the other's).
class CondensedPairs : public InterfaceStrategy
{
public:
  void decide(const Assembler &assembler, const Vector &r, Vector &R,
              const std::function<Point(int node)> &u) override;
  void combine_rows(const std::vector<int> &nodes, LocalSystem &local) const override;
  void add_terms(Assembler &assembler) const override;
  /// Per axis of this rank's overlap: whether its rows are combined, dC/dP and dC/d(cg).
  std::vector<double> jacobian_dependencies() const override;
  std::vector<HeldDirection> held_directions(bool all) const override;
  std::vector<OpenPair> open_pairs(double zero) const override;
  void hold_shut(std::vector<char> shut) override { shut_ = std::move(shut); }
  const std::vector<char> &active() const override { return active_; }
  const std::vector<double> &pressure() const override { return pressure_; }

protected:
  /// An axis of a pair: the slot of d.u among the displacement unknowns of nodes a and b;
  /// `normal`: d is the pair's normal n, or with `leaning` the component of n its conditions
  /// leave free (the axis of the nodes' frames); else another axis of the frames.
  struct Axis
  {
    int pair = -1;
    int slot_a = 0;
    int slot_b = 0;
    bool normal = false;
    bool leaning = false;
  };
  CondensedPairs(const ContactInterface &interface, const DofManager &dofs,
                 const NodalConstraints &constraints);
  /// Claims the gap normal of every pair (its first axis): the component of the normal that
  /// the nodes' displacement conditions leave free (none: the pair is held by them, and has
  /// no axis). Where gaps cross, a node's normals need not be perpendicular (the frame is then
  /// not orthonormal: NodalConstraints). Throws InputError (naming `where`) when the two nodes
  /// are constrained in different directions, or a normal lies in the span of the node's other
  /// normals and held directions (NodalConstraints::add_free_axis()).
  void claim_normals(NodalConstraints &constraints, const std::string &where);
  /// Throws InputError (naming `where`) unless the pair's two nodes have the same constrained
  /// directions.
  void check_alike(const NodalConstraints &constraints, const ContactInterface::Row &pair,
                   const std::string &where);
  /// Claims every axis the pair's nodes leave free: the normal, then the coordinate axes, as
  /// NodalConstraints::close() completes a frame. Throws InputError (naming `where`) when the
  /// two nodes of a pair are not constrained alike.
  void claim_free_axes(NodalConstraints &constraints, const std::string &where);
  /// The vectors sized to the axes claimed; called once at the end of a kind's constructor.
  void finish_claims();

  /// The condition of an axis (`normal`: along the pair's normal) at P [Pa] and cg = c g [Pa].
  virtual ComplementarityFunction::Value law(bool normal, double P, double cg) const = 0;
  /// Whether a pair holds at P and c g of its normal axis (zero if it has none; for
  /// active()).
  virtual bool holds(double P, double cg) const = 0;

  const NodalConstraints &constraints_;

private:
  using Row = ContactInterface::Row;
  /// The direction d of axis i (the pair's normal for its first).
  Point direction(std::size_t axis) const;
  /// The rows of a pairing (not a split gap): P = R_(j,d)/D_jj, the rows of j's partners
  /// moved as the class comment says.
  void decide_rows(const Assembler &assembler, const Vector &r, Vector &R,
                   const std::function<Point(int node)> &u);
  void combine_row_rows(const std::vector<int> &nodes, LocalSystem &local) const;
  void add_row_terms(Assembler &assembler) const;
  /// Keeps the figures of owned row `row` (the owned_index-th) at the last decision.
  void record(std::size_t owned_index, int row, bool shut, double P_normal, double cg_normal);
  /// The direction axis of row k holds, at its twin point.
  HeldDirection held_direction(int k, std::size_t axis) const;

  int u_slot_;
  std::vector<Axis> axes_;              ///< by pair, the normal first
  std::vector<std::size_t> first_axis_; ///< per pair, its first axis; one past the last at end
  std::vector<ComplementarityFunction::Value> value_; ///< per axis (those in the overlap)
  std::vector<char> active_;                          ///< per owned pair
  std::vector<double> pressure_;                      ///< per owned pair [Pa]
  std::vector<double> opening_;                       ///< per owned pair, g [m]
  std::vector<char> shut_; ///< per pair: held shut (hold_shut()), or empty
};
} // namespace kiln
