#include "app/contact_pairs_setup.hpp"

#include "base/errors.hpp"
#include "contact/contact_interface.hpp"
#include "contact/contact_pairs.hpp"
#include "contact/interface_parameters.hpp"
#include "contact/mortar_pairing.hpp"
#include "contact/pair_research.hpp"
#include "physics/heat/pair_gap_heat.hpp"
#include "physics/materials/material_map.hpp"

#include <memory>
#include <optional>

namespace kiln
{
std::vector<PairingRows> setup_contact_pairs(Mesh &mesh, const Teuchos::ParameterList &params,
                                             const DofLayout &layout, const std::string &input_path)
{
  const Teuchos::ParameterList &contact = params.sublist("Mechanics").sublist("Contact");
  std::vector<PairingRows> pairings;
  for (const ContactPairInput &pair :
       contact_pairs(contact, input_path + ": Kiln/Mechanics/Contact"))
  {
    const MortarPairing pairing(mesh, pair.primary_side_set, pair.secondary_side_set, pair.options,
                                pair.where);
    const std::string name = "pair \"" + pair.name + "\"";
    pairings.push_back(
        {name, pairing.rows(), pair_interface_parameters(contact), nullptr, nullptr});
    mesh.contact_pairs.push_back({pair.name, pair.secondary_side_set});
    // The heat across its gap, on the cells of the same search.
    if (pair.heat_transfer.numParams() > 0)
    {
      KILN_CHECK_INPUT(
          layout.temperature ||
              !MortarGapHeat(pair.heat_transfer, pair.where + "/Heat Transfer").active(),
          pair.where + "/Heat Transfer",
          "carries heat across the pair, but the run has no temperature "
          "(Kiln/\"Physics\" = \"Elasticity\"); set Physics to "
          "\"Thermo-Elasticity\", or remove the Heat Transfer sublist");
    }
    if (layout.temperature && pair.heat_transfer.numParams() > 0)
    {
      // The contact conductance's pressure reads the materials' elastic laws.
      std::optional<MaterialMap> materials;
      if (pair.heat_transfer.isParameter("Gap Pressure Coefficient") &&
          pair.heat_transfer.get<double>("Gap Pressure Coefficient") > 0.0)
        materials.emplace(params, mesh.block_ids(), input_path);
      auto heat = std::make_shared<PairGapHeat>(
          mesh, pair.primary_side_set, pair.secondary_side_set, pairing.search_distance(),
          pair.options.sliding_distance, pair.heat_transfer, pair.where + "/Heat Transfer",
          materials ? &materials->uniform_material() : nullptr, materials ? &*materials : nullptr);
      if (heat->active())
        pairings.back().heat = std::move(heat);
    }
    // The search redone during a run, within the margins (the heat's cells with the rows).
    pairings.back().research =
        std::make_shared<const PairResearch>(mesh, pair.primary_side_set, pair.secondary_side_set,
                                             pair.options, pair.where, name, pairing.margins());
  }
  return pairings;
}

std::vector<std::pair<int, int>> pairing_links(const std::vector<PairingRows> &pairings)
{
  std::vector<std::pair<int, int>> links;
  for (const PairingRows &pairing : pairings)
  {
    const auto more = pairing.research != nullptr ? pairing.research->links(pairing.rows)
                                                  : partner_links(pairing.rows);
    links.insert(links.end(), more.begin(), more.end());
    if (pairing.heat != nullptr)
    {
      const auto heat = pairing.heat->links();
      links.insert(links.end(), heat.begin(), heat.end());
    }
  }
  return links;
}
} // namespace kiln
