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
                                 const ContactInterface::Row &pair, const std::string &where)
{
  const auto da = constraints.directions(pair.a()), db = constraints.directions(pair.node);
  bool alike = da.size() == db.size();
  for (std::size_t i = 0; alike && i < da.size(); ++i)
    alike = std::abs(dot(da[i].axis, db[i].axis)) > 1.0 - 1e-12;
  if (alike)
    return;
  const auto names = [&](const std::vector<NodalConstraints::Direction> &directions)
  { return condition_names(constraints, directions); };
  const Point &x = interface_.mesh().coordinates[pair.a()];
  KILN_CHECK_INPUT(false, where,
                   "cannot pair gap nodes "
                       << pair.a() << " and " << pair.node << " at (" << x[0] << ", " << x[1]
                       << ", " << x[2] << "): the displacement conditions hold them in different "
                       << "directions (conditions " << names(da) << " at one, " << names(db)
                       << " at the other), so the pair is over-determined. Apply the conditions "
                          "to the faces of both sides of the gap alike");
}
void CondensedPairs::claim_normals(NodalConstraints &constraints, const std::string &where)
{
  const auto &mesh_points = interface_.mesh().coordinates;
  const auto &pairs = interface_.rows();
  const bool split = interface_.split();
  first_axis_.clear();
  axes_.clear();
  for (std::size_t k = 0; k < pairs.size(); ++k)
  {
    const ContactInterface::Row &pair = pairs[k];
    first_axis_.push_back(axes_.size());
    // A split gap's two nodes are held alike; a row's partners claim no axes (their held
    // axes are eliminated before the rows are combined), so only node j's conditions count.
    if (split)
      check_alike(constraints, pair, where);
    // The component of the normal that the conditions leave free: the conditions' directions
    // first, contact on the rest (doc/contact.md, "Conditions at gap nodes").
    Point free = pair.normal;
    for (const NodalConstraints::Direction &d :
         constraints.directions(split ? pair.a() : pair.node))
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
    const std::vector<int> claiming =
        split ? std::vector<int>{pair.a(), pair.node} : std::vector<int>{pair.node};
    for (const int node : claiming)
    {
      // Where gaps cross, each pair of the node claims its own normal as an axis of the node's
      // frame (perpendicular or not: the frame's dual basis keeps each pair's multiplier in its
      // own row); a normal in the span of the node's other axes over-determines it.
      const int slot = constraints.add_free_axis(node, pair.normal);
      const Point &x = mesh_points[node];
      const std::string across = split
                                     ? "of its pair with node " +
                                           std::to_string(node == pair.a() ? pair.node : pair.a()) +
                                           " across " + interface_.name()
                                     : "of its row in " + interface_.name();
      KILN_CHECK_INPUT(slot >= 0, where,
                       "cannot hold gap node "
                           << node << " at (" << x[0] << ", " << x[1] << ", " << x[2]
                           << "): the normal " << across << " lies (within "
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
      (node == pair.node ? axis.slot_b : axis.slot_a) = slot;
    }
    axes_.push_back(axis);
  }
  first_axis_.push_back(axes_.size());
}

void CondensedPairs::claim_free_axes(NodalConstraints &constraints, const std::string &where)
{
  const auto &pairs = interface_.rows();
  const bool split = interface_.split();
  first_axis_.clear();
  axes_.clear();
  for (std::size_t k = 0; k < pairs.size(); ++k)
  {
    const ContactInterface::Row &pair = pairs[k];
    first_axis_.push_back(axes_.size());
    // The two nodes of a split gap must be constrained alike, so that their frames have the
    // same axes; a row's partners claim nothing.
    if (split)
      check_alike(constraints, pair, where);
    bool perpendicular = true;
    for (const NodalConstraints::Direction &d :
         constraints.directions(split ? pair.a() : pair.node))
      perpendicular = perpendicular && std::abs(dot(d.axis, pair.normal)) <= 1e-6;
    // The normal first (n itself where the constraints are perpendicular to it), then the
    // coordinate axes, as NodalConstraints::close() completes a frame.
    std::array<Point, 4> candidates{pair.normal, Point{1, 0, 0}, Point{0, 1, 0}, Point{0, 0, 1}};
    for (std::size_t c = 0; c < candidates.size(); ++c)
    {
      const int slot_a = split ? constraints.add_free_axis(pair.a(), candidates[c], c > 0) : 0;
      const int slot_b = constraints.add_free_axis(pair.node, candidates[c], c > 0);
      KILN_ASSERT(!split || (slot_a < 0) == (slot_b < 0), "the frames of a tied pair differ");
      if (slot_b >= 0)
        axes_.push_back({static_cast<int>(k), slot_a, slot_b, c == 0, c == 0 && !perpendicular});
    }
  }
  first_axis_.push_back(axes_.size());
}

void CondensedPairs::finish_claims()
{
  value_.assign(axes_.size(), {});
  active_.assign(interface_.owned_rows().size(), 0);
  pressure_.assign(interface_.owned_rows().size(), 0.0);
  opening_.assign(interface_.owned_rows().size(), 0.0);
}

Point CondensedPairs::direction(const std::size_t axis) const
{
  const ContactInterface::Row &pair = interface_.rows()[axes_[axis].pair];
  const Axis &a = axes_[axis];
  if (a.normal && !a.leaning)
    return pair.normal;
  return interface_.split() ? constraints_.axes(pair.a())[a.slot_a]
                            : constraints_.axes(pair.node)[a.slot_b];
}

void CondensedPairs::decide(const Assembler &assembler, const Vector &r_overlap, Vector &R,
                            const std::function<Point(int)> &u)
{
  if (!interface_.split())
  {
    decide_rows(assembler, r_overlap, R, u);
    return;
  }
  const auto owned_map = dofs_.owned_dof_map();
  const auto overlap_map = dofs_.overlap_dof_map();
  const LO invalid = Teuchos::OrdinalTraits<LO>::invalid();
  // Every rank with a pair in its overlap (both nodes or neither: twins come together)
  // decides it alike, from the assembled rows.
  const auto r = r_overlap.getData();
  auto values = R.getDataNonConst();
  std::size_t owned_index = 0;
  const auto &pairs = interface_.rows();
  for (std::size_t k = 0; k < pairs.size(); ++k)
  {
    const ContactInterface::Row &pair = pairs[k];
    if (overlap_map->getLocalElement(dofs_.node_dof(pair.a(), u_slot_)) == invalid)
      continue;
    const bool owned = owned_map->getLocalElement(dofs_.node_dof(pair.node, u_slot_)) != invalid;
    const bool shut = !shut_.empty() && shut_[k] != 0;
    double P_normal = 0.0, cg_normal = 0.0;
    for (std::size_t i = first_axis_[k]; i < first_axis_[k + 1]; ++i)
    {
      const Axis &axis = axes_[i];
      const GO gid_a = dofs_.node_dof(pair.a(), u_slot_ + axis.slot_a);
      const GO gid_b = dofs_.node_dof(pair.node, u_slot_ + axis.slot_b);
      const LO a = assembler.lid(gid_a), b = assembler.lid(gid_b);
      const double P = (r[b] - r[a]) / (2.0 * pair.area);
      const double cg = pair.c * gap_opening(direction(i), u(pair.a()), u(pair.node));
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
      record(owned_index++, static_cast<int>(k), shut, P_normal, cg_normal);
  }
}

void CondensedPairs::record(const std::size_t owned_index, const int row, const bool shut,
                            const double P_normal, const double cg_normal)
{
  KILN_ASSERT(interface_.owned_rows()[owned_index] == row, "owned rows out of order");
  const double c = interface_.rows()[row].c;
  pressure_[owned_index] = P_normal;
  opening_[owned_index] = c > 0.0 ? cg_normal / c : 0.0;
  active_[owned_index] = shut || holds(P_normal, cg_normal);
}

void CondensedPairs::decide_rows(const Assembler &assembler, const Vector &r_overlap, Vector &R,
                                 const std::function<Point(int)> &u)
{
  const auto owned_map = dofs_.owned_dof_map();
  const auto overlap_map = dofs_.overlap_dof_map();
  const LO invalid = Teuchos::OrdinalTraits<LO>::invalid();
  const auto r = r_overlap.getData();
  auto values = R.getDataNonConst();
  const auto &rows = interface_.rows();
  const auto in_overlap = [&](const int node)
  { return overlap_map->getLocalElement(dofs_.node_dof(node, u_slot_)) != invalid; };
  // The partners' owned rows start from their assembled rows (so that deciding again on the
  // same R gives the same rows), then each row adds w_jk (d . t_(k,q)) (R_(j,d) - D_jj C).
  for (const Row &row : rows)
    if (in_overlap(row.node))
      for (const int k : row.partners)
        for (int q = constraints_.n_constrained(k); q < 3; ++q)
        {
          const GO gid = dofs_.node_dof(k, u_slot_ + q);
          const LO owned_k = owned_map->getLocalElement(gid);
          if (owned_k != invalid)
            values[owned_k] = r[assembler.lid(gid)];
        }
  // Every rank with a row in its overlap (node j with all its partners, or none of them:
  // DofManager) decides it alike, from the assembled rows.
  std::size_t owned_index = 0;
  for (std::size_t k = 0; k < rows.size(); ++k)
  {
    const Row &row = rows[k];
    if (!in_overlap(row.node))
      continue;
    const bool owned = owned_map->getLocalElement(dofs_.node_dof(row.node, u_slot_)) != invalid;
    const bool shut = !shut_.empty() && shut_[k] != 0;
    const Point twin_u = twin_point(row.partners, row.weights, u);
    double P_normal = 0.0, cg_normal = 0.0;
    for (std::size_t i = first_axis_[k]; i < first_axis_[k + 1]; ++i)
    {
      const Axis &axis = axes_[i];
      const Point d = direction(i);
      const GO gid_j = dofs_.node_dof(row.node, u_slot_ + axis.slot_b);
      const LO j = assembler.lid(gid_j);
      const double P = r[j] / row.area;
      // g0 n projected on d: the reference opening along the normal, none across it.
      const double cg =
          row.c * (dot(d, row.normal) * row.gap0 + gap_opening(d, twin_u, u(row.node)));
      value_[i] = shut && axis.normal ? ComplementarityFunction::Value{true, cg, 0.0, 1.0}
                                      : law(axis.normal, P, cg);
      if (value_[i].combined)
      {
        const double moved = r[j] - row.area * value_[i].C;
        for (std::size_t p = 0; p < row.partners.size(); ++p)
        {
          const int node_k = row.partners[p];
          const auto &t = constraints_.dual_axes(node_k);
          for (int q = constraints_.n_constrained(node_k); q < 3; ++q)
          {
            const LO owned_k = owned_map->getLocalElement(dofs_.node_dof(node_k, u_slot_ + q));
            if (owned_k != invalid)
              values[owned_k] += row.weights[p] * dot(d, t[q]) * moved;
          }
        }
        if (owned)
          values[owned_map->getLocalElement(gid_j)] = row.area * value_[i].C;
      }
      if (axis.normal)
      {
        P_normal = P;
        cg_normal = cg;
      }
    }
    if (owned)
      record(owned_index++, static_cast<int>(k), shut, P_normal, cg_normal);
  }
}

void CondensedPairs::combine_rows(const std::vector<int> &nodes, LocalSystem &local) const
{
  if (!interface_.split())
  {
    combine_row_rows(nodes, local);
    return;
  }
  const int n_local = local.n_nodes();
  const int m = local.size();
  auto &jac = local.jacobian_values();
  const auto &pairs = interface_.rows();
  for (int i = 0; i < n_local; ++i)
  {
    const auto [begin, end] = interface_.rows_of_partner(nodes[i]);
    for (const int *pair = begin; pair != end; ++pair)
    {
      const int k = *pair;
      int j = -1;
      for (std::size_t l = first_axis_[k]; l < first_axis_[k + 1]; ++l)
      {
        if (!value_[l].combined)
          continue;
        if (j < 0)
          j = static_cast<int>(std::find(nodes.begin(), nodes.end(), pairs[k].node) -
                               nodes.begin());
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

void CondensedPairs::combine_row_rows(const std::vector<int> &nodes, LocalSystem &local) const
{
  const int n_local = local.n_nodes();
  const int m = local.size();
  auto &jac = local.jacobian_values();
  const auto &rows = interface_.rows();
  std::vector<int> partner_index;
  for (int i = 0; i < n_local; ++i)
  {
    const int k = interface_.row_of_node(nodes[i]);
    if (k < 0)
      continue;
    const Row &row = rows[k];
    partner_index.clear();
    for (const int p : row.partners)
      partner_index.push_back(
          static_cast<int>(std::find(nodes.begin(), nodes.end(), p) - nodes.begin()));
    const bool whole =
        std::find(partner_index.begin(), partner_index.end(), n_local) == partner_index.end();
    for (std::size_t l = first_axis_[k]; l < first_axis_[k + 1]; ++l)
    {
      if (!value_[l].combined)
        continue;
      const std::size_t ij = local.index(u_slot_ + axes_[l].slot_b, i);
      if (!whole)
      {
        // Node j joined the system as a partner's row (DofManager: not its other partners):
        // its rows here are zero.
        KILN_ASSERT(std::all_of(jac.begin() + static_cast<long>(ij * m),
                                jac.begin() + static_cast<long>((ij + 1) * m),
                                [](const double v) { return v == 0.0; }),
                    "a local system lacks a partner of node " << nodes[i]);
        continue;
      }
      // Row (k, q) += w_jk (d . t_(k,q)) (1 - dC/dP) row (j, d); row (j, d) *= dC/dP.
      const Point d = direction(l);
      const double moved = 1.0 - value_[l].dC_dP;
      for (std::size_t p = 0; p < row.partners.size(); ++p)
      {
        const int node_k = row.partners[p];
        const auto &t = constraints_.dual_axes(node_k);
        for (int q = constraints_.n_constrained(node_k); q < 3; ++q)
        {
          const double w = row.weights[p] * dot(d, t[q]) * moved;
          const std::size_t ik = local.index(u_slot_ + q, partner_index[p]);
          for (int c = 0; c < m; ++c)
            jac[ik * m + c] += w * jac[ij * m + c];
        }
      }
      for (int c = 0; c < m; ++c)
        jac[ij * m + c] *= value_[l].dC_dP;
    }
  }
}

void CondensedPairs::add_terms(Assembler &assembler) const
{
  if (!interface_.split())
  {
    add_row_terms(assembler);
    return;
  }
  const int F = dofs_.n_node_fields();
  LocalSystem local(2, F);
  for (const int k : interface_.owned_rows())
    for (std::size_t l = first_axis_[k]; l < first_axis_[k + 1]; ++l)
    {
      if (!value_[l].combined)
        continue;
      const Axis &axis = axes_[l];
      const ContactInterface::Row &pair = interface_.rows()[k];
      const Point d = direction(l);
      // d(A C)/dû = A c dC/d(cg) dg/dû, g = d.(u_b - u_a), u = sum_k û_k t_k (the dual axes):
      // the columns of the unknowns that are not constrained (those are fixed at their
      // prescribed values).
      const double w = pair.area * pair.c * value_[l].dC_dcg;
      local.clear();
      // Row b gets them; row a, which is R_a + R_b - A C, minus them.
      for (int side = 0; side < 2; ++side)
      {
        const int node = side == 0 ? pair.a() : pair.node;
        const auto &q = constraints_.dual_axes(node);
        for (int c = constraints_.n_constrained(node); c < 3; ++c)
        {
          const double v = (side == 0 ? -w : w) * dot(d, q[c]);
          local.jacobian(u_slot_ + axis.slot_b, 1, u_slot_ + c, side) = v;
          local.jacobian(u_slot_ + axis.slot_a, 0, u_slot_ + c, side) = -v;
        }
      }
      assembler.add(assembler.node_lids({pair.a(), pair.node}), local);
    }
}

void CondensedPairs::add_row_terms(Assembler &assembler) const
{
  const int F = dofs_.n_node_fields();
  for (const int k : interface_.owned_rows())
  {
    const Row &row = interface_.rows()[k];
    std::vector<int> nodes{row.node};
    nodes.insert(nodes.end(), row.partners.begin(), row.partners.end());
    const int n = static_cast<int>(nodes.size());
    LocalSystem local(n, F);
    for (std::size_t l = first_axis_[k]; l < first_axis_[k + 1]; ++l)
    {
      if (!value_[l].combined)
        continue;
      const Point d = direction(l);
      // d(D C)/dû = D c dC/d(cg) dg/dû, g = g0 + d.(u_j - sum_k w_jk u_k) (dg/du_k = -w_jk d),
      // u = sum_q û_q t_q: the columns of the free unknowns of j and its partners. Row (j, d)
      // gets them; each partner's row (k, q), which holds -w_jk (d . t_(k,q)) D C, the same
      // times that.
      const double scale = row.area * row.c * value_[l].dC_dcg;
      local.clear();
      for (int s = 0; s < n; ++s)
      {
        const double w_s = s == 0 ? 1.0 : -row.weights[s - 1];
        const auto &t = constraints_.dual_axes(nodes[s]);
        for (int c = constraints_.n_constrained(nodes[s]); c < 3; ++c)
        {
          const double v = scale * w_s * dot(d, t[c]);
          local.jacobian(u_slot_ + axes_[l].slot_b, 0, u_slot_ + c, s) += v;
          for (int p = 1; p < n; ++p)
          {
            const auto &t_k = constraints_.dual_axes(nodes[p]);
            const double w_p = row.weights[p - 1];
            for (int q = constraints_.n_constrained(nodes[p]); q < 3; ++q)
              local.jacobian(u_slot_ + q, p, u_slot_ + c, s) -= w_p * dot(d, t_k[q]) * v;
          }
        }
      }
      assembler.add(assembler.node_lids(nodes), local);
    }
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

InterfaceStrategy::HeldDirection CondensedPairs::held_direction(const int k,
                                                                const std::size_t axis) const
{
  const Row &row = interface_.rows()[k];
  const auto &X = interface_.mesh().coordinates;
  // A split gap holds at node a; a row at its twin point sum_k w_jk X_k.
  const Point at = interface_.split()
                       ? X[row.a()]
                       : twin_point(row.partners, row.weights, [&X](const int n) { return X[n]; });
  return {row.a(), row.node, direction(axis), at};
}

std::vector<InterfaceStrategy::OpenPair> CondensedPairs::open_pairs(const double zero) const
{
  std::vector<OpenPair> open;
  const auto &owned = interface_.owned_rows();
  for (std::size_t i = 0; i < owned.size(); ++i)
  {
    const int k = owned[i];
    const bool shut = !shut_.empty() && shut_[k] != 0;
    if ((active_[i] && !shut && pressure_[i] > zero) || first_axis_[k] == first_axis_[k + 1])
      continue;
    open.push_back({k, opening_[i], held_direction(k, first_axis_[k]), active_[i] != 0});
  }
  return open;
}

std::vector<InterfaceStrategy::HeldDirection> CondensedPairs::held_directions(const bool all) const
{
  std::vector<HeldDirection> held;
  const auto &owned = interface_.owned_rows();
  for (std::size_t i = 0; i < owned.size(); ++i)
    if (all || active_[i])
    {
      const int k = owned[i];
      for (std::size_t l = first_axis_[k]; l < first_axis_[k + 1]; ++l)
        held.push_back(held_direction(k, l));
    }
  return held;
}
} // namespace kiln
