#include "physics/heat/pair_gap_heat.hpp"

#include "contact/face_search.hpp"
#include "mesh/contact_surface.hpp"
#include "physics/nodal_fields.hpp"

namespace kiln
{
PairGapHeat::PairGapHeat(const Mesh &mesh, const int primary_side_set, const int secondary_side_set,
                         const double search_distance, const Teuchos::ParameterList &heat_transfer,
                         const std::string &where)
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
    nodes_.push_back(MortarGapHeat::nodes(secondary, primary, cell));
    owning_cells_.push_back(secondary.face_cell(cell.secondary_face));
    n_secondary_.push_back(static_cast<int>(secondary.face_nodes(cell.secondary_face).size()));
    cells_.push_back(std::move(cell));
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
                             const std::size_t k, std::vector<double> &T,
                             std::vector<Point> &x) const
{
  const std::vector<int> &nodes = nodes_[k];
  T.resize(nodes.size());
  x.resize(nodes.size());
  for (std::size_t a = 0; a < nodes.size(); ++a)
  {
    T[a] = fields.T(nodes[a]);
    x[a] = mesh_.coordinates[nodes[a]];
    if (slots.u >= 0)
      for (int d = 0; d < 3; ++d)
        x[a][d] += fields.u(nodes[a])[d];
  }
}

void PairGapHeat::evaluate(const NodalFields &fields, const FieldSlots &slots, const int n_fields,
                           const bool jacobian, const std::vector<char> &owns_cell,
                           const Sink &sink) const
{
  std::vector<double> T;
  std::vector<Point> x;
  for (std::size_t k = 0; k < cells_.size(); ++k)
    if (owns_cell[owning_cells_[k]])
    {
      cell_state(fields, slots, k, T, x);
      LocalSystem local(static_cast<int>(nodes_[k].size()), n_fields, jacobian);
      heat_.evaluate(cells_[k], T, x, slots, local);
      sink(nodes_[k], local);
    }
}

double PairGapHeat::heat_flow(const NodalFields &fields, const FieldSlots &slots,
                              const std::vector<char> &owns_cell) const
{
  double total = 0.0;
  std::vector<double> T;
  std::vector<Point> x;
  for (std::size_t k = 0; k < cells_.size(); ++k)
    if (owns_cell[owning_cells_[k]])
    {
      cell_state(fields, slots, k, T, x);
      total += heat_.heat_flow(cells_[k], T, x);
    }
  return total;
}
} // namespace kiln
