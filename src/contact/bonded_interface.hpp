#pragma once
/// The interface kind "Bonded".
#include "contact/tied_pairs.hpp"

#include <string>

namespace kiln
{
/// u_b = u_a at every pair: C = c d.(u_b - u_a) on the normal and on every axis the pair's
/// nodes leave free (the two nodes must be constrained alike), always combined. A bonded gap
/// gives the uncut body's answer.
class BondedInterface final : public TiedPairs
{
public:
  static std::string description();
  /// None of its own.
  static Teuchos::ParameterList valid_parameters() { return {}; }

  /// Claims its axes; InputError naming `where` for constraints that conflict with them.
  BondedInterface(const ContactInterface &interface, const DofManager &dofs,
                  NodalConstraints &constraints, const Teuchos::ParameterList &contact,
                  const std::string &where);
};
} // namespace kiln
