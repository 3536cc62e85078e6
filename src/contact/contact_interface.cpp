#include "contact/contact_interface.hpp"

#include <cmath>
#include <vector>

namespace kiln
{
ContactInterface::ContactInterface(const Mesh &mesh, const DofManager &dofs, const int gap,
                                   const double modulus, const double scale)
    : mesh_(mesh), gap_(gap), offsets_(mesh.n_nodes() + 1, 0)
{
  const int rank = dofs.owned_dof_map()->getComm()->getRank();
  for (const GapPair &gap_pair : mesh.gap_pairs)
  {
    if (gap_pair.gap != gap)
      continue;
    Pair pair;
    pair.a = gap_pair.node_a;
    pair.b = gap_pair.node_b;
    pair.area = gap_pair.area;
    pair.c = scale * modulus / std::sqrt(gap_pair.area);
    pair.normal = gap_pair.normal;
    ++offsets_[pair.a + 1];
    if (dofs.node_owner()[pair.b] == rank)
      owned_pairs_.push_back(static_cast<int>(pairs_.size()));
    pairs_.push_back(pair);
  }
  for (int n = 0; n < mesh.n_nodes(); ++n)
    offsets_[n + 1] += offsets_[n];
  pairs_of_a_.resize(pairs_.size());
  std::vector<int> next(offsets_.begin(), offsets_.end() - 1);
  for (std::size_t k = 0; k < pairs_.size(); ++k)
    pairs_of_a_[next[pairs_[k].a]++] = static_cast<int>(k);
}
} // namespace kiln
