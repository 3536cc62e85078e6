#pragma once
/// One row of an interface's pairing (doc/contact.md, "Separately meshed bodies (issue 30):
/// design", "The shape"): a secondary node j with its normal, its area D_jj, its initial gap
/// and its partners, the primary nodes k with weights w_jk = M_jk / D_jj. The split gap's pair
/// (a, b) is the row of node b with the one partner a of weight 1, D_jj = A and g0 = 0; a
/// mortar pairing (MortarPairing) gives rows with several partners and a geometric g0.
#include "mesh/mesh.hpp"

#include <vector>

namespace kiln
{
struct ContactRow
{
  int node = -1;   ///< the secondary mesh node j (the split gap's node b)
  Point normal{};  ///< n_j, unit, from the primary to the secondary side
  double area = 0; ///< D_jj [m^2] (the split gap: A, the integral of phi_a over its faces)
  /// g0_j = n_j . (X_j - sum_k w_jk X_k) [m]: the opening in the reference configuration, so
  /// that g_j = g0_j + n_j . (u_j - sum_k w_jk u_k) (gap_opening); 0 for a split gap.
  double gap0 = 0;
  std::vector<int> partners;   ///< the primary mesh nodes k (the split gap: node a)
  std::vector<double> weights; ///< w_jk, as many as partners, summing to 1 [-]
  /// The slip of a mortar pairing's row since its last search beyond which it is searched
  /// again (PairResearch; with rows fixed, e.g. a test's pairing, not searched):
  /// `Search Update Fraction` times `face_size`, the smallest diameter of j's secondary faces
  /// [m]; 0: not checked (a split gap, whose sides share their nodes' positions).
  double slip_limit = 0;
  double face_size = 0;
  /// The relative displacement u_j - sum_k w_jk u_k at the state of the row's last search [m]
  /// (0 at set-up): the slip is measured from it (row_slip).
  Point slip0{};
};
} // namespace kiln
