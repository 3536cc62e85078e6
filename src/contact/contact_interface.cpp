#include "contact/contact_interface.hpp"

#include "base/errors.hpp"

#include <cmath>

namespace kiln
{
ContactInterface::ContactInterface(const Mesh &mesh, const DofManager &dofs,
                                   NodalConstraints &constraints, const double modulus,
                                   const double scale, const std::string &where)
    : pair_of_node_(mesh.n_nodes(), -1)
{
  const int rank = dofs.owned_dof_map()->getComm()->getRank();
  for (const GapPair &gap_pair : mesh.gap_pairs)
  {
    Pair pair;
    pair.a = gap_pair.node_a;
    pair.b = gap_pair.node_b;
    pair.area = gap_pair.area;
    pair.c = scale * modulus / std::sqrt(gap_pair.area);
    pair.normal = gap_pair.normal;
    for (const int node : {pair.a, pair.b})
    {
      for (const NodalConstraints::Direction &d : constraints.directions(node))
      {
        const double cosine = dot(d.axis, pair.normal);
        const Point &x = mesh.coordinates[node];
        KILN_CHECK_INPUT(std::abs(cosine) <= 1e-6, where,
                         "cannot hold: the condition \""
                             << constraints.value_name(d.value) << "\" constrains gap node " << node
                             << " at (" << x[0] << ", " << x[1] << ", " << x[2]
                             << ") in a direction at cos = " << cosine
                             << " to the gap normal, which contact needs free. Apply it on faces "
                                "perpendicular to the gap, or set \"Enabled\" = false");
      }
      const int slot = constraints.add_free_axis(node, pair.normal);
      KILN_CHECK_INPUT(slot >= 0, where,
                       "cannot hold: gap node " << node
                                                << " has its displacement fully prescribed; "
                                                   "remove the condition there or set "
                                                   "\"Enabled\" = false");
      (node == pair.a ? pair.slot_a : pair.slot_b) = slot;
      pair_of_node_[node] = static_cast<int>(pairs_.size());
    }
    if (dofs.node_owner()[pair.b] == rank)
      owned_pairs_.push_back(static_cast<int>(pairs_.size()));
    pairs_.push_back(pair);
  }
}
} // namespace kiln
