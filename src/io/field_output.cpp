#include "io/field_output.hpp"

#include "contact/gap_opening.hpp"
#include "mesh/contact_surface.hpp"
#include "physics/mechanics/stress_measures.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <limits>

namespace kiln
{
FieldOutput::FieldOutput(CoupledProblem &problem, const Mesh &mesh, const DofManager &dofs)
    : problem_(problem), mesh_(mesh), dofs_(dofs), shown_pair_(mesh.n_nodes(), -1)
{
  for (std::size_t p = 0; p < mesh.gap_pairs.size(); ++p)
    for (const int n : {mesh.gap_pairs[p].node_a, mesh.gap_pairs[p].node_b})
      if (shown_pair_[n] < 0 || mesh.gap_pairs[shown_pair_[n]].gap > mesh.gap_pairs[p].gap)
        shown_pair_[n] = static_cast<int>(p);
  for (const ContactPairSurface &pair : mesh.contact_pairs)
  {
    if (pair_node_area_.empty())
      pair_node_area_.assign(static_cast<std::size_t>(mesh.n_nodes()), 0.0);
    const ContactSurface surface(mesh, pair.secondary_side_set, pair.surface_name());
    for (int j = 0; j < surface.n_nodes(); ++j)
      if (double &area = pair_node_area_[static_cast<std::size_t>(surface.nodes()[j])]; area == 0.0)
        area = surface.nodal_area(j);
  }
}

void FieldOutput::write_gap_field(ResultsWriter &writer, const std::string &name,
                                  const std::vector<double> &per_pair,
                                  const std::vector<double> *at_rows) const
{
  writer.write_gap_field(name, per_pair);
  std::vector<double> owned;
  for (const int n : dofs_.owned_nodes())
    owned.push_back(shown_pair_[n] >= 0  ? per_pair[static_cast<std::size_t>(shown_pair_[n])]
                    : at_rows != nullptr ? (*at_rows)[n]
                                         : std::numeric_limits<double>::quiet_NaN());
  writer.write_node_field(name, 1, owned);
}

void FieldOutput::write(ResultsWriter &writer, const double time, const int cycle, const double dt,
                        const Vector &x)
{
  const DofLayout &layout = dofs_.layout();
  writer.begin_step(time, cycle, dt);
  if (layout.temperature)
    writer.write_node_field("temperature", 1, problem_.node_temperatures(x));
  std::vector<Point> u(dofs_.owned_nodes().size(), Point{});
  if (layout.displacement)
  {
    u = problem_.node_displacements(x);
    std::vector<double> values;
    values.reserve(3 * u.size());
    for (const Point &v : u)
      values.insert(values.end(), v.begin(), v.end());
    writer.write_node_field("displacement", 3, values);
    std::vector<double> stress, strain, thermal_strain, von_mises_stress, mean_pressure,
        principal_stress;
    // The Voigt order of the kernels (xx yy zz xy xz yz) into the written order of
    // tensor_components() (xx yy zz xy yz xz).
    const auto append = [](std::vector<double> &out, const Voigt &v) {
      out.insert(out.end(), {v[0], v[1], v[2], v[3], v[5], v[4]});
    };
    const auto add_cell = [&](const auto &c)
    {
      append(stress, c.stress);
      append(strain, c.strain);
      append(thermal_strain, c.thermal_strain);
      von_mises_stress.push_back(von_mises(c.stress));
      mean_pressure.push_back(pressure(c.stress));
      const auto p = principal_values(c.stress);
      principal_stress.insert(principal_stress.end(), p.begin(), p.end());
    };
    // A model with state: its points are evaluated once, for the stress and the plastic fields
    // (the cells' averages would evaluate them again).
    const bool with_state = problem_.quadrature_state() != nullptr;
    std::vector<ElasticityKernel::PointAverages> points;
    if (with_state)
    {
      points = problem_.point_averages(x);
      for (const auto &c : points)
        add_cell(c);
    }
    else
      for (const auto &c : problem_.cell_averages(x))
        add_cell(c);
    writer.write_cell_field("stress", 6, stress);
    writer.write_cell_field("strain", 6, strain);
    writer.write_cell_field("thermal_strain", 6, thermal_strain);
    writer.write_cell_field("von_mises_stress", 1, von_mises_stress);
    writer.write_cell_field("pressure", 1, mean_pressure);
    writer.write_cell_field("principal_stress", 3, principal_stress);
    if (with_state)
    {
      // Its plastic strain and rate, averaged over each cell's points.
      std::vector<double> plastic_strain, plastic_strain_rate;
      for (const auto &c : points)
      {
        plastic_strain.push_back(c.plastic_strain);
        plastic_strain_rate.push_back(c.plastic_strain_rate);
      }
      writer.write_cell_field("plastic_strain", 1, plastic_strain);
      writer.write_cell_field("plastic_strain_rate", 1, plastic_strain_rate);
    }
  }
  if (problem_.has_contact())
  {
    CoupledProblem::ContactOutput contact = problem_.contact_output(x);
    write_gap_field(writer, "gap_opening", gap_opening(u), &contact.opening);
    // One sign for the gap everywhere: the pressure, positive in compression (+ 0.0: no -0).
    for (double &p : contact.pair_traction)
      p = -p + 0.0;
    for (double &p : contact.traction)
      p = -p + 0.0;
    write_gap_field(writer, "contact_pressure", contact.pair_traction, &contact.traction);
    write_gap_field(writer, "contact_active", contact.pair_active, &contact.active);
  }
  else
    write_gap_field(writer, "gap_opening", gap_opening(u));
  if (layout.temperature && (!mesh_.gap_pairs.empty() || !pair_node_area_.empty()))
  {
    std::vector<double> flux = problem_.gap_heat_flow(x);
    for (std::size_t p = 0; p < flux.size(); ++p)
      flux[p] /= mesh_.gap_pairs[p].area;
    // At the pairs' secondary nodes: the node's heat flow over its share of the area.
    std::vector<double> at_rows;
    if (!pair_node_area_.empty())
    {
      at_rows = problem_.pair_node_heat_flow(x);
      for (std::size_t n = 0; n < at_rows.size(); ++n)
        at_rows[n] = pair_node_area_[n] > 0.0 ? at_rows[n] / pair_node_area_[n]
                                              : std::numeric_limits<double>::quiet_NaN();
    }
    write_gap_field(writer, "gap_heat_flux", flux, at_rows.empty() ? nullptr : &at_rows);
  }
  writer.end_step();
}

std::vector<double> FieldOutput::gap_opening(const std::vector<Point> &u_owned) const
{
  // The mesh is replicated; the displacement of every node is summed over the ranks.
  const int n_nodes = mesh_.n_nodes();
  std::vector<double> local(3 * static_cast<std::size_t>(n_nodes), 0.0), u(local.size(), 0.0);
  if (dofs_.layout().displacement)
  {
    const auto &owned = dofs_.owned_nodes();
    for (std::size_t i = 0; i < owned.size(); ++i)
      for (int d = 0; d < 3; ++d)
        local[3 * owned[i] + d] = u_owned[i][d];
    Teuchos::reduceAll(*dofs_.owned_dof_map()->getComm(), Teuchos::REDUCE_SUM,
                       static_cast<int>(local.size()), local.data(), u.data());
  }
  const auto displacement = [&](const int n) {
    return Point{u[3 * n], u[3 * n + 1], u[3 * n + 2]};
  };
  // The width of the mesh's gap (zero where it was split) plus the opening by the
  // displacement: the displacements are subtracted before they meet the coordinates, which
  // would round them off.
  std::vector<double> opening;
  for (const auto &p : mesh_.gap_pairs)
    opening.push_back(
        kiln::gap_opening(p.normal, mesh_.coordinates[p.node_a], mesh_.coordinates[p.node_b]) +
        kiln::gap_opening(p.normal, displacement(p.node_a), displacement(p.node_b)));
  return opening;
}
} // namespace kiln
