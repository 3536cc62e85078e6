#pragma once
/// The "Contact" sublist of "Mechanics": the gap interface's kind and parameters.
#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace kiln
{
/// "Enabled", "Kind" (interface_kinds()), "Complementarity Scale" and every kind's own
/// parameters.
Teuchos::ParameterList interface_parameters();
/// Throws InputError (naming `path`) if the validated sublist `contact` gives a parameter of
/// another kind than its "Kind", or a "Gaps" entry whose "Side Set" is not one of
/// `gap_side_sets` or is named twice; and the same for every gap's own parameters.
void check_interface_parameters(const Teuchos::ParameterList &contact,
                                const std::vector<int> &gap_side_sets, const std::string &path);
/// The parameters of the gap at side set `side_set`: those of `contact` (validated), replaced
/// by those its "Gaps" entry for that side set gives.
Teuchos::ParameterList gap_interface_parameters(const Teuchos::ParameterList &contact,
                                                int side_set);
/// The parameters of every pair of Contact/Pairs: those of `contact` (validated), without its
/// "Gaps" and "Pairs".
Teuchos::ParameterList pair_interface_parameters(const Teuchos::ParameterList &contact);
} // namespace kiln
