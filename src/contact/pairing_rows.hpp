#pragma once
/// The rows of one pairing of two side sets with the parameters of its kind, as the set-up
/// hands them to CoupledProblem (doc/contact.md, "Separately meshed bodies (issue 30): design").
#include "contact/contact_row.hpp"

#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <string>
#include <vector>

namespace kiln
{
class PairGapHeat;
class PairResearch;

/// A pairing's rows (e.g. MortarPairing's, fixed at set-up) and its interface parameters
/// ("Kind", "Complementarity Scale" and the kind's own, validated as the "Contact" sublist's).
/// The DofManager must have been built with partner_links(rows).
struct PairingRows
{
  std::string name; ///< for messages, e.g. "pair \"pellet\""
  std::vector<ContactRow> rows;
  Teuchos::ParameterList parameters;
  /// The heat across the pair's gap (physics/heat/pair_gap_heat.hpp), null without a term
  /// on; the DofManager must have been given its links() too. Its cells are rebuilt at each
  /// search of the pair (PairGapHeat::rebuild).
  std::shared_ptr<PairGapHeat> heat;
  /// The search redone during a run (contact/pair_research.hpp); the DofManager must have
  /// been given its links() (the margins) instead of partner_links(rows). Null: rows fixed at
  /// set-up (a test's pairing).
  std::shared_ptr<const PairResearch> research;
};
} // namespace kiln
