#include "physics/state_output.hpp"

#include "base/errors.hpp"
#include "contact/gap_opening.hpp"
#include "discretization/element_values.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace kiln
{
StateOutput::StateOutput(const Mesh &mesh, const DofManager &dofs, const FieldSlots &slots,
                         const NodalFields &fields, const ThermalPhysics *thermal,
                         const MechanicalPhysics *mechanics, const ResidualTerms &terms,
                         const std::vector<std::unique_ptr<InterfaceStrategy>> &interfaces)
    : mesh_(mesh), dofs_(dofs), slots_(slots), fields_(fields), thermal_(thermal),
      mechanics_(mechanics), terms_(terms), interfaces_(interfaces)
{
}

std::vector<double> StateOutput::node_temperatures() const
{
  std::vector<double> T;
  for (const int n : dofs_.owned_nodes())
    T.push_back(fields_.T(n));
  return T;
}

std::vector<Point> StateOutput::node_displacements() const
{
  std::vector<Point> u;
  for (const int n : dofs_.owned_nodes())
    u.push_back(fields_.u(n));
  return u;
}

void StateOutput::for_each_owned_cell(const CellVisitor &visit) const
{
  KILN_ASSERT(mechanics_ != nullptr, "the cell averages need the displacement");
  ElementValues fe;
  std::vector<double> T;
  std::vector<Point> u;
  int cell_local = 0;
  for (const int c : dofs_.owned_cells())
  {
    T.clear();
    u.clear();
    for (const int n : mesh_.cell_nodes(c))
    {
      T.push_back(fields_.T(n));
      u.push_back(fields_.u(n));
    }
    fe.reinit(mesh_, c);
    visit(mechanics_->block_elasticity().of_cell(c), fe, T, u,
          mechanics_->block_elasticity().output_history(cell_local++));
  }
}

std::vector<ElasticityKernel::CellAverages> StateOutput::cell_averages() const
{
  std::vector<ElasticityKernel::CellAverages> result;
  for_each_owned_cell(
      [&result](const ElasticityKernel &kernel, const ElementValues &fe,
                const std::vector<double> &T, const std::vector<Point> &u,
                const ElasticityKernel::PointHistory &history)
      {
        if (!kernel.general())
        {
          result.push_back(kernel.cell_averages(fe, u, T));
          return;
        }
        // The general path: σ, ε and ε_th from the model's points.
        const ElasticityKernel::PointAverages points = kernel.point_averages(fe, u, T, history);
        ElasticityKernel::CellAverages averages{};
        averages.stress = points.stress;
        averages.strain = points.strain;
        averages.thermal_strain = points.thermal_strain;
        result.push_back(averages);
      });
  return result;
}

std::vector<ElasticityKernel::PointAverages> StateOutput::point_averages() const
{
  std::vector<ElasticityKernel::PointAverages> result;
  for_each_owned_cell([&result](const ElasticityKernel &kernel, const ElementValues &fe,
                                const std::vector<double> &T, const std::vector<Point> &u,
                                const ElasticityKernel::PointHistory &history)
                      { result.push_back(kernel.point_averages(fe, u, T, history)); });
  return result;
}

StateOutput::ContactOutput StateOutput::contact_output() const
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::size_t n_pairs = mesh_.gap_pairs.size();
  ContactOutput out{std::vector<double>(mesh_.n_nodes(), nan),
                    std::vector<double>(mesh_.n_nodes(), nan), std::vector<double>(n_pairs, nan),
                    std::vector<double>(n_pairs, nan), std::vector<double>(mesh_.n_nodes(), nan)};
  if (interfaces_.empty())
    return out;
  // The pairings' rows: g_j from their owners (one rank each: the sum is exact), NaN off them.
  std::vector<double> local(2 * static_cast<std::size_t>(mesh_.n_nodes()), 0.0),
      global(local.size(), 0.0);
  const auto u = [this](const int node) { return fields_.u(node); };
  for (const auto &strategy : interfaces_)
    if (!strategy->interface().split())
      for (const int k : strategy->interface().owned_rows())
      {
        const ContactInterface::Row &row = strategy->interface().rows()[k];
        local[2 * row.node] =
            gap_opening(row.normal, row.gap0, row.node, row.partners, row.weights, u);
        local[2 * row.node + 1] = 1.0;
      }
  Teuchos::reduceAll(*dofs_.owned_dof_map()->getComm(), Teuchos::REDUCE_SUM,
                     static_cast<int>(local.size()), local.data(), global.data());
  for (int n = 0; n < mesh_.n_nodes(); ++n)
    if (global[2 * n + 1] > 0.0)
      out.opening[n] = global[2 * n];
  // The k-th pair of gap g's interface is the k-th pair of gap g in Mesh::gap_pairs.
  std::vector<std::vector<int>> mesh_pairs(mesh_.gap_side_sets.size());
  for (std::size_t p = 0; p < n_pairs; ++p)
    mesh_pairs[mesh_.gap_pairs[p].gap].push_back(static_cast<int>(p));
  // A node on several gaps shows its pair of the first (the gaps in the input's order).
  for (const auto &strategy : interfaces_)
  {
    const ContactOutput more = strategy->node_values();
    for (std::size_t n = 0; n < out.traction.size(); ++n)
      if (std::isnan(out.traction[n]))
      {
        out.traction[n] = more.traction[n];
        out.active[n] = more.active[n];
      }
    if (!strategy->interface().split())
      continue; // a pairing's rows: not in Mesh::gap_pairs
    const std::vector<int> &of_gap = mesh_pairs[strategy->interface().gap()];
    for (std::size_t k = 0; k < of_gap.size(); ++k)
    {
      out.pair_traction[of_gap[k]] = more.pair_traction[k];
      out.pair_active[of_gap[k]] = more.pair_active[k];
    }
  }
  return out;
}

