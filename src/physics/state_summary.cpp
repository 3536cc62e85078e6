#include "physics/state_summary.hpp"

#include "contact/gap_opening.hpp"
#include "discretization/element_values.hpp"
#include "mesh/hex_geometry.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kiln
{
void summarize_temperature(const Mesh &mesh, const DofManager &dofs, const NodalFields &fields,
                           const BlockHeatConductionKernel &conduction, StateSummary &summary)
{
  const auto &comm = *dofs.owned_dof_map()->getComm();
  if (!dofs.layout().temperature)
    return;
  // One material of constant rho c: ∫ H = rho c ∫ T.
  const bool linear =
      conduction.kernels().size() == 1 && conduction.kernels().front().enthalpy().is_linear();
  double sums[3] = {0.0, 0.0, 0.0}; // ∫T, ∫1, ∫H(T)
  ElementValues fe;
  for (const int c : dofs.owned_cells())
  {
    fe.reinit(mesh, c);
    const HeatConductionKernel &kernel = conduction.of_cell(c);
    // H as the capacity term sees it: at the point (consistent), or at the nodes (lumped).
    const bool lumped = kernel.capacity() == HeatConductionKernel::Capacity::lumped;
    for (int q = 0; q < fe.n_qpoints(); ++q)
    {
      double T = 0.0, H = 0.0;
      for (int i = 0; i < fe.n_shape(); ++i)
      {
        const double T_i = fields.T(mesh.cell_nodes(c)[i]);
        T += fe.shape(i, q) * T_i;
        if (!linear && lumped)
          H += fe.shape(i, q) * kernel.enthalpy().value(T_i);
      }
      sums[0] += T * fe.JxW(q);
      sums[1] += fe.JxW(q);
      if (!linear)
        sums[2] += (lumped ? H : kernel.enthalpy().value(T)) * fe.JxW(q);
    }
  }
  if (linear)
    sums[2] = conduction.kernels().front().enthalpy().heat_capacity(0.0) * sums[0];
  double totals[3] = {0.0, 0.0, 0.0};
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 3, sums, totals);
  double T_min = std::numeric_limits<double>::infinity(), T_max = -T_min;
  for (const int n : dofs.owned_nodes())
  {
    T_min = std::min(T_min, fields.T(n));
    T_max = std::max(T_max, fields.T(n));
  }
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, T_min, Teuchos::outArg(summary.T_min));
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, T_max, Teuchos::outArg(summary.T_max));
  summary.T_mean = totals[0] / totals[1];
  summary.thermal_energy = totals[2];
}

void summarize_displacement(const DofManager &dofs, const NodalFields &fields,
                            StateSummary &summary)
{
  if (!dofs.layout().displacement)
    return;
  double largest = 0.0;
  for (const int n : dofs.owned_nodes())
    largest = std::max(largest, std::sqrt(dot(fields.u(n), fields.u(n))));
  Teuchos::reduceAll(*dofs.owned_dof_map()->getComm(), Teuchos::REDUCE_MAX, largest,
                     Teuchos::outArg(summary.max_displacement));
}

