#include "contact/contact_interface.hpp"

#include <cmath>

namespace kiln
{
ContactInterface::ContactInterface(const Mesh &mesh, const DofManager &dofs, const double modulus,
                                   const double scale)
    : mesh_(mesh), pair_of_node_(mesh.n_nodes(), -1)
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
    pair_of_node_[pair.a] = pair_of_node_[pair.b] = static_cast<int>(pairs_.size());
    if (dofs.node_owner()[pair.b] == rank)
      owned_pairs_.push_back(static_cast<int>(pairs_.size()));
    pairs_.push_back(pair);
  }
}
} // namespace kiln
