#include "io/field_catalog.hpp"

namespace kiln
{
const std::vector<FieldDescription> &field_catalog()
{
  static const std::vector<std::string> xyz = {"x", "y", "z"};
  static const std::vector<FieldDescription> catalog = {
      {"temperature", true, {}, "K", "temperature"},
      {"displacement", true, xyz, "m", "displacement"},
      {"stress", false, tensor_components(), "Pa", "Cauchy stress, cell-volume average"},
      {"strain", false, tensor_components(), "-", "total strain, cell-volume average"},
      {"thermal_strain", false, tensor_components(), "-",
       "thermal strain alpha (T - T_ref) I, cell-volume average"},
      {"von_mises_stress", false, {}, "Pa", "von Mises stress of the cell's average stress"},
      {"pressure", false, {}, "Pa", "-tr(sigma)/3 of the cell's average stress"},
      {"principal_stress",
       false,
       {"1", "2", "3"},
       "Pa",
       "principal stresses of the cell's average stress, largest first"},
      {"plastic_strain",
       false,
       {},
       "-",
       "equivalent plastic strain, average over the cell's points (a model with state only)"},
      {"plastic_strain_rate",
       false,
       {},
       "1/s",
       "equivalent plastic strain rate, average over the cell's points (a model with state "
       "only)"},
      {"gap_opening", true, {}, "m", "normal opening of the gap; NaN off the gap"},
      {"contact_pressure",
       true,
       {},
       "Pa",
       "contact pressure across the gap, positive in compression (minus the normal traction), "
       "0 where open; NaN off the gap"},
      {"contact_active",
       true,
       {},
       "-",
       "1 where the gap's pair is in contact, 0 where open; NaN "
       "off the gap"},
      {"gap_heat_flux",
       true,
       {},
       "W/m^2",
       "heat flux across the gap from side a to side b, and at a contact pair's secondary "
       "nodes from the secondary to the primary side; NaN off the gaps and pairs"},
  };
  return catalog;
}

const FieldDescription *describe_field(const std::string &name)
{
  for (const FieldDescription &f : field_catalog())
    if (f.name == name)
      return &f;
  return nullptr;
}
} // namespace kiln
