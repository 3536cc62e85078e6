#pragma once
/// The input of the contact pairs between separately meshed bodies (issue 30):
/// `Mechanics/Contact/Pairs`, a sublist of pairs named by the user, each with its two side
/// sets and the options of its mortar pairing (MortarPairing). The kinds and their parameters
/// stay Contact's; the split gaps stay in `Contact/Gaps`.
#include "contact/mortar_pairing.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace kiln
{
/// One entry of Contact/Pairs, read and checked.
struct ContactPairInput
{
  std::string name;  ///< the entry's name in the input
  std::string where; ///< its path in messages: `path`/Pairs/"name"
  int primary_side_set = 0;
  int secondary_side_set = 0; ///< the finer or softer side: the pressure lives there
  MortarPairingOptions options;
  /// The validated "Heat Transfer" sublist (MortarGapHeat::valid_parameters(), declared by
  /// MechanicalPhysics::valid_parameters(): the heat terms live in physics); empty if the
  /// parameters were not declared.
  Teuchos::ParameterList heat_transfer;
};

/// The parameters of one pair (declared as Contact's "Pairs", interface_parameters()):
/// "Primary Side Set", "Secondary Side Set" (both required), "Search Distance", "Penetration
/// Tolerance", "Search Update Fraction", "Sliding Distance".
Teuchos::ParameterList contact_pair_parameters();

/// The pairs of the validated Contact sublist `contact`, in the input's order; `path` names
/// `contact` in messages ("in.xml: Kiln/Mechanics/Contact"). Throws InputError naming the
/// pair's side set parameter if it is not given, or its "Search Update Fraction" if it is 0.
std::vector<ContactPairInput> contact_pairs(const Teuchos::ParameterList &contact,
                                            const std::string &path);
} // namespace kiln
