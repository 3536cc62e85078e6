#include "physics/heat/pair_gap_heat.hpp"

#include "base/errors.hpp"
#include "contact/face_search.hpp"
#include "discretization/element_values.hpp"
#include "mesh/contact_surface.hpp"
#include "physics/nodal_fields.hpp"

#include <algorithm>
#include <sstream>

namespace kiln
{
PairGapHeat::PairGapHeat(const Mesh &mesh, const int primary_side_set, const int secondary_side_set,
                         const double search_distance, const double sliding_distance,
                         const Teuchos::ParameterList &heat_transfer, const std::string &where,
                         const Material *material, const MaterialMap *materials)
    : mesh_(mesh), primary_side_set_(primary_side_set), secondary_side_set_(secondary_side_set),
      search_distance_(search_distance), where_(where), heat_(heat_transfer, where)
{
  if (!heat_.active())
    return;
  const ContactSurface primary(mesh, primary_side_set, where);
  const ContactSurface secondary(mesh, secondary_side_set, where);
  for (const ContactSurface *surface : {&primary, &secondary})
    surface_nodes_.insert(surface_nodes_.end(), surface->nodes().begin(), surface->nodes().end());
  std::sort(surface_nodes_.begin(), surface_nodes_.end());
  surface_nodes_.erase(std::unique(surface_nodes_.begin(), surface_nodes_.end()),
                       surface_nodes_.end());
  // The margins: the faces facing each secondary face within the reach plus the sliding
  // distance, as the rows' (MortarPairing::margins()).
  const FaceSearch search(primary);
  margin_faces_.resize(static_cast<std::size_t>(secondary.n_faces()));
  for (int s = 0; s < secondary.n_faces(); ++s)
    for (const int m : search.candidates(secondary.face_box(s), search_distance + sliding_distance))
      if (dot(secondary.face_area_vector(s), primary.face_area_vector(m)) < 0.0)
        margin_faces_[static_cast<std::size_t>(s)].push_back(m);
  set_ = build(nullptr);
  if (heat_.pressure_coefficient() > 0.0)
  {
    KILN_ASSERT(material != nullptr, "PairGapHeat: the contact conductance needs the material");
    ContactConductanceKernel::Parameters k;
    k.h0 = 0.0;
    k.length = 1.0; // unused with h0 = 0
    k.pressure_coefficient = heat_.pressure_coefficient();
    // Every mesh cell a cell within the margins can read.
    std::vector<int> beside;
    for (int s = 0; s < secondary.n_faces(); ++s)
      for (const int m : margin_faces_[static_cast<std::size_t>(s)])
        beside.insert(beside.end(), {secondary.face_cell(s), primary.face_cell(m)});
    contact_ = std::make_unique<const ContactConductanceKernel>(
        ContactConductanceKernel::for_materials(k, *material, mesh, materials, beside,
                                                where + "/\"Gap Pressure Coefficient\"", "is > 0",
                                                "set it to 0 (a constant \"Conductance\" "
                                                "instead), or use an elastic material beside "
                                                "the pair"));
  }
}

std::vector<int> PairGapHeat::block_nodes(const ContactSurface &secondary,
                                          const ContactSurface &primary, const int s, const int m,
                                          std::array<int, 2> &mesh_cells,
                                          std::array<std::vector<int>, 2> &locals) const
{
  std::vector<int> nodes;
  for (const int j : secondary.face_nodes(s))
    nodes.push_back(secondary.nodes()[j]);
  for (const int k : primary.face_nodes(m))
    nodes.push_back(primary.nodes()[k]);
  mesh_cells = {secondary.face_cell(s), primary.face_cell(m)};
  if (heat_.pressure_coefficient() > 0.0)
  {
    // The contact pressure reads every node of the two cells: they follow the faces'.
    for (int side = 0; side < 2; ++side)
    {
      locals[side].clear();
      for (const int n : mesh_.cell_nodes(mesh_cells[side]))
      {
        auto it = std::find(nodes.begin(), nodes.end(), n);
        if (it == nodes.end())
          it = nodes.insert(nodes.end(), n);
        locals[side].push_back(static_cast<int>(it - nodes.begin()));
      }
    }
  }
  return nodes;
}

PairGapHeat::CellSet PairGapHeat::build(const std::vector<Point> *u) const
{
  ContactSurface primary(mesh_, primary_side_set_, where_);
  ContactSurface secondary(mesh_, secondary_side_set_, where_);
  CellSet set;
  if (u != nullptr)
  {
    KILN_ASSERT(u->size() == surface_nodes_.size(), "a displacement per surface node");
    for (ContactSurface *surface : {&primary, &secondary})
    {
      std::vector<Point> v;
      v.reserve(surface->nodes().size());
      for (const int n : surface->nodes())
        v.push_back((*u)[static_cast<std::size_t>(
            std::lower_bound(surface_nodes_.begin(), surface_nodes_.end(), n) -
            surface_nodes_.begin())]);
      surface->set_displacement(v);
    }
    set.u = *u;
  }
  const FaceSearch search(primary);
  for (MortarGapCell &cell : MortarGapHeat::cells(secondary, primary, search, search_distance_))
  {
    // As the pair's rows: a primary face looking the same way (the far side of a thin body)
    // is not the other side of the gap.
    if (dot(secondary.face_area_vector(cell.secondary_face),
            primary.face_area_vector(cell.primary_face)) >= 0.0)
      continue;
    std::array<int, 2> mesh_cells{};
    std::array<std::vector<int>, 2> locals;
    set.nodes.push_back(block_nodes(secondary, primary, cell.secondary_face, cell.primary_face,
                                    mesh_cells, locals));
    if (heat_.pressure_coefficient() > 0.0)
    {
      set.mesh_cells.push_back(mesh_cells);
      set.cell_locals.push_back(std::move(locals));
    }
    set.owning_cells.push_back(mesh_cells[0]);
    set.n_secondary.push_back(static_cast<int>(secondary.face_nodes(cell.secondary_face).size()));
    set.cells.push_back(std::move(cell));
  }
  return set;
}

void PairGapHeat::rebuild(const std::vector<Point> &u, const double time, const std::string &name)
{
  CellSet set = build(&u);
  for (const MortarGapCell &cell : set.cells)
  {
    const std::vector<int> &margin = margin_faces_[static_cast<std::size_t>(cell.secondary_face)];
    if (std::binary_search(margin.begin(), margin.end(), cell.primary_face))
      continue;
    const ContactSurface secondary(mesh_, secondary_side_set_, where_);
    std::ostringstream message;
    message << name << ": at t = " << time
            << " s the heat across the gap, its cells rebuilt in the current configuration, "
               "pairs the secondary face of nodes";
    for (const int j : secondary.face_nodes(cell.secondary_face))
      message << " " << secondary.nodes()[j] + 1;
    message << " (of mesh cell " << secondary.face_cell(cell.secondary_face) + 1
            << ") with a primary face outside its margin of set-up (the faces within \"Search "
               "Distance\" plus \"Sliding Distance\" of it): the pair has slid beyond the "
               "small-sliding limit (doc/contact.md, \"Small sliding\"). Keep the sliding along "
               "this pair within it (a smaller imposed motion or load), or raise the pair's "
               "\"Sliding Distance\" to the largest sliding expected (a larger matrix graph). "
               "The results up to the last accepted step are kept";
    throw RunError(message.str());
  }
  set_ = std::move(set);
}

void PairGapHeat::visit_margin_blocks(
    const std::function<void(int owning_cell, int n_secondary, std::vector<int> nodes)> &visit)
    const
{
  if (margin_faces_.empty())
    return;
  const ContactSurface primary(mesh_, primary_side_set_, where_);
  const ContactSurface secondary(mesh_, secondary_side_set_, where_);
  std::array<int, 2> mesh_cells{};
  std::array<std::vector<int>, 2> locals;
  for (int s = 0; s < secondary.n_faces(); ++s)
    for (const int m : margin_faces_[static_cast<std::size_t>(s)])
    {
      std::vector<int> nodes = block_nodes(secondary, primary, s, m, mesh_cells, locals);
      visit(mesh_cells[0], secondary.face_nodes(s).size(), std::move(nodes));
    }
}

std::vector<std::pair<int, std::vector<int>>> PairGapHeat::margin_blocks() const
{
  std::vector<std::pair<int, std::vector<int>>> blocks;
  visit_margin_blocks([&](const int owning_cell, int, std::vector<int> nodes)
                      { blocks.emplace_back(owning_cell, std::move(nodes)); });
  return blocks;
}

std::vector<std::pair<int, int>> PairGapHeat::links() const
{
  std::vector<std::pair<int, int>> links;
  visit_margin_blocks(
      [&](int, const int n_secondary, const std::vector<int> &nodes)
      {
        // The secondary face's nodes come first.
        const auto ns = static_cast<std::size_t>(n_secondary);
        for (std::size_t i = 0; i < ns; ++i)
          for (std::size_t k = ns; k < nodes.size(); ++k)
            links.emplace_back(nodes[i], nodes[k]);
      });
  std::sort(links.begin(), links.end());
  links.erase(std::unique(links.begin(), links.end()), links.end());
  return links;
}

void PairGapHeat::cell_state(const NodalFields &fields, const FieldSlots &slots,
                             const std::size_t k, std::vector<double> &T, std::vector<Point> &u,
                             std::vector<Point> &x) const
{
  const std::vector<int> &nodes = set_.nodes[k];
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
  const std::size_t n = set_.nodes[k].size();
  std::vector<Point> dp_du(n, Point{0, 0, 0});
  std::vector<double> dp_dT(n, 0.0);
  ElementValues fe_s, fe_m;
  fe_s.reinit(mesh_, set_.mesh_cells[k][0]);
  fe_m.reinit(mesh_, set_.mesh_cells[k][1]);
  const std::array<std::vector<int>, 2> &locals = set_.cell_locals[k];
  const double p = contact_->pressure(set_.cells[k].normal, fe_s, fe_m,
                                      {locals[0].data(), static_cast<int>(locals[0].size())},
                                      {locals[1].data(), static_cast<int>(locals[1].size())},
                                      set_.mesh_cells[k], T, u, dp_du, dp_dT);
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
  for (std::size_t k = 0; k < set_.cells.size(); ++k)
    if (owns_cell[set_.owning_cells[k]])
    {
      cell_state(fields, slots, k, T, u, x);
      LocalSystem local(static_cast<int>(set_.nodes[k].size()), n_fields, jacobian);
      heat_.evaluate(set_.cells[k], T, x, slots, local, contact_term(k, T, u).get());
      sink(set_.nodes[k], local);
    }
}

double PairGapHeat::heat_flow(const NodalFields &fields, const FieldSlots &slots,
                              const std::vector<char> &owns_cell) const
{
  double total = 0.0;
  std::vector<double> T;
  std::vector<Point> u, x;
  for (std::size_t k = 0; k < set_.cells.size(); ++k)
    if (owns_cell[set_.owning_cells[k]])
    {
      cell_state(fields, slots, k, T, u, x);
      total += heat_.heat_flow(set_.cells[k], T, x, contact_term(k, T, u).get());
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
  for (std::size_t k = 0; k < set_.cells.size(); ++k)
    if (owns_cell[set_.owning_cells[k]])
    {
      cell_state(fields, slots, k, T, u, x);
      const int n_fields = std::max(slots.T, slots.u + 2) + 1;
      LocalSystem local(static_cast<int>(set_.nodes[k].size()), n_fields, false);
      heat_.evaluate(set_.cells[k], T, x, slots, local, contact_term(k, T, u).get());
      for (int i = 0; i < set_.n_secondary[k]; ++i)
        flow[static_cast<std::size_t>(set_.nodes[k][static_cast<std::size_t>(i)])] +=
            local.residual(slots.T, i);
    }
}
} // namespace kiln
