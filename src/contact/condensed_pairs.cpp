#include "contact/condensed_pairs.hpp"

#include "base/errors.hpp"
#include "contact/gap_opening.hpp"

#include <Teuchos_OrdinalTraits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace kiln
{
namespace
{
/// The names of the displacement conditions of `directions`, quoted ("none" if none).
std::string condition_names(const NodalConstraints &constraints,
                            const std::vector<NodalConstraints::Direction> &directions)
{
  std::string text;
  for (const auto &d : directions)
    text += (text.empty() ? "\"" : ", \"") + constraints.value_name(d.value) + "\"";
  return text.empty() ? std::string("none") : text;
}

/// The ids of the gap side sets other than `gap` (an index) with a pair at `node`.
std::string other_gap_side_sets(const Mesh &mesh, const int node, const int gap)
{
  std::vector<int> ids;
  for (const GapPair &p : mesh.gap_pairs)
    if ((p.node_a == node || p.node_b == node) && p.gap != gap &&
        std::find(ids.begin(), ids.end(), mesh.gap_side_sets[p.gap]) == ids.end())
      ids.push_back(mesh.gap_side_sets[p.gap]);
  std::string text;
  for (const int id : ids)
    text += (text.empty() ? "" : ", ") + std::to_string(id);
  return text.empty() ? std::string("none") : text;
}
} // namespace

CondensedPairs::CondensedPairs(const ContactInterface &interface, const DofManager &dofs,
                               const NodalConstraints &constraints)
    : InterfaceStrategy(interface, dofs), constraints_(constraints),
      u_slot_(dofs.layout().slot(Field::ux))
{
}

void CondensedPairs::check_alike(const NodalConstraints &constraints,
                                 const ContactInterface::Pair &pair, const std::string &where)
{
  const auto da = constraints.directions(pair.a), db = constraints.directions(pair.b);
  bool alike = da.size() == db.size();
  for (std::size_t i = 0; alike && i < da.size(); ++i)
    alike = std::abs(dot(da[i].axis, db[i].axis)) > 1.0 - 1e-12;
  if (alike)
    return;
  const auto names = [&](const std::vector<NodalConstraints::Direction> &directions)
  { return condition_names(constraints, directions); };
  const Point &x = interface_.mesh().coordinates[pair.a];
  KILN_CHECK_INPUT(false, where,
                   "cannot pair gap nodes "
                       << pair.a << " and " << pair.b << " at (" << x[0] << ", " << x[1] << ", "
                       << x[2] << "): the displacement conditions hold them in different "
                       << "directions (conditions " << names(da) << " at one, " << names(db)
                       << " at the other), so the pair is over-determined. Apply the conditions "
                          "to the faces of both sides of the gap alike");
}

void CondensedPairs::claim_normals(NodalConstraints &constraints, const std::string &where)
{
  const auto &mesh_points = interface_.mesh().coordinates;
  const auto &pairs = interface_.pairs();
  first_axis_.clear();
  axes_.clear();
  for (std::size_t k = 0; k < pairs.size(); ++k)
  {
    const ContactInterface::Pair &pair = pairs[k];
    first_axis_.push_back(axes_.size());
    check_alike(constraints, pair, where);
    // The component of the normal that the conditions leave free: the conditions' directions
    // first, contact on the rest (doc/contact.md, "Conditions at gap nodes").
    Point free = pair.normal;
    for (const NodalConstraints::Direction &d : constraints.directions(pair.a))
    {
      const double along = dot(free, d.axis);
      for (int i = 0; i < 3; ++i)
        free[i] -= along * d.axis[i];
    }
    const double length = std::sqrt(dot(free, free));
    if (length <= 1e-6)
      continue; // held along the normal by its conditions: no contact there
    for (double &v : free)
      v /= length;
    Axis axis;
    axis.pair = static_cast<int>(k);
    axis.normal = true;
    axis.leaning = length < 1.0 - 1e-12;
    for (const int node : {pair.a, pair.b})
    {
      // Where gaps cross, each pair of the node claims its own normal as an axis of the node's
      // frame (perpendicular or not: the frame's dual basis keeps each pair's multiplier in its
      // own row); a normal in the span of the node's other axes over-determines it.
      const int slot = constraints.add_free_axis(node, pair.normal);
      const Point &x = mesh_points[node];
      KILN_CHECK_INPUT(slot >= 0, where,
                       "cannot hold gap node "
                           << node << " at (" << x[0] << ", " << x[1] << ", " << x[2]
                           << "): the normal of its pair with node "
                           << (node == pair.a ? pair.b : pair.a) << " across gap side set "
                           << interface_.mesh().gap_side_sets[interface_.gap()] << " lies (within "
                           << NodalConstraints::min_sine
                           << " rad) in the span of the directions the node already has (the "
                              "normals of its pairs across gap side sets "
                           << other_gap_side_sets(interface_.mesh(), node, interface_.gap())
                           << " and its displacement conditions "
                           << condition_names(constraints, constraints.directions(node))
                           << "), so the node is over-determined: its normals and held "
                              "directions must be linearly independent. Remove a displacement "
                              "condition there or one of the gaps, or mesh the gaps so that "
                              "their normals and the held directions at a node are independent");
      KILN_ASSERT(dot(constraints.frame_axis_so_far(node, slot), free) > 1.0 - 1e-12,
                  "the axis of node " << node << " is not its free normal");
      (node == pair.a ? axis.slot_a : axis.slot_b) = slot;
    }
    axes_.push_back(axis);
  }
  first_axis_.push_back(axes_.size());
}

void CondensedPairs::claim_free_axes(NodalConstraints &constraints, const std::string &where)
{
  const auto &pairs = interface_.pairs();
  first_axis_.clear();
  axes_.clear();
  for (std::size_t k = 0; k < pairs.size(); ++k)
  {
    const ContactInterface::Pair &pair = pairs[k];
    first_axis_.push_back(axes_.size());
    // The two nodes must be constrained alike, so that their frames have the same axes.
    check_alike(constraints, pair, where);
    bool perpendicular = true;
    for (const NodalConstraints::Direction &d : constraints.directions(pair.a))
      perpendicular = perpendicular && std::abs(dot(d.axis, pair.normal)) <= 1e-6;
    // The normal first (n itself where the constraints are perpendicular to it), then the
    // coordinate axes, as NodalConstraints::close() completes a frame.
    std::array<Point, 4> candidates{pair.normal, Point{1, 0, 0}, Point{0, 1, 0}, Point{0, 0, 1}};
    for (std::size_t c = 0; c < candidates.size(); ++c)
    {
      const int slot_a = constraints.add_free_axis(pair.a, candidates[c], c > 0);
      const int slot_b = constraints.add_free_axis(pair.b, candidates[c], c > 0);
      KILN_ASSERT((slot_a < 0) == (slot_b < 0), "the frames of a tied pair differ");
      if (slot_a >= 0)
        axes_.push_back({static_cast<int>(k), slot_a, slot_b, c == 0, c == 0 && !perpendicular});
    }
  }
  first_axis_.push_back(axes_.size());
}

void CondensedPairs::finish_claims()
{
  value_.assign(axes_.size(), {});
  active_.assign(interface_.owned_pairs().size(), 0);
  pressure_.assign(interface_.owned_pairs().size(), 0.0);
  opening_.assign(interface_.owned_pairs().size(), 0.0);
}

Point CondensedPairs::direction(const std::size_t axis) const
{
  const ContactInterface::Pair &pair = interface_.pairs()[axes_[axis].pair];
  const Axis &a = axes_[axis];
  return a.normal && !a.leaning ? pair.normal : constraints_.axes(pair.a)[a.slot_a];
}

void CondensedPairs::decide(const Assembler &assembler, const Vector &r_overlap, Vector &R,
                            const std::function<Point(int)> &u)
{
  const auto owned_map = dofs_.owned_dof_map();
  const auto overlap_map = dofs_.overlap_dof_map();
  const LO invalid = Teuchos::OrdinalTraits<LO>::invalid();
  // Every rank with a pair in its overlap (both nodes or neither: twins come together)
  // decides it alike, from the assembled rows.
  const auto r = r_overlap.getData();
  auto values = R.getDataNonConst();
  std::size_t owned_index = 0;
  const auto &pairs = interface_.pairs();
  for (std::size_t k = 0; k < pairs.size(); ++k)
  {
    const ContactInterface::Pair &pair = pairs[k];
    if (overlap_map->getLocalElement(dofs_.node_dof(pair.a, u_slot_)) == invalid)
      continue;
    const bool owned = owned_map->getLocalElement(dofs_.node_dof(pair.b, u_slot_)) != invalid;
    const bool shut = !shut_.empty() && shut_[k] != 0;
    double P_normal = 0.0, cg_normal = 0.0;
    for (std::size_t i = first_axis_[k]; i < first_axis_[k + 1]; ++i)
    {
      const Axis &axis = axes_[i];
      const GO gid_a = dofs_.node_dof(pair.a, u_slot_ + axis.slot_a);
      const GO gid_b = dofs_.node_dof(pair.b, u_slot_ + axis.slot_b);
      const LO a = assembler.lid(gid_a), b = assembler.lid(gid_b);
      const double P = (r[b] - r[a]) / (2.0 * pair.area);
      const double cg = pair.c * gap_opening(direction(i), u(pair.a), u(pair.b));
      // Held shut (Minimum Norm): the normal is tied, g = 0, whatever P.
      value_[i] = shut && axis.normal ? ComplementarityFunction::Value{true, cg, 0.0, 1.0}
                                      : law(axis.normal, P, cg);
      const LO owned_a = owned_map->getLocalElement(gid_a);
      if (value_[i].combined && owned_a != invalid)
        values[owned_a] = r[a] + r[b] - pair.area * value_[i].C;
      if (value_[i].combined && owned)
        values[owned_map->getLocalElement(gid_b)] = pair.area * value_[i].C;
      if (axis.normal)
      {
        P_normal = P;
        cg_normal = cg;
      }
    }
    if (owned)
    {
      KILN_ASSERT(interface_.owned_pairs()[owned_index] == static_cast<int>(k),
                  "owned pairs out of order");
      pressure_[owned_index] = P_normal;
      opening_[owned_index] = pair.c > 0.0 ? cg_normal / pair.c : 0.0;
      active_[owned_index] = shut || holds(P_normal, cg_normal);
      ++owned_index;
    }
  }
}

void CondensedPairs::combine_rows(const std::vector<int> &nodes, LocalSystem &local) const
{
  const int n_local = local.n_nodes();
  const int m = local.size();
  auto &jac = local.jacobian_values();
  const auto &pairs = interface_.pairs();
  for (int i = 0; i < n_local; ++i)
  {
    const auto [begin, end] = interface_.pairs_of_node_a(nodes[i]);
    for (const int *pair = begin; pair != end; ++pair)
    {
      const int k = *pair;
      int j = -1;
      for (std::size_t l = first_axis_[k]; l < first_axis_[k + 1]; ++l)
      {
        if (!value_[l].combined)
          continue;
        if (j < 0)
          j = static_cast<int>(std::find(nodes.begin(), nodes.end(), pairs[k].b) - nodes.begin());
        const std::size_t ia = local.index(u_slot_ + axes_[l].slot_a, i);
        if (j == n_local)
        {
          // Node a is itself a twin that joined the system (where gaps cross, its own twins
          // do not): its rows here are zero, and so are its partner's.
          KILN_ASSERT(std::all_of(jac.begin() + static_cast<long>(ia * m),
                                  jac.begin() + static_cast<long>((ia + 1) * m),
                                  [](const double v) { return v == 0.0; }),
                      "a local system lacks the twin of node " << nodes[i]);
          continue;
        }
        const std::size_t ib = local.index(u_slot_ + axes_[l].slot_b, j);
        const double w = 0.5 * value_[l].dC_dP;
        for (int c = 0; c < m; ++c)
        {
          const double va = jac[ia * m + c], vb = jac[ib * m + c];
          jac[ib * m + c] = w * (vb - va);
          jac[ia * m + c] = va + vb - jac[ib * m + c];
        }
      }
    }
  }
}

void CondensedPairs::add_terms(Assembler &assembler) const
{
  const int F = dofs_.n_node_fields();
  LocalSystem local(2, F);
  for (const int k : interface_.owned_pairs())
    for (std::size_t l = first_axis_[k]; l < first_axis_[k + 1]; ++l)
    {
      if (!value_[l].combined)
        continue;
      const Axis &axis = axes_[l];
      const ContactInterface::Pair &pair = interface_.pairs()[k];
      const Point d = direction(l);
      // d(A C)/dû = A c dC/d(cg) dg/dû, g = d.(u_b - u_a), u = sum_k û_k t_k (the dual axes):
      // the columns of the unknowns that are not constrained (those are fixed at their
      // prescribed values).
      const double w = pair.area * pair.c * value_[l].dC_dcg;
      local.clear();
      // Row b gets them; row a, which is R_a + R_b - A C, minus them.
      for (int side = 0; side < 2; ++side)
      {
        const int node = side == 0 ? pair.a : pair.b;
        const auto &q = constraints_.dual_axes(node);
        for (int c = constraints_.n_constrained(node); c < 3; ++c)
        {
          const double v = (side == 0 ? -w : w) * dot(d, q[c]);
          local.jacobian(u_slot_ + axis.slot_b, 1, u_slot_ + c, side) = v;
          local.jacobian(u_slot_ + axis.slot_a, 0, u_slot_ + c, side) = -v;
        }
      }
      assembler.add(assembler.node_lids({pair.a, pair.b}), local);
    }
}

std::vector<double> CondensedPairs::jacobian_dependencies() const
{
  std::vector<double> d;
  d.reserve(3 * value_.size());
  for (const ComplementarityFunction::Value &v : value_)
    d.insert(d.end(), {v.combined ? 1.0 : 0.0, v.dC_dP, v.dC_dcg});
  return d;
}

std::vector<InterfaceStrategy::OpenPair> CondensedPairs::open_pairs(const double zero) const
{
  std::vector<OpenPair> open;
  const auto &owned = interface_.owned_pairs();
  for (std::size_t i = 0; i < owned.size(); ++i)
  {
    const int k = owned[i];
    const bool shut = !shut_.empty() && shut_[k] != 0;
    if ((active_[i] && !shut && pressure_[i] > zero) || first_axis_[k] == first_axis_[k + 1])
      continue;
    const ContactInterface::Pair &pair = interface_.pairs()[k];
    open.push_back({k, opening_[i], {pair.a, pair.b, direction(first_axis_[k])}, active_[i] != 0});
  }
  return open;
}

std::vector<InterfaceStrategy::HeldDirection> CondensedPairs::held_directions(const bool all) const
{
  std::vector<HeldDirection> held;
  const auto &owned = interface_.owned_pairs();
  for (std::size_t i = 0; i < owned.size(); ++i)
    if (all || active_[i])
    {
      const int k = owned[i];
      const ContactInterface::Pair &pair = interface_.pairs()[k];
      for (std::size_t l = first_axis_[k]; l < first_axis_[k + 1]; ++l)
        held.push_back({pair.a, pair.b, direction(l)});
    }
  return held;
}
} // namespace kiln
