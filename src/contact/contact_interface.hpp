#pragma once
/// The pairing across the gap: the node pairs, their areas, normals and owners.
#include "discretization/dof_manager.hpp"
#include "mesh/mesh.hpp"

#include <vector>

namespace kiln
{
/// One pair (a, b) per gap node of side a and its twin (Mesh::gap_pairs), with the normal n
/// from a to b and the area A (∫φ_a over side a's gap faces). The pair belongs to the rank
/// that owns node b. The interface kinds (InterfaceStrategy) claim their axes in the nodes'
/// frames and decide the pairs' conditions.
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

  /// `modulus` is lambda + 2G [Pa], `scale` the input's "Complementarity Scale".
  ContactInterface(const Mesh &mesh, const DofManager &dofs, double modulus, double scale);

  const Mesh &mesh() const { return mesh_; }
  const std::vector<Pair> &pairs() const { return pairs_; }
  int n_pairs() const { return static_cast<int>(pairs_.size()); }
  /// The pairs whose node b this rank owns, increasing.
  const std::vector<int> &owned_pairs() const { return owned_pairs_; }
  /// The pair of a gap node (either side), or -1.
  int pair_of_node(const int node) const { return pair_of_node_[node]; }

private:
  const Mesh &mesh_;
  std::vector<Pair> pairs_;
  std::vector<int> owned_pairs_;
  std::vector<int> pair_of_node_;
};
} // namespace kiln
