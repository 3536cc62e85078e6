#include "physics/heat/pair_gap_heat.hpp"

#include "base/errors.hpp"
#include "contact/face_search.hpp"
#include "discretization/element_values.hpp"
#include "mesh/contact_surface.hpp"
#include "physics/nodal_fields.hpp"

#include <algorithm>

namespace kiln
{
PairGapHeat::PairGapHeat(const Mesh &mesh, const int primary_side_set, const int secondary_side_set,
                         const double search_distance, const Teuchos::ParameterList &heat_transfer,
                         const std::string &where, const Material *material,
                         const MaterialMap *materials)
    : mesh_(mesh), heat_(heat_transfer, where)
{
  if (!heat_.active())
    return;
  const ContactSurface primary(mesh, primary_side_set, where);
  const ContactSurface secondary(mesh, secondary_side_set, where);
  const FaceSearch search(primary);
  for (MortarGapCell &cell : MortarGapHeat::cells(secondary, primary, search, search_distance))
  {
    // As the pair's rows: a primary face looking the same way (the far side of a thin body)
    // is not the other side of the gap.
    if (dot(secondary.face_area_vector(cell.secondary_face),
            primary.face_area_vector(cell.primary_face)) >= 0.0)
      continue;
    std::vector<int> nodes = MortarGapHeat::nodes(secondary, primary, cell);
    const std::array<int, 2> mesh_cells{secondary.face_cell(cell.secondary_face),
                                        primary.face_cell(cell.primary_face)};
    if (heat_.pressure_coefficient() > 0.0)
    {
      // The contact pressure reads every node of the two cells: they follow the faces'.
      std::array<std::vector<int>, 2> locals;
      for (int side = 0; side < 2; ++side)
        for (const int n : mesh.cell_nodes(mesh_cells[side]))
        {
          auto it = std::find(nodes.begin(), nodes.end(), n);
          if (it == nodes.end())
            it = nodes.insert(nodes.end(), n);
          locals[side].push_back(static_cast<int>(it - nodes.begin()));
        }
      mesh_cells_.push_back(mesh_cells);
      cell_locals_.push_back(std::move(locals));
    }
    nodes_.push_back(std::move(nodes));
    owning_cells_.push_back(mesh_cells[0]);
    n_secondary_.push_back(static_cast<int>(secondary.face_nodes(cell.secondary_face).size()));
    cells_.push_back(std::move(cell));
  }
  if (heat_.pressure_coefficient() > 0.0)
  {
    KILN_ASSERT(material != nullptr, "PairGapHeat: the contact conductance needs the material");
    ContactConductanceKernel::Parameters k;
    k.h0 = 0.0;
    k.length = 1.0; // unused with h0 = 0
    k.pressure_coefficient = heat_.pressure_coefficient();
    std::vector<int> beside;
    for (const auto &pair : mesh_cells_)
      beside.insert(beside.end(), pair.begin(), pair.end());
    contact_ = std::make_unique<const ContactConductanceKernel>(
        ContactConductanceKernel::for_materials(k, *material, mesh, materials, beside,
                                                where + "/\"Gap Pressure Coefficient\"", "is > 0",
                                                "set it to 0 (a constant \"Conductance\" "
                                                "instead), or use an elastic material beside "
                                                "the pair"));
  }
}

std::vector<std::pair<int, int>> PairGapHeat::links() const
{
  std::vector<std::pair<int, int>> links;
  for (std::size_t k = 0; k < cells_.size(); ++k)
  {
    const auto ns = static_cast<std::size_t>(n_secondary_[k]);
    for (std::size_t i = 0; i < ns; ++i)
      for (std::size_t m = ns; m < nodes_[k].size(); ++m)
        links.emplace_back(nodes_[k][i], nodes_[k][m]);
  }
  return links;
}

void PairGapHeat::cell_state(const NodalFields &fields, const FieldSlots &slots,
                             const std::size_t k, std::vector<double> &T, std::vector<Point> &u,
                             std::vector<Point> &x) const
{
  const std::vector<int> &nodes = nodes_[k];
  T.resize(nodes.size());
  u.assign(nodes.size(), Point{0, 0, 0});
  x.resize(nodes.size());
  for (std::size_t a = 0; a < nodes.size(); ++a)
  {
    T[a] = fields.T(nodes[a]);
    x[a] = mesh_.coordinates[nodes[a]];
    if (slots.u >= 0)
      for (int d = 0; d < 3; ++d)
      {
        u[a][d] = fields.u(nodes[a])[d];
        x[a][d] += u[a][d];
      }
  }
}

std::unique_ptr<MortarGapHeat::ContactTerm>
PairGapHeat::contact_term(const std::size_t k, const std::vector<double> &T,
                          const std::vector<Point> &u) const
{
  if (contact_ == nullptr)
    return nullptr;
  const std::size_t n = nodes_[k].size();
  std::vector<Point> dp_du(n, Point{0, 0, 0});
  std::vector<double> dp_dT(n, 0.0);
  ElementValues fe_s, fe_m;
  fe_s.reinit(mesh_, mesh_cells_[k][0]);
  fe_m.reinit(mesh_, mesh_cells_[k][1]);
  const std::array<std::vector<int>, 2> &locals = cell_locals_[k];
  const double p = contact_->pressure(
      cells_[k].normal, fe_s, fe_m, {locals[0].data(), static_cast<int>(locals[0].size())},
      {locals[1].data(), static_cast<int>(locals[1].size())}, mesh_cells_[k], T, u, dp_du, dp_dT);
  auto term = std::make_unique<MortarGapHeat::ContactTerm>();
  term->h = contact_->conductance(0.0, p);
  const double dh_dp = contact_->conductance_pressure_derivative(p);
  term->dh_du.resize(n);
  term->dh_dT.resize(n);
  for (std::size_t a = 0; a < n; ++a)
  {
    for (int d = 0; d < 3; ++d)
      term->dh_du[a][d] = dh_dp * dp_du[a][d];
    term->dh_dT[a] = dh_dp * dp_dT[a];
  }
  return term;
}

void PairGapHeat::evaluate(const NodalFields &fields, const FieldSlots &slots, const int n_fields,
                           const bool jacobian, const std::vector<char> &owns_cell,
                           const Sink &sink) const
{
  std::vector<double> T;
  std::vector<Point> u, x;
  for (std::size_t k = 0; k < cells_.size(); ++k)
    if (owns_cell[owning_cells_[k]])
    {
      cell_state(fields, slots, k, T, u, x);
      LocalSystem local(static_cast<int>(nodes_[k].size()), n_fields, jacobian);
      heat_.evaluate(cells_[k], T, x, slots, local, contact_term(k, T, u).get());
      sink(nodes_[k], local);
    }
}

double PairGapHeat::heat_flow(const NodalFields &fields, const FieldSlots &slots,
                              const std::vector<char> &owns_cell) const
{
  double total = 0.0;
  std::vector<double> T;
  std::vector<Point> u, x;
  for (std::size_t k = 0; k < cells_.size(); ++k)
    if (owns_cell[owning_cells_[k]])
    {
      cell_state(fields, slots, k, T, u, x);
      total += heat_.heat_flow(cells_[k], T, x, contact_term(k, T, u).get());
    }
  return total;
}

void PairGapHeat::add_node_heat_flow(const NodalFields &fields, const FieldSlots &slots,
                                     const std::vector<char> &owns_cell,
                                     std::vector<double> &flow) const
{
  // The secondary rows of the residual: R_i = Σ_q w_q N_i(xi_s) q.
  std::vector<double> T;
  std::vector<Point> u, x;
  for (std::size_t k = 0; k < cells_.size(); ++k)
    if (owns_cell[owning_cells_[k]])
    {
      cell_state(fields, slots, k, T, u, x);
      const int n_fields = std::max(slots.T, slots.u + 2) + 1;
      LocalSystem local(static_cast<int>(nodes_[k].size()), n_fields, false);
      heat_.evaluate(cells_[k], T, x, slots, local, contact_term(k, T, u).get());
      for (int i = 0; i < n_secondary_[k]; ++i)
        flow[static_cast<std::size_t>(nodes_[k][static_cast<std::size_t>(i)])] +=
            local.residual(slots.T, i);
    }
}
} // namespace kiln
