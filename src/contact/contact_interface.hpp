#pragma once
/// The contact interface: the node pairs across the gap, their areas, normals and owners.
#include "discretization/dof_manager.hpp"
#include "discretization/nodal_constraints.hpp"
#include "mesh/mesh.hpp"

#include <string>
#include <vector>

namespace kiln
{
/// One pair (a, b) per gap node of side a and its twin (Mesh::gap_pairs), with the normal n
/// from a to b and the area A (∫φ_a over side a's gap faces). n.u is an unknown of each
/// node of a pair: the interface gives each a free axis n in its nodal frame
/// (NodalConstraints), so the normal rows of the pair can be combined (NormalContact). The
/// pair belongs to the rank that owns node b.
class ContactInterface
{
public:
  struct Pair
  {
    int a = -1, b = -1; ///< mesh nodes
    double area = 0.0;  ///< A [m^2]
    double c = 0.0;     ///< the complementarity constant c = s (lambda + 2G)/sqrt(A) [Pa/m]
    Point normal{};     ///< n, from a to b
    int slot_a = 0;     ///< the slot of n.u among node a's displacement unknowns
    int slot_b = 0;
  };

  /// Adds the free axes to `constraints` (before it is closed). `modulus` is lambda + 2G
  /// [Pa], `scale` the input's "Complementarity Scale". Throws InputError (naming `where`)
  /// when a constraint at a gap node is not perpendicular to the gap normal or fixes the node.
  ContactInterface(const Mesh &mesh, const DofManager &dofs, NodalConstraints &constraints,
                   double modulus, double scale, const std::string &where);

  const std::vector<Pair> &pairs() const { return pairs_; }
  int n_pairs() const { return static_cast<int>(pairs_.size()); }
  /// The pairs whose node b this rank owns, increasing.
  const std::vector<int> &owned_pairs() const { return owned_pairs_; }
  /// The pair of a gap node (either side), or -1.
  int pair_of_node(const int node) const { return pair_of_node_[node]; }

private:
  std::vector<Pair> pairs_;
  std::vector<int> owned_pairs_;
  std::vector<int> pair_of_node_;
};
} // namespace kiln
