#pragma once
/// The mortar integrals of one secondary face against the primary faces it may overlap
/// (doc/contact.md, "Separately meshed bodies (issue 30): design"), over its segments with each
/// (MortarSegments) and with its dual basis on the covered part (DualBasis):
///   D_ij    = ∫ psi_i N_j                (i, j nodes of the secondary face; diagonal)
///   M_(i,p,k) = ∫ psi_i N^p_k             (k a node of primary face p)
///   g~_i    = ∫ psi_i n . (x_s - x_m)     (the weighted gap: n the unit normal from the
///                                          primary to the secondary side, minus the segments'
///                                          normal; x_s, x_m the points of the two faces that
///                                          the normal joins; gap_opening, > 0 open)
/// Summed over a surface's faces by node, they give the rows of the mortar pairing.
#include "contact/mortar_segments.hpp"

#include <vector>

namespace kiln
{
class MortarFaceIntegrals
{
public:
  MortarFaceIntegrals(const MortarFace &secondary, const std::vector<MortarFace> &primaries);

  /// Whether some primary face overlaps the secondary face (else every integral is 0).
  bool covered() const { return covered_area_ > 0; }
  /// The covered part's area [m^2].
  double covered_area() const { return covered_area_; }
  int n_shape() const { return n_shape_; }
  /// D_ij [m^2].
  double D(const int i, const int j) const { return D_[i * n_shape_ + j]; }
  /// M_(i,p,k) [m^2]: secondary node i, primary face p (the constructor's order), its node k.
  double M(const int i, const int p, const int k) const { return M_[p][i * n_primary_[p] + k]; }
  /// g~_i [m^3].
  double weighted_gap(const int i) const { return weighted_gap_[i]; }

private:
  int n_shape_ = 0;
  double covered_area_ = 0.0;
  std::vector<double> D_;
  std::vector<int> n_primary_;
  std::vector<std::vector<double>> M_;
  std::vector<double> weighted_gap_;
};
} // namespace kiln
