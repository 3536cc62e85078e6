#include "contact/dual_basis.hpp"

#include "base/errors.hpp"
#include "elements/finite_element.hpp"

#include <array>
#include <cmath>
#include <utility>

namespace kiln
{
namespace
{
/// The inverse of the symmetric positive definite n x n matrix `m` (row major), by
/// Gauss-Jordan elimination with partial pivoting.
std::vector<double> inverse(std::vector<double> m, const int n)
{
  std::vector<double> inv(static_cast<std::size_t>(n * n), 0.0);
  for (int i = 0; i < n; ++i)
    inv[i * n + i] = 1.0;
  for (int c = 0; c < n; ++c)
  {
    int pivot = c;
    for (int r = c + 1; r < n; ++r)
      if (std::abs(m[r * n + c]) > std::abs(m[pivot * n + c]))
        pivot = r;
    KILN_ASSERT(m[pivot * n + c] != 0.0, "DualBasis: a singular mass matrix");
    for (int k = 0; k < n; ++k)
    {
      std::swap(m[c * n + k], m[pivot * n + k]);
      std::swap(inv[c * n + k], inv[pivot * n + k]);
    }
    const double p = m[c * n + c];
    for (int k = 0; k < n; ++k)
    {
      m[c * n + k] /= p;
      inv[c * n + k] /= p;
    }
    for (int r = 0; r < n; ++r)
      if (r != c && m[r * n + c] != 0.0)
      {
        const double f = m[r * n + c];
        for (int k = 0; k < n; ++k)
        {
          m[r * n + k] -= f * m[c * n + k];
          inv[r * n + k] -= f * inv[c * n + k];
        }
      }
  }
  return inv;
}
} // namespace

DualBasis::DualBasis(const CellType type, const std::vector<MortarPoint> &covered)
    : type_(type), n_shape_(FiniteElement::of(type).n_shape())
{
  if (covered.empty())
    throw InternalError("DualBasis: the face is not covered (no mortar points)");
  const FiniteElement &fe = FiniteElement::of(type);
  const int n = n_shape_;
  std::vector<double> mass(static_cast<std::size_t>(n * n), 0.0), integral(n, 0.0);
  std::array<double, max_cell_nodes> N{};
  for (const MortarPoint &p : covered)
  {
    fe.values(p.xi_s, N.data());
    for (int i = 0; i < n; ++i)
    {
      integral[i] += N[i] * p.weight;
      for (int j = 0; j < n; ++j)
        mass[i * n + j] += N[i] * N[j] * p.weight;
    }
  }
  A_ = inverse(std::move(mass), n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      A_[i * n + j] *= integral[i];
}

void DualBasis::values(const Point &xi, double *psi) const
{
  std::array<double, max_cell_nodes> N{};
  FiniteElement::of(type_).values(xi, N.data());
  values_from_shape(N.data(), psi);
}

void DualBasis::values_from_shape(const double *N, double *psi) const
{
  for (int i = 0; i < n_shape_; ++i)
  {
    psi[i] = 0.0;
    for (int j = 0; j < n_shape_; ++j)
      psi[i] += coefficient(i, j) * N[j];
  }
}
} // namespace kiln