void summarize_contact(const std::vector<const InterfaceStrategy *> &interfaces,
                       const NodalFields &fields, const Teuchos::Comm<int> &comm,
                       StateSummary &summary)
{
  if (interfaces.empty())
    return;
  const std::size_t n_gaps = interfaces.front()->interface().mesh().gap_side_sets.size();
  // Per gap: in contact, area, force, loaded (sums); g, -g (maxima).
  std::vector<double> sums(4 * n_gaps, 0.0),
      extremes(2 * n_gaps, -std::numeric_limits<double>::infinity());
  std::vector<int> n_pairs(n_gaps, 0);
  // Per pairing: rows in contact, area in contact, force, loaded (sums).
  std::vector<double> pair_sums;
  for (const InterfaceStrategy *contact : interfaces)
  {
    const ContactInterface &interface = contact->interface();
    if (!interface.split())
    {
      PairFigures pair;
      pair.name = interface.name();
      pair.n_rows = interface.n_rows();
      summary.pairs.push_back(pair);
      double sums_of_pair[4] = {0.0, 0.0, 0.0, 0.0};
      const auto &owned = interface.owned_rows();
      for (std::size_t i = 0; i < owned.size(); ++i)
        if (contact->active()[i])
        {
          const double area = interface.rows()[owned[i]].area;
          sums_of_pair[0] += 1.0;
          sums_of_pair[1] += area;
          sums_of_pair[2] += area * contact->pressure()[i];
          sums_of_pair[3] += carries_load(contact->pressure()[i], interface.modulus()) ? 1.0 : 0.0;
        }
      pair_sums.insert(pair_sums.end(), sums_of_pair, sums_of_pair + 4);
      continue;
    }
    const std::size_t g = static_cast<std::size_t>(interface.gap());
    n_pairs[g] += interface.n_rows();
    const auto &owned = interface.owned_rows();
    for (std::size_t i = 0; i < owned.size(); ++i)
    {
      const ContactInterface::Row &pair = interface.rows()[owned[i]];
      const double opening = gap_opening(pair.normal, fields.u(pair.a()), fields.u(pair.node));
      extremes[2 * g] = std::max(extremes[2 * g], opening);
      extremes[2 * g + 1] = std::max(extremes[2 * g + 1], -opening);
      if (contact->active()[i])
      {
        sums[4 * g] += 1.0;
        sums[4 * g + 1] += pair.area;
        sums[4 * g + 2] += pair.area * contact->pressure()[i];
        sums[4 * g + 3] += carries_load(contact->pressure()[i], interface.modulus()) ? 1.0 : 0.0;
      }
    }
  }
  std::vector<double> totals(sums.size(), 0.0), maxima(extremes.size(), 0.0);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(sums.size()), sums.data(),
                     totals.data());
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, static_cast<int>(extremes.size()), extremes.data(),
                     maxima.data());
  std::vector<double> pair_totals(pair_sums.size(), 0.0);
  if (!pair_sums.empty())
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(pair_sums.size()),
                       pair_sums.data(), pair_totals.data());
  for (std::size_t p = 0; p < summary.pairs.size(); ++p)
  {
    summary.pairs[p].n_active = static_cast<int>(pair_totals[4 * p]);
    summary.pairs[p].contact_area = pair_totals[4 * p + 1];
    summary.pairs[p].normal_force = pair_totals[4 * p + 2];
    summary.pairs[p].n_loaded = static_cast<int>(pair_totals[4 * p + 3]);
  }
  summary.gaps.assign(n_gaps, GapFigures{});
  double all_max[2] = {-std::numeric_limits<double>::infinity(),
                       -std::numeric_limits<double>::infinity()};
  for (std::size_t g = 0; g < n_gaps; ++g)
  {
    GapFigures &gap = summary.gaps[g];
    gap.n_pairs = n_pairs[g];
    gap.n_active = static_cast<int>(totals[4 * g]);
    gap.contact_area = totals[4 * g + 1];
    gap.normal_force = totals[4 * g + 2];
    gap.n_loaded = static_cast<int>(totals[4 * g + 3]);
    gap.max_opening = gap.n_pairs > 0 ? maxima[2 * g] : 0.0;
    gap.min_opening = gap.n_pairs > 0 ? -maxima[2 * g + 1] : 0.0;
    summary.n_pairs += gap.n_pairs;
    summary.n_active += gap.n_active;
    summary.n_loaded += gap.n_loaded;
    summary.contact_area += gap.contact_area;
    summary.normal_force += gap.normal_force;
    all_max[0] = std::max(all_max[0], maxima[2 * g]);
    all_max[1] = std::max(all_max[1], maxima[2 * g + 1]);
  }
  const bool any = summary.n_pairs > 0;
  summary.max_opening = any ? all_max[0] : 0.0;
  summary.max_penetration = any ? std::max(all_max[1], 0.0) : 0.0;
  summary.min_opening = any ? -all_max[1] : 0.0;
}
} // namespace kiln
