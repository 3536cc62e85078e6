#pragma once
/// The set-up of the contact pairs between separately meshed bodies (issue 30; doc/contact.md,
/// "Separately meshed bodies (issue 30): design"): each entry of Mechanics/Contact/Pairs paired
/// by MortarPairing, its heat across the gap (PairGapHeat), and the partner links the DofManager
/// needs for them, before its maps are built.
#include "contact/pairing_rows.hpp"
#include "discretization/dof_manager.hpp"
#include "mesh/mesh.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <utility>
#include <vector>

namespace kiln
{
/// The pairings of the deck `params`' Mechanics/Contact/Pairs on `mesh`, in input order (its
/// materials give a pair's contact conductance its pressure); each pair is added to
/// Mesh::contact_pairs. `input_path` names the input file in messages. Throws
/// InputError as MortarPairing does, and for a Heat Transfer term in a run without
/// temperature (`layout.temperature` false).
std::vector<PairingRows> setup_contact_pairs(Mesh &mesh, const Teuchos::ParameterList &params,
                                             const DofLayout &layout,
                                             const std::string &input_path);

/// The links (j, k) the DofManager needs for `pairings`: their rows' partners and their heat
/// terms' links.
std::vector<std::pair<int, int>> pairing_links(const std::vector<PairingRows> &pairings);
} // namespace kiln
