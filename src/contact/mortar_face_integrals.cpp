#include "contact/mortar_face_integrals.hpp"

#include "contact/dual_basis.hpp"
#include "contact/gap_opening.hpp"
#include "elements/finite_element.hpp"
#include "mesh/mesh.hpp"

#include <array>

namespace kiln
{
MortarFaceIntegrals::MortarFaceIntegrals(const MortarFace &secondary,
                                         const std::vector<MortarFace> &primaries)
{
  const FiniteElement &fe_s = FiniteElement::of(secondary.type);
  const int n = n_shape_ = fe_s.n_shape();
  D_.assign(static_cast<std::size_t>(n * n), 0.0);
  weighted_gap_.assign(n, 0.0);
  for (const MortarFace &primary : primaries)
  {
    n_primary_.push_back(FiniteElement::of(primary.type).n_shape());
    M_.emplace_back(static_cast<std::size_t>(n * n_primary_.back()), 0.0);
  }
  std::vector<MortarSegments> segments;
  segments.reserve(primaries.size());
  std::size_t n_points = 0;
  for (const MortarFace &primary : primaries)
  {
    segments.emplace_back(secondary, primary);
    covered_area_ += segments.back().area();
    n_points += segments.back().points().size();
  }
  std::vector<MortarPoint> covered;
  covered.reserve(n_points);
  for (const MortarSegments &segment : segments)
    covered.insert(covered.end(), segment.points().begin(), segment.points().end());
  if (covered.empty())
    return;
  const DualBasis dual(secondary.type, covered);
  std::array<double, max_cell_nodes> psi{}, N{}, N_m{};
  for (std::size_t p = 0; p < primaries.size(); ++p)
  {
    const FiniteElement &fe_m = FiniteElement::of(primaries[p].type);
    const Point &outward = segments[p].normal(); // the secondary face's, towards the primary
    const Point normal{-outward[0], -outward[1], -outward[2]};
    for (const MortarPoint &q : segments[p].points())
    {
      fe_s.values(q.xi_s, N.data());
      fe_m.values(q.xi_m, N_m.data());
      dual.values_from_shape(N.data(), psi.data());
      // The faces' points at xi_s and xi_m (face_point's sums, with the values at hand).
      Point x_s{0, 0, 0}, x_m{0, 0, 0};
      for (int j = 0; j < n; ++j)
        for (int d = 0; d < 3; ++d)
          x_s[d] += N[j] * secondary.x[j][d];
      for (int k = 0; k < n_primary_[p]; ++k)
        for (int d = 0; d < 3; ++d)
          x_m[d] += N_m[k] * primaries[p].x[k][d];
      const double gap = gap_opening(normal, x_m, x_s);
      for (int i = 0; i < n; ++i)
      {
        const double psi_w = psi[i] * q.weight;
        for (int j = 0; j < n; ++j)
          D_[i * n + j] += psi_w * N[j];
        for (int k = 0; k < n_primary_[p]; ++k)
          M_[p][i * n_primary_[p] + k] += psi_w * N_m[k];
        weighted_gap_[i] += psi_w * gap;
      }
    }
  }
}
} // namespace kiln