std::vector<double> StateOutput::gap_heat_flow() const
{
  std::vector<double> flow(mesh_.gap_pairs.size(), std::numeric_limits<double>::quiet_NaN());
  if (!thermal_ || mesh_.gap_pairs.empty())
    return flow;
  // The gap terms' heat rows at the side-a nodes of each face [W], into the face's pairs (a
  // node where gaps cross is in a pair of each), summed over the ranks.
  std::map<std::pair<int, int>, int> pair_of; // (gap, node a) -> pair
  for (std::size_t p = 0; p < mesh_.gap_pairs.size(); ++p)
    pair_of[{mesh_.gap_pairs[p].gap, mesh_.gap_pairs[p].node_a}] = static_cast<int>(p);
  std::vector<double> local(flow.size(), 0.0);
  const std::vector<int> &faces = terms_.evaluated_gap_faces();
  std::size_t call = 0;
  terms_.evaluate_gap_faces(fields_, false,
                            [&](const std::vector<int> &nodes, LocalSystem &system)
                            {
                              const GapFace &face = mesh_.gap_faces[faces[call++]];
                              const int gap = face.gap;
                              // The face's side-a nodes come first (any face type).
                              const int n_side_a = static_cast<int>(face.node_b.size());
                              for (int i = 0; i < n_side_a; ++i)
                                local[pair_of.at({gap, nodes[i]})] += system.residual(slots_.T, i);
                            });
  Teuchos::reduceAll(*dofs_.owned_dof_map()->getComm(), Teuchos::REDUCE_SUM,
                     static_cast<int>(local.size()), local.data(), flow.data());
  return flow;
}

StateSummary StateOutput::summary() const
{
  StateSummary s;
  if (!interfaces_.empty())
  {
    std::vector<const InterfaceStrategy *> strategies;
    for (const auto &strategy : interfaces_)
      strategies.push_back(strategy.get());
    summarize_contact(strategies, fields_, *dofs_.owned_dof_map()->getComm(), s);
  }
  if (thermal_)
    summarize_temperature(mesh_, dofs_, fields_, thermal_->conduction(), s);
  summarize_displacement(dofs_, fields_, s);
  // The heat across each gap, for the history's columns per gap (several gaps only).
  s.gaps.resize(mesh_.gap_side_sets.size());
  if (thermal_ && mesh_.gap_side_sets.size() > 1)
  {
    for (GapFigures &gap : s.gaps)
      gap.heat_flow = 0.0;
    const std::vector<double> flow = gap_heat_flow();
    for (std::size_t p = 0; p < flow.size(); ++p)
      s.gaps[mesh_.gap_pairs[p].gap].heat_flow += flow[p];
  }
  return s;
}
} // namespace kiln
