#pragma once
/// Frictionless normal contact across the gap by condensed pressures: the strategy that
/// decides the active set and turns the assembled rows into the contact rows.
#include "contact/active_set_monitor.hpp"
#include "contact/complementarity_function.hpp"
#include "contact/contact_interface.hpp"
#include "discretization/assembler.hpp"

#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace kiln
{
/// Per pair (a, b) of the ContactInterface (doc/contact.md): g = n.(u_b - u_a) >= 0, p >= 0,
/// p g = 0, with the force -p A n on a and p A n on b. The pressure is condensed: from the
/// assembled rows R without contact, P = (R_b - R_a)/(2A) (the normal rows, n.u being an
/// unknown of each node) is the pressure that balances the pair, and the complementarity
/// function decides from P and c g. A pair whose rows are combined has rows
/// R_a + R_b - A C(P, c g) (p cancels; minus the row of b, which makes the row's diagonal the
/// pair's stiffness and keeps Krylov iterations of closed contact near those of open contact)
/// and A C(P, c g); the others keep theirs (p = 0). The Jacobian is the exact
/// generalized derivative of these rows: the element systems' rows are combined alike
/// (combine_rows()), plus the terms of A C in g (add_pair_terms()).
///
/// decide() runs once per state x: the decision and F(x) are kept until x changes, so a
/// Newton iteration assembles the residual once, and its Jacobian only the Jacobian.
class NormalContact
{
public:
  using Vector = Tpetra::Vector<>;
  /// The "Contact" sublist of "Mechanics".
  static Teuchos::ParameterList valid_parameters();

  /// `contact`: the validated "Contact" sublist. Keeps references to its arguments.
  NormalContact(const ContactInterface &interface, const DofManager &dofs,
                const Assembler &assembler, const NodalConstraints &constraints,
                const Teuchos::ParameterList &contact);

  ActiveSetMonitor &monitor() { return monitor_; }

  /// Whether decide() has run at this x (and nothing has changed since). Collective.
  bool decided_at(const Vector &x) const;
  /// Forgets the decision (the time, the constraints or the function changed).
  void invalidate() { decided_ = false; }
  /// Decides every pair of this rank's overlap from R, the assembled rows at x without
  /// contact (owned), and turns R into F(x): the combined pairs' rows. u(node) is the
  /// displacement of an overlap node at x~ (NodalConstraints). Collective.
  void decide(const Vector &x, Vector &R, const std::function<Point(int node)> &u);
  /// F(x) of the last decision (owned).
  const Vector &residual() const { return *F_; }
  /// A Jacobian was evaluated from the last decision: the monitor sees its active set (a
  /// cycle switches the function, and the next state is decided anew).
  void jacobian_evaluated();

  /// With contact every local system that holds a gap node holds its twin: `nodes` with the
  /// twins it lacks appended and `local` extended alike (their rows and columns zero), or
  /// nothing if it lacks none.
  std::optional<std::pair<std::vector<int>, LocalSystem>>
  with_twins(const std::vector<int> &nodes, const LocalSystem &local) const;
  /// Combines the Jacobian rows of the pairs of the last decision in a local system in the
  /// nodes' frames: row b := (dC/dP / 2)(row b - row a), row a := row a + row b - row b'
  /// (row b' the new row b).
  void combine_rows(const std::vector<int> &nodes, LocalSystem &local) const;
  /// Adds the terms of A C in g, A c dC/d(cg) dg/dû, of the owned pairs of the last
  /// decision to a Jacobian assembly.
  void add_pair_terms(Assembler &assembler) const;

  /// What the contact rows of the Jacobian depend on at the last decision: per pair of this
  /// rank's overlap, whether its rows are combined, dC/dP and dC/d(cg). Equal vectors give
  /// equal rows (the min function's are those of the active set).
  std::vector<double> jacobian_dependencies() const;
  /// At the last decision, per owned pair: in contact (P - c g > 0), and P [Pa].
  const std::vector<char> &active() const { return active_; }
  const std::vector<double> &pressure() const { return pressure_; }
  /// Per mesh node, on every rank (collective): the normal traction across the gap at the
  /// last decision (-p, negative in compression) [Pa] and 1/0 for pairs in contact; NaN off
  /// the gap.
  struct NodeValues
  {
    std::vector<double> traction;
    std::vector<double> active;
  };
  NodeValues node_values() const;

private:
  const ContactInterface &interface_;
  const DofManager &dofs_;
  const Assembler &assembler_;
  const NodalConstraints &constraints_;
  int u_slot_;
  std::unique_ptr<ComplementarityFunction> function_; ///< the input's
  std::unique_ptr<ComplementarityFunction> fallback_; ///< after a cycle
  ActiveSetMonitor monitor_;

  // The decision.
  bool decided_ = false;
  Teuchos::RCP<Vector> x_;                            ///< the x it was taken at
  Teuchos::RCP<Vector> F_;                            ///< F(x)
  Teuchos::RCP<Vector> R_overlap_;                    ///< work: R on the overlap map
  std::vector<ComplementarityFunction::Value> value_; ///< per pair (those in the overlap)
  std::vector<char> active_;                          ///< per owned pair
  std::vector<double> pressure_;                      ///< per owned pair [Pa]
};
} // namespace kiln
