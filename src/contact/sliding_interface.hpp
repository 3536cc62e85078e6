#pragma once
/// The interface kind "Sliding".
#include "contact/tied_pairs.hpp"

#include <string>

namespace kiln
{
/// g = n.(u_b - u_a) = 0 at every pair: C = c g on the normal axis, always combined, so the
/// normal traction may be a pressure or a tension; nothing tangential (frictionless). Truchas'
/// viscoplastic-ring interface.
class SlidingInterface final : public TiedPairs
{
public:
  static std::string description();
  /// None of its own.
  static Teuchos::ParameterList valid_parameters() { return {}; }

  /// Claims its axes; InputError naming `where` for constraints that conflict with them.
  SlidingInterface(const ContactInterface &interface, const DofManager &dofs,
                   NodalConstraints &constraints, const Teuchos::ParameterList &contact,
                   const std::string &where);
};
} // namespace kiln
