#include "contact/normal_contact.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "contact/gap_opening.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_OrdinalTraits.hpp>

#include <algorithm>
#include <limits>

namespace kiln
{
Teuchos::ParameterList NormalContact::valid_parameters()
{
  Teuchos::ParameterList p("Contact");
  p.set("Enabled", true,
        "true: the two sides of the gap may separate but not interpenetrate, and carry a "
        "compressive normal traction when in contact (frictionless); false: they are separate "
        "bodies that pass through each other [-]");
  const auto &functions = complementarity_functions();
  p.set("Complementarity Function", functions.names().front(),
        "how g >= 0, p >= 0, p g = 0 enters the Newton solve: " + functions.describe() +
            ". After an active-set cycle a step switches to Fischer-Burmeister anyway",
        choice_validator(functions.names()));
  p.set("Complementarity Scale", 1.0,
        "s in c = s (lambda + 2G) / sqrt(A), A the pair's area: weighs the gap against the "
        "pressure; it changes the Newton path, not the converged answer; must be > 0 [-]",
        positive_double_validator());
  return p;
}

NormalContact::NormalContact(const ContactInterface &interface, const DofManager &dofs,
                             const Assembler &assembler, const NodalConstraints &constraints,
                             const Teuchos::ParameterList &contact)
    : interface_(interface), dofs_(dofs), assembler_(assembler), constraints_(constraints),
      u_slot_(dofs.layout().slot(Field::ux)),
      function_(
          complementarity_functions().create(contact.get<std::string>("Complementarity Function"))),
      fallback_(complementarity_functions().create("Fischer-Burmeister")),
      monitor_(dofs.owned_dof_map()->getComm(), interface.n_pairs(),
               static_cast<int>(interface.owned_pairs().size())),
      x_(Teuchos::rcp(new Vector(dofs.owned_dof_map()))),
      F_(Teuchos::rcp(new Vector(dofs.owned_dof_map()))),
      R_overlap_(assembler.make_overlap_vector()), value_(interface.pairs().size()),
      active_(interface.owned_pairs().size(), 0), pressure_(interface.owned_pairs().size(), 0.0)
{
}

bool NormalContact::decided_at(const Vector &x) const
{
  int same = decided_ ? 1 : 0;
  if (same == 1)
  {
    const auto a = x.getData(), b = x_->getData();
    same = std::equal(a.begin(), a.end(), b.begin()) ? 1 : 0;
  }
  int everywhere = 0;
  Teuchos::reduceAll(*dofs_.owned_dof_map()->getComm(), Teuchos::REDUCE_MIN, same,
                     Teuchos::outArg(everywhere));
  return everywhere == 1;
}

void NormalContact::decide(const Vector &x, Vector &R, const std::function<Point(int)> &u)
{
  const auto owned_map = dofs_.owned_dof_map();
  const auto overlap_map = dofs_.overlap_dof_map();
  const LO invalid = Teuchos::OrdinalTraits<LO>::invalid();
  // Every rank with a pair in its overlap (both nodes or neither: twins come together)
  // decides it alike, from the assembled rows.
  assembler_.gather(R, *R_overlap_);
  const ComplementarityFunction &function = monitor_.fallback() ? *fallback_ : *function_;
  {
    const auto r = R_overlap_->getData();
    auto values = R.getDataNonConst();
    std::size_t owned_index = 0;
    const auto &pairs = interface_.pairs();
    for (std::size_t k = 0; k < pairs.size(); ++k)
    {
      const ContactInterface::Pair &pair = pairs[k];
      const GO gid_a = dofs_.node_dof(pair.a, u_slot_ + pair.slot_a);
      const GO gid_b = dofs_.node_dof(pair.b, u_slot_ + pair.slot_b);
      if (overlap_map->getLocalElement(gid_a) == invalid)
        continue;
      const LO a = assembler_.lid(gid_a), b = assembler_.lid(gid_b);
      const double P = (r[b] - r[a]) / (2.0 * pair.area);
      const double cg = pair.c * gap_opening(pair.normal, u(pair.a), u(pair.b));
      value_[k] = function.evaluate(P, cg);
      const LO owned_a = owned_map->getLocalElement(gid_a);
      const LO owned_b = owned_map->getLocalElement(gid_b);
      if (value_[k].combined && owned_a != invalid)
        values[owned_a] = r[a] + r[b] - pair.area * value_[k].C;
      if (owned_b != invalid)
      {
        if (value_[k].combined)
          values[owned_b] = pair.area * value_[k].C;
        KILN_ASSERT(interface_.owned_pairs()[owned_index] == static_cast<int>(k),
                    "owned pairs out of order");
        pressure_[owned_index] = P;
        active_[owned_index] = P - cg > 0.0;
        ++owned_index;
      }
    }
  }
  Tpetra::deep_copy(*x_, x);
  Tpetra::deep_copy(*F_, R);
  decided_ = true;
}

void NormalContact::jacobian_evaluated()
{
  const bool fallback = monitor_.fallback();
  monitor_.jacobian_evaluated(active_);
  if (monitor_.fallback() != fallback)
    decided_ = false;
}

std::optional<std::pair<std::vector<int>, LocalSystem>>
NormalContact::with_twins(const std::vector<int> &nodes, const LocalSystem &local) const
{
  std::vector<int> extended_nodes = assembler_.with_twins(nodes);
  if (extended_nodes.size() == nodes.size())
    return std::nullopt;
  const int F = local.n_fields();
  LocalSystem extended(static_cast<int>(extended_nodes.size()), F, local.has_jacobian());
  const int m = local.size();
  for (int i = 0; i < m; ++i)
  {
    extended.residual(i % F, i / F) = local.residual_values()[i];
    if (local.has_jacobian())
      for (int j = 0; j < m; ++j)
        extended.jacobian(i % F, i / F, j % F, j / F) =
            local.jacobian_values()[static_cast<std::size_t>(i) * m + j];
  }
  return std::make_pair(std::move(extended_nodes), std::move(extended));
}

void NormalContact::combine_rows(const std::vector<int> &nodes, LocalSystem &local) const
{
  const int n_local = local.n_nodes();
  const int m = local.size();
  auto &jac = local.jacobian_values();
  const auto &pairs = interface_.pairs();
  for (int i = 0; i < n_local; ++i)
  {
    const int k = interface_.pair_of_node(nodes[i]);
    if (k < 0 || nodes[i] != pairs[k].a || !value_[k].combined)
      continue;
    const int j =
        static_cast<int>(std::find(nodes.begin(), nodes.end(), pairs[k].b) - nodes.begin());
    KILN_ASSERT(j < n_local, "a local system lacks the twin of node " << nodes[i]);
    const std::size_t ia = local.index(u_slot_ + pairs[k].slot_a, i);
    const std::size_t ib = local.index(u_slot_ + pairs[k].slot_b, j);
    const double w = 0.5 * value_[k].dC_dP;
    for (int c = 0; c < m; ++c)
    {
      const double va = jac[ia * m + c], vb = jac[ib * m + c];
      jac[ib * m + c] = w * (vb - va);
      jac[ia * m + c] = va + vb - jac[ib * m + c];
    }
  }
}

void NormalContact::add_pair_terms(Assembler &assembler) const
{
  const int F = dofs_.n_node_fields();
  LocalSystem local(2, F);
  for (const int k : interface_.owned_pairs())
  {
    if (!value_[k].combined)
      continue;
    const ContactInterface::Pair &pair = interface_.pairs()[k];
    // d(A C)/dû = A c dC/d(cg) dg/dû, g = n.(u_b - u_a), u = sum_k û_k q_k: the columns of
    // the unknowns that are not constrained (those are fixed at their prescribed values).
    const double w = pair.area * pair.c * value_[k].dC_dcg;
    local.clear();
    // Row b gets them; row a, which is R_a + R_b - A C, minus them.
    for (int side = 0; side < 2; ++side)
    {
      const int node = side == 0 ? pair.a : pair.b;
      const auto &q = constraints_.axes(node);
      for (int l = constraints_.n_constrained(node); l < 3; ++l)
      {
        const double d = (side == 0 ? -w : w) * dot(pair.normal, q[l]);
        local.jacobian(u_slot_ + pair.slot_b, 1, u_slot_ + l, side) = d;
        local.jacobian(u_slot_ + pair.slot_a, 0, u_slot_ + l, side) = -d;
      }
    }
    assembler.add(assembler.node_lids({pair.a, pair.b}), local);
  }
}

NormalContact::NodeValues NormalContact::node_values() const
{
  const auto &comm = *dofs_.owned_dof_map()->getComm();
  const int n = interface_.n_pairs();
  const int n_nodes = static_cast<int>(dofs_.node_owner().size());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  NodeValues out{std::vector<double>(n_nodes, nan), std::vector<double>(n_nodes, nan)};
  std::vector<double> local(2 * static_cast<std::size_t>(n), 0.0), global(local.size(), 0.0);
  const auto &owned = interface_.owned_pairs();
  for (std::size_t i = 0; i < owned.size(); ++i)
  {
    local[owned[i]] = active_[i] ? -pressure_[i] : 0.0;
    local[n + owned[i]] = active_[i] ? 1.0 : 0.0;
  }
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 2 * n, local.data(), global.data());
  for (int k = 0; k < n; ++k)
    for (const int node : {interface_.pairs()[k].a, interface_.pairs()[k].b})
    {
      out.traction[node] = global[k];
      out.active[node] = global[n + k];
    }
  return out;
}

std::vector<double> NormalContact::jacobian_dependencies() const
{
  KILN_ASSERT(decided_, "jacobian_dependencies() needs a decision");
  std::vector<double> d;
  d.reserve(3 * value_.size());
  for (const ComplementarityFunction::Value &v : value_)
    d.insert(d.end(), {v.combined ? 1.0 : 0.0, v.dC_dP, v.dC_dcg});
  return d;
}
} // namespace kiln
