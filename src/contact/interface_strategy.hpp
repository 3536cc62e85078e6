#pragma once
/// The hooks every kind of gap interface fits: the problem holds a list of strategies and
/// calls the same hooks on each (4C's contact AbstractStrategy in Kiln's terms; doc/contact.md,
/// "Interface kinds").
#include "base/registry.hpp"
#include "contact/contact_interface.hpp"
#include "discretization/assembler.hpp"
#include "discretization/local_system.hpp"
#include "discretization/nodal_constraints.hpp"

#include <Teuchos_FancyOStream.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Tpetra_Vector.hpp>

#include <functional>
#include <string>
#include <vector>

namespace kiln
{
/// An interface across the gap (the pairs of a ContactInterface) whose conditions enter the
/// residual by condensation into the pairs' own unknowns (no unknowns of its own). A strategy
/// - claims axes in the nodal frames when it is created (before NodalConstraints::close());
/// - decides, once per state x, from the assembled rows without interface terms, and writes
///   the rows of F(x) of its pairs (decide());
/// - distributes: combines the Jacobian rows of its pairs in each local system
///   (combine_rows()), and adds the terms of its own rows (add_terms());
/// - says what its Jacobian rows depend on (jacobian_dependencies()), which pairs hold the
///   bodies together (held_directions()), its output fields (node_values()) and its figures
///   (active(), pressure()).
/// Its state is decided from x alone: a checkpoint's x restores it (resume()).
class InterfaceStrategy
{
public:
  using Vector = Tpetra::Vector<>;
  virtual ~InterfaceStrategy() = default;

  // --- Per state x (CoupledProblem takes one decision per x for every strategy) ------------
  /// Decides every pair of this rank's overlap from r, the assembled rows at x without
  /// interface terms (overlap map, read only), and writes the rows of F(x) of those pairs into
  /// R (owned: on entry the assembled rows). u(node): the displacement of an overlap node at
  /// x~. Collective only if the strategy says so.
  virtual void decide(const Assembler &assembler, const Vector &r, Vector &R,
                      const std::function<Point(int node)> &u) = 0;
  /// A Jacobian was evaluated from the last decision. Returns true if the next evaluation must
  /// decide anew (the strategy changed its law). Collective.
  virtual bool jacobian_evaluated() = 0;

  // --- Distribute and add ------------------------------------------------------------------
  /// Combines the Jacobian rows of its pairs of the last decision in a local system in the
  /// nodes' frames (nodes[i]: the mesh node of local node i; the system holds each pair
  /// whole).
  virtual void combine_rows(const std::vector<int> &nodes, LocalSystem &local) const = 0;
  /// Adds the terms of its own rows of the last decision to a Jacobian assembly.
  virtual void add_terms(Assembler &assembler) const = 0;
  /// What its Jacobian rows depend on at the last decision: equal vectors give equal rows.
  virtual std::vector<double> jacobian_dependencies() const = 0;

  // --- Steps -------------------------------------------------------------------------------
  /// Log lines (active-set changes) go to `out`.
  virtual void set_log(Teuchos::RCP<Teuchos::FancyOStream> out) { (void)out; }
  /// A step's Newton solve begins.
  virtual void start_step() {}
  /// The step ending at `time` is accepted at the last decision. Collective.
  virtual void step_accepted(double time) { (void)time; }
  /// A run goes on from a saved state at the last decision. Collective.
  virtual void resume() {}

  // --- What it holds and what it shows -----------------------------------------------------
  /// A direction along which a pair (mesh nodes a and b) holds the two sides together, acting
  /// at point `at` (node a's position; for a pairing's row, a its first partner, b its node j
  /// and `at` its twin point sum_k w_jk X_k).
  struct HeldDirection
  {
    int a = -1;
    int b = -1;
    Point direction{};
    Point at{};
  };
  /// This rank's share (the pairs whose node b it owns): with `all`, every direction its pairs
  /// can hold (the set-up's count of free motions); else those they hold at the last decision.
  virtual std::vector<HeldDirection> held_directions(bool all) const = 0;
  /// A pair of this rank's share (node b owned) that may open (kind "Contact") and carries no
  /// pressure at the last decision: its index in ContactInterface::pairs(), its opening g [m],
  /// the direction it holds or would hold, and whether it holds (held shut, or by its law at
  /// a pressure of round-off).
  struct OpenPair
  {
    int pair = -1;
    double opening = 0.0;
    HeldDirection held;
    bool holds = false;
  };
  /// This rank's pairs that do not hold at the last decision, those held shut, and those that
  /// hold by their law with P <= `zero` [Pa] (none for a kind whose pairs always hold).
  virtual std::vector<OpenPair> open_pairs(double zero) const
  {
    (void)zero;
    return {};
  }
  /// With "Free Motions" = "Minimum Norm" (doc/contact.md, "Free motions while pairs open"):
  /// the pairs (ContactInterface::pairs() order, the same on every rank) that the next
  /// decisions hold shut, g = 0 on their normal, whatever their multiplier; empty: none. A
  /// kind whose pairs always hold ignores it.
  virtual void hold_shut(std::vector<char> shut) { (void)shut; }
  /// At the last decision, per owned pair (ContactInterface::owned_pairs()): whether it holds
  /// (in contact) and the normal pressure P [Pa], positive in compression.
  virtual const std::vector<char> &active() const = 0;
  virtual const std::vector<double> &pressure() const = 0;
  /// Pairs that hold at the last decision, over all ranks. Collective.
  int count_active() const;

  /// Per mesh node, on every rank (collective): the normal traction across the gap at the
  /// last decision (-p, negative in compression) [Pa] and 1/0 for pairs that hold; NaN off the
  /// gap. pair_traction and pair_active: the same per pair (ContactInterface::pairs() order
  /// from node_values(); Mesh::gap_pairs order from CoupledProblem::contact_output()).
  struct NodeValues
  {
    std::vector<double> traction;
    std::vector<double> active;
    std::vector<double> pair_traction;
    std::vector<double> pair_active;
    /// Per mesh node: the opening g_j of a pairing's row at its node j [m], NaN elsewhere
    /// (from CoupledProblem::contact_output() only; empty from node_values()).
    std::vector<double> opening;
  };
  NodeValues node_values() const;

  const ContactInterface &interface() const { return interface_; }

protected:
  InterfaceStrategy(const ContactInterface &interface, const DofManager &dofs)
      : interface_(interface), dofs_(dofs)
  {
  }
  const ContactInterface &interface_;
  const DofManager &dofs_;
};

/// The arguments of every kind's constructor: the pairs, the unknowns, the constraints (the
/// kind claims its axes in the constructor), the validated "Contact" sublist and its path for
/// messages.
using InterfaceKinds =
    Registry<InterfaceStrategy, const ContactInterface &, const DofManager &, NodalConstraints &,
             const Teuchos::ParameterList &, const std::string &>;
/// Every interface kind Kiln has, by the name of Contact/"Kind" (interface_kinds.cpp: one line
/// per kind).
const InterfaceKinds &interface_kinds();
} // namespace kiln
