#pragma once
/// The pairing across the gap: the node pairs, their areas, normals and owners.
#include "discretization/dof_manager.hpp"
#include "mesh/mesh.hpp"

#include <utility>
#include <vector>

namespace kiln
{
/// The pairs (a, b) of one gap (Mesh::gap_pairs whose `gap` it is), with the normal n from a
/// to b and the area A (∫φ_a over side a's gap faces). The pair belongs to the rank that owns
/// node b. The interface kinds (InterfaceStrategy) claim their axes in the nodes' frames and
/// decide the pairs' conditions.
class ContactInterface
{
public:
  struct Pair
  {
    int a = -1, b = -1; ///< mesh nodes
    double area = 0.0;  ///< A [m^2]
    double c = 0.0;     ///< the complementarity constant c = s (lambda + 2G)/sqrt(A) [Pa/m]
    Point normal{};     ///< n, from a to b
  };

  /// The pairs of gap `gap` (an index into Mesh::gap_side_sets). `modulus` is lambda + 2G
  /// [Pa], `scale` the input's "Complementarity Scale".
  ContactInterface(const Mesh &mesh, const DofManager &dofs, int gap, double modulus, double scale);

  const Mesh &mesh() const { return mesh_; }
  const std::vector<Pair> &pairs() const { return pairs_; }
  int n_pairs() const { return static_cast<int>(pairs_.size()); }
  /// The pairs whose node b this rank owns, increasing.
  const std::vector<int> &owned_pairs() const { return owned_pairs_; }
  int gap() const { return gap_; }
  /// The pairs whose node a is `node` (several where gaps cross), as [begin, end).
  std::pair<const int *, const int *> pairs_of_node_a(const int node) const
  {
    return {pairs_of_a_.data() + offsets_[node], pairs_of_a_.data() + offsets_[node + 1]};
  }

private:
  const Mesh &mesh_;
  int gap_;
  std::vector<Pair> pairs_;
  std::vector<int> owned_pairs_;
  std::vector<int> offsets_;    ///< per mesh node, into pairs_of_a_ (CSR)
  std::vector<int> pairs_of_a_; ///< the pairs of each node a, increasing
};
} // namespace kiln
