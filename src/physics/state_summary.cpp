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
                           const double rho_c, StateSummary &summary)
{
  const auto &comm = *dofs.owned_dof_map()->getComm();
  if (!dofs.layout().temperature)
    return;
  double sums[3] = {0.0, 0.0, 0.0}; // ∫T, ∫1, ∫rho c T
  ElementValues fe;
  for (const int c : dofs.owned_cells())
  {
    fe.reinit(mesh, c);
    for (int q = 0; q < fe.n_qpoints(); ++q)
    {
      double T = 0.0;
      for (int i = 0; i < fe.n_shape(); ++i)
        T += fe.shape(i, q) * fields.T(mesh.cell_nodes(c)[i]);
      sums[0] += T * fe.JxW(q);
      sums[1] += fe.JxW(q);
    }
  }
  sums[2] = rho_c * sums[0];
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
  double sums[3] = {0.0, 0.0, 0.0}; // in contact, area, force
  double extremes[2] = {-std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity()}; // g, -g
  int n_pairs = 0;
  for (const InterfaceStrategy *contact : interfaces)
  {
    const ContactInterface &interface = contact->interface();
    n_pairs += interface.n_pairs();
    const auto &owned = interface.owned_pairs();
    for (std::size_t i = 0; i < owned.size(); ++i)
    {
      const ContactInterface::Pair &pair = interface.pairs()[owned[i]];
      const double g = gap_opening(pair.normal, fields.u(pair.a), fields.u(pair.b));
      extremes[0] = std::max(extremes[0], g);
      extremes[1] = std::max(extremes[1], -g);
      if (contact->active()[i])
      {
        sums[0] += 1.0;
        sums[1] += pair.area;
        sums[2] += pair.area * contact->pressure()[i];
      }
    }
  }
  double totals[3] = {0.0, 0.0, 0.0}, maxima[2] = {0.0, 0.0};
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 3, sums, totals);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 2, extremes, maxima);
  summary.n_pairs = n_pairs;
  summary.n_active = static_cast<int>(totals[0]);
  summary.contact_area = totals[1];
  summary.normal_force = totals[2];
  summary.max_opening = n_pairs > 0 ? maxima[0] : 0.0;
  summary.max_penetration = n_pairs > 0 ? std::max(maxima[1], 0.0) : 0.0;
  summary.min_opening = n_pairs > 0 ? -maxima[1] : 0.0;
}
} // namespace kiln
