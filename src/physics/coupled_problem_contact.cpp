/// Contact across the gap in CoupledProblem: the pairs' frames, the complementarity rows,
/// the active set (doc/contact.md).
#include "physics/coupled_problem.hpp"

#include "base/errors.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_OrdinalTraits.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace kiln
{
namespace internal
{

int sum_over_ranks(const Teuchos::Comm<int> &comm, const int local)
{
  int global = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return global;
}
} // namespace internal

void CoupledProblem::setup_contact(const Teuchos::ParameterList &contact, const std::string &where)
{
  fischer_burmeister_ =
      contact.get<std::string>("Complementarity Function") == "Fischer-Burmeister";
  const double scale = contact.get<double>("Complementarity Scale");
  const int rank = dofs_.owned_dof_map()->getComm()->getRank();
  for (const GapPair &gap_pair : mesh_.gap_pairs)
  {
    ContactPair pair;
    pair.a = gap_pair.node_a;
    pair.b = gap_pair.node_b;
    pair.area = gap_pair.area;
    pair.c = scale * modulus_ / std::sqrt(gap_pair.area);
    const Point &n = gap_pair.normal;
    for (const int node : {pair.a, pair.b})
    {
      // The node's frame: its constrained directions, then n, then the axes.
      NodeFrame frame;
      if (frame_of_node_[node] >= 0)
        frame = frames_[frame_of_node_[node]];
      std::vector<Point> basis(frame.q.begin(), frame.q.begin() + frame.n_constrained);
      for (int l = 0; l < frame.n_constrained; ++l)
      {
        const double cosine = dot(frame.q[l], n);
        const Point &x = mesh_.coordinates[node];
        KILN_CHECK_INPUT(std::abs(cosine) <= 1e-6, where,
                         "cannot hold: the condition \""
                             << mechanical_bcs_[frame.bc[l]].name() << "\" constrains gap node "
                             << node << " at (" << x[0] << ", " << x[1] << ", " << x[2]
                             << ") in a direction at cos = " << cosine
                             << " to the gap normal, which contact needs free. Apply it on faces "
                                "perpendicular to the gap, or set \"Enabled\" = false");
      }
      KILN_CHECK_INPUT(frame.n_constrained < 3 && append_orthonormal(basis, n), where,
                       "cannot hold: gap node " << node
                                                << " has its displacement fully prescribed; "
                                                   "remove the condition there or set "
                                                   "\"Enabled\" = false");
      for (int d = 0; d < 3 && basis.size() < 3; ++d)
      {
        Point e{};
        e[d] = 1.0;
        append_orthonormal(basis, e);
      }
      std::copy(basis.begin(), basis.end(), frame.q.begin());
      (node == pair.a ? pair.slot_a : pair.slot_b) = frame.n_constrained;
      if (frame_of_node_[node] >= 0)
        frames_[frame_of_node_[node]] = frame;
      else
      {
        frame_of_node_[node] = static_cast<int>(frames_.size());
        frames_.push_back(frame);
      }
      pair_of_node_[node] = static_cast<int>(pairs_.size());
    }
    if (dofs_.node_owner()[pair.b] == rank)
      owned_pairs_.push_back(static_cast<int>(pairs_.size()));
    pairs_.push_back(pair);
  }
  contact_mode_.assign(pairs_.size(), ContactMode::open);
  contact_dP_.assign(pairs_.size(), 0.0);
  contact_dg_.assign(pairs_.size(), 0.0);
  f_overlap_ = assembler_.make_overlap_vector();
  active_.assign(owned_pairs_.size(), 0);
  pressure_.assign(owned_pairs_.size(), 0.0);
  last_jacobian_active_.assign(owned_pairs_.size(), 0);
}

void CoupledProblem::update_contact(Vector &f)
{
  const auto owned_map = dofs_.owned_dof_map();
  const auto x = x_overlap_->getData();
  if (!pairs_.empty())
  {
    // Every rank with a pair in its overlap (both nodes or neither: twins come together)
    // decides it alike, from the assembled rows.
    assembler_.gather(f, *f_overlap_);
    const auto r = f_overlap_->getData();
    const bool fischer_burmeister = fischer_burmeister_ || cycle_fallback_;
    auto values = f.getDataNonConst();
    std::size_t owned_index = 0;
    for (std::size_t k = 0; k < pairs_.size(); ++k)
    {
      const ContactPair &pair = pairs_[k];
      if (overlap_index_[pair.a] < 0)
        continue;
      const GO gid_a = dofs_.node_dof(pair.a, u_slot_ + pair.slot_a);
      const GO gid_b = dofs_.node_dof(pair.b, u_slot_ + pair.slot_b);
      const LO a = assembler_.lid(gid_a), b = assembler_.lid(gid_b);
      const double P = (r[b] - r[a]) / (2.0 * pair.area);
      const double cg = pair.c * (x[b] - x[a]);
      double C = 0.0; // the contact row of b, A C(P, g)
      if (fischer_burmeister)
      {
        const double rho = std::hypot(P, cg);
        contact_mode_[k] = ContactMode::fischer_burmeister;
        // At the origin, the generalized derivative of the direction (1, 1).
        contact_dP_[k] = rho > 0.0 ? 1.0 - P / rho : 1.0 - 1.0 / std::sqrt(2.0);
        contact_dg_[k] = rho > 0.0 ? 1.0 - cg / rho : 1.0 - 1.0 / std::sqrt(2.0);
        C = pair.area * (P + cg - rho);
      }
      else
      {
        contact_mode_[k] = P - cg > 0.0 ? ContactMode::closed : ContactMode::open;
        C = pair.area * cg;
      }
      const bool open = contact_mode_[k] == ContactMode::open;
      const LO owned_a = owned_map->getLocalElement(gid_a);
      const LO owned_b = owned_map->getLocalElement(gid_b);
      if (!open && owned_a != Teuchos::OrdinalTraits<LO>::invalid())
        values[owned_a] = r[a] + r[b];
      if (owned_b != Teuchos::OrdinalTraits<LO>::invalid())
      {
        if (!open)
          values[owned_b] = C;
        KILN_ASSERT(owned_pairs_[owned_index] == static_cast<int>(k), "owned pairs out of order");
        pressure_[owned_index] = P;
        active_[owned_index] = P - cg > 0.0;
        ++owned_index;
      }
    }
  }
  if (!frozen_temperature_.empty())
  {
    auto values = f.getDataNonConst();
    for (std::size_t i = 0; i < frozen_temperature_.size(); ++i)
    {
      const LO row = static_cast<LO>(F_ * i + T_slot_);
      values[row] = x[assembler_.lid(owned_map->getGlobalElement(row))] - frozen_temperature_[i];
    }
  }
}

void CoupledProblem::add_contact_jacobian(Matrix &J)
{
  const auto owned_map = dofs_.owned_dof_map();
  J.resumeFill();
  for (std::size_t i = 0; i < owned_pairs_.size(); ++i)
  {
    const int k = owned_pairs_[i];
    if (contact_mode_[k] == ContactMode::open)
      continue;
    const ContactPair &pair = pairs_[k];
    // d(A c g) = A c (du_b - du_a), times dC/d(c g) for Fischer-Burmeister.
    const double w =
        pair.area * pair.c * (contact_mode_[k] == ContactMode::closed ? 1.0 : contact_dg_[k]);
    const GO columns[2] = {dofs_.node_dof(pair.a, u_slot_ + pair.slot_a),
                           dofs_.node_dof(pair.b, u_slot_ + pair.slot_b)};
    const double entries[2] = {-w, w};
    J.sumIntoGlobalValues(columns[1], Teuchos::ArrayView<const GO>(columns, 2),
                          Teuchos::ArrayView<const double>(entries, 2));
  }
  if (!frozen_temperature_.empty())
  {
    Teuchos::Array<LO> columns;
    Teuchos::Array<double> entries;
    for (std::size_t i = 0; i < frozen_temperature_.size(); ++i)
    {
      const LO row = static_cast<LO>(F_ * i + T_slot_);
      const std::size_t n = J.getNumEntriesInLocalRow(row);
      columns.resize(n);
      entries.resize(n);
      std::size_t count = 0;
      J.getLocalRowCopy(row, columns(), entries(), count);
      const LO diagonal = J.getColMap()->getLocalElement(owned_map->getGlobalElement(row));
      for (std::size_t e = 0; e < count; ++e)
        entries[e] = columns[e] == diagonal ? 1.0 : 0.0;
      J.replaceLocalValues(row, columns(0, count), entries(0, count));
    }
  }
  J.fillComplete(owned_map, owned_map);
}

void CoupledProblem::track_active_set()
{
  const auto &comm = *dofs_.owned_dof_map()->getComm();
  int closed = 0, opened = 0;
  for (std::size_t i = 0; i < active_.size(); ++i)
  {
    closed += active_[i] && !last_jacobian_active_[i];
    opened += !active_[i] && last_jacobian_active_[i];
  }
  closed = internal::sum_over_ranks(comm, closed);
  opened = internal::sum_over_ranks(comm, opened);
  ++jacobians_;
  if (closed + opened > 0)
  {
    if (!out_.is_null())
      *out_ << "  contact, Newton iteration " << jacobians_ << ": " << closed << " pairs closed, "
            << opened << " opened; " << n_active_pairs() << " of " << pairs_.size()
            << " in contact\n";
  }
  const int repeated = history_.record(active_, comm);
  if (repeated > 0 && !cycle_fallback_)
  {
    cycle_fallback_ = true;
    if (!out_.is_null())
      *out_ << "  contact: the active set of Newton iteration " << repeated
            << " came back at iteration " << jacobians_
            << " (a cycle); this step goes on with the Fischer-Burmeister function\n";
  }
  last_jacobian_active_ = active_;
}

int CoupledProblem::n_active_pairs() const
{
  const int local = static_cast<int>(std::count(active_.begin(), active_.end(), 1));
  return internal::sum_over_ranks(*dofs_.owned_dof_map()->getComm(), local);
}

void CoupledProblem::step_accepted(const double time)
{
  if (pairs_.empty())
    return;
  last_jacobian_active_ = active_;
  const int active = n_active_pairs();
  if (active != accepted_active_ && !out_.is_null())
  {
    const int n = static_cast<int>(pairs_.size());
    *out_ << "contact at t = " << time << " s: " << active << " of " << n
          << " gap pairs in contact (was " << accepted_active_ << ")"
          << (active == n && accepted_active_ < n   ? ": the gap has closed"
              : active == 0 && accepted_active_ > 0 ? ": the gap has opened"
                                                    : "")
          << "\n";
  }
  accepted_active_ = active;
}

void CoupledProblem::freeze_temperature(const Vector *x)
{
  frozen_temperature_.clear();
  if (x == nullptr || T_slot_ < 0)
    return;
  const auto values = x->getData();
  for (std::size_t i = 0; i < dofs_.owned_nodes().size(); ++i)
    frozen_temperature_.push_back(values[F_ * i + T_slot_]);
}

CoupledProblem::ContactOutput CoupledProblem::contact_output(const Vector &x)
{
  const auto &comm = *dofs_.owned_dof_map()->getComm();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ContactOutput out{std::vector<double>(mesh_.n_nodes(), nan),
                    std::vector<double>(mesh_.n_nodes(), nan)};
  if (pairs_.empty())
    return out;
  evaluate(x, f_work_.get(), nullptr);
  const int n = static_cast<int>(pairs_.size());
  std::vector<double> local(2 * static_cast<std::size_t>(n), 0.0), global(local.size(), 0.0);
  for (std::size_t i = 0; i < owned_pairs_.size(); ++i)
  {
    local[owned_pairs_[i]] = active_[i] ? -pressure_[i] : 0.0;
    local[n + owned_pairs_[i]] = active_[i] ? 1.0 : 0.0;
  }
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 2 * n, local.data(), global.data());
  for (int k = 0; k < n; ++k)
    for (const int node : {pairs_[k].a, pairs_[k].b})
    {
      out.traction[node] = global[k];
      out.active[node] = global[n + k];
    }
  return out;
}
} // namespace kiln
