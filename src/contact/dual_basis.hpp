#pragma once
/// The dual basis of a secondary face for the contact pressure (Wohlmuth 2000), on the part of
/// the face that primary faces cover (Cichosz and Bischoff 2011; doc/contact.md, "Dual basis on
/// the covered part"): A_e = diag(∫ N) (∫ N N^T)^-1, both integrals over the covered part,
/// psi_i = Σ_j A_ij N_j. Then ∫ psi_i N_j = δ_ij ∫ N_j over that part: D is diagonal, with
/// D_jj > 0 however little of the face is covered.
#include "contact/mortar_segments.hpp"

#include <vector>

namespace kiln
{
class DualBasis
{
public:
  /// A_e of a secondary face of `type` from the integration points of its segments with all
  /// the primary faces (their xi_s and weights). InternalError if they cover nothing.
  DualBasis(CellType type, const std::vector<MortarPoint> &covered);

  int n_shape() const { return n_shape_; }
  /// A_ij [-].
  double coefficient(const int i, const int j) const { return A_[i * n_shape_ + j]; }
  /// psi_i(xi), i < n_shape(), into `psi`.
  void values(const Point &xi, double *psi) const;
  /// psi_i from the face's standard shape values N_j at a point (FiniteElement::values), when
  /// the caller has them already.
  void values_from_shape(const double *N, double *psi) const;

private:
  CellType type_;
  int n_shape_;
  std::vector<double> A_;
};
} // namespace kiln
