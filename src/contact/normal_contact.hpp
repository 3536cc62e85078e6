#pragma once
/// The interface kind "Contact": frictionless normal contact by condensed pressures, with a
/// complementarity function and an active-set monitor.
#include "contact/active_set_monitor.hpp"
#include "contact/complementarity_function.hpp"
#include "contact/condensed_pairs.hpp"

#include <memory>
#include <string>

namespace kiln
{
/// Per pair (doc/contact.md): g = n.(u_b - u_a) >= 0, p >= 0, p g = 0, with the force
/// -p A n on a and p A n on b, written C(P, c g) = 0 with the input's complementarity
/// function on the normal axis (CondensedPairs). A pair whose rows are not combined keeps
/// them: p = 0, the sides move apart freely. After an active-set cycle the rest of the step
/// uses Fischer-Burmeister (ActiveSetMonitor).
class NormalContact final : public CondensedPairs
{
public:
  static std::string description();
  /// Its own parameters in the "Contact" sublist of "Mechanics".
  static Teuchos::ParameterList valid_parameters();

  /// Claims the gap normal of every pair (InputError naming `where` for a constraint that is
  /// not perpendicular to it). `contact`: the validated "Contact" sublist.
  NormalContact(const ContactInterface &interface, const DofManager &dofs,
                NodalConstraints &constraints, const Teuchos::ParameterList &contact,
                const std::string &where);

  bool jacobian_evaluated() override;
  void set_log(Teuchos::RCP<Teuchos::FancyOStream> out) override;
  void start_step() override;
  void step_accepted(double time) override;
  void resume() override;

private:
  ComplementarityFunction::Value law(bool normal, double P, double cg) const override;
  bool holds(double P, double cg) const override;
  /// Per owned pair at the last decision: in contact with a pressure above round-off
  /// (carries_load).
  std::vector<char> loaded() const;

  std::unique_ptr<ComplementarityFunction> function_; ///< the input's
  std::unique_ptr<ComplementarityFunction> fallback_; ///< after a cycle
  ActiveSetMonitor monitor_;
};
} // namespace kiln
