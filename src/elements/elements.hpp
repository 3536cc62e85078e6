#pragma once
/// The element types' makers (one file each in this folder), registered by
/// FiniteElement::of() in finite_element_table.cpp; and the small 1D and barycentric
/// Lagrange helpers several of them share.
#include "elements/finite_element.hpp"

#include <memory>

namespace kiln::elements
{
std::unique_ptr<FiniteElement> make_hex8();
std::unique_ptr<FiniteElement> make_tet4();
std::unique_ptr<FiniteElement> make_wedge6();
std::unique_ptr<FiniteElement> make_pyramid5();
std::unique_ptr<FiniteElement> make_tet10();
std::unique_ptr<FiniteElement> make_hex20();
std::unique_ptr<FiniteElement> make_hex27();
std::unique_ptr<FiniteElement> make_quad4();
std::unique_ptr<FiniteElement> make_tri3();
std::unique_ptr<FiniteElement> make_quad8();
std::unique_ptr<FiniteElement> make_quad9();
std::unique_ptr<FiniteElement> make_tri6();

/// The quadratic 1D Lagrange function on [-1, 1] of the node at r (-1, 0 or 1), at t.
inline double lagrange2(const double r, const double t)
{
  return r == 0 ? 1 - t * t : 0.5 * t * (t + r);
}
/// Its derivative.
inline double lagrange2_derivative(const double r, const double t)
{
  return r == 0 ? -2 * t : t + 0.5 * r;
}

/// The unit simplex's barycentric coordinates at xi (dim 2 or 3): l[0] = 1 - Σ xi_k, l[k] =
/// xi_{k-1}; their gradients are -1 (l[0]) and the unit vectors.
inline void barycentric(const Point &xi, const int dim, double *l)
{
  l[0] = 1 - xi[0] - xi[1] - (dim == 3 ? xi[2] : 0.0);
  for (int k = 0; k < dim; ++k)
    l[k + 1] = xi[k];
}
inline Point barycentric_gradient(const int k, const int dim)
{
  if (k == 0)
    return {-1.0, -1.0, dim == 3 ? -1.0 : 0.0};
  Point g{0, 0, 0};
  g[k - 1] = 1.0;
  return g;
}

/// The quadratic simplex basis (TRI6, TETRA10): corner i: l_i (2 l_i - 1); the mid-edge
/// node of edge (a, b): 4 l_a l_b; `edges` the edges in mid-edge node order.
template <int n_edges>
void simplex2_values(const Point &xi, const int dim, const int (&edges)[n_edges][2], double *N)
{
  double l[4];
  barycentric(xi, dim, l);
  for (int i = 0; i <= dim; ++i)
    N[i] = l[i] * (2 * l[i] - 1);
  for (int e = 0; e < n_edges; ++e)
    N[dim + 1 + e] = 4 * l[edges[e][0]] * l[edges[e][1]];
}
template <int n_edges>
void simplex2_gradients(const Point &xi, const int dim, const int (&edges)[n_edges][2], Point *dN)
{
  double l[4];
  barycentric(xi, dim, l);
  for (int i = 0; i <= dim; ++i)
  {
    const Point g = barycentric_gradient(i, dim);
    for (int k = 0; k < 3; ++k)
      dN[i][k] = (4 * l[i] - 1) * g[k];
  }
  for (int e = 0; e < n_edges; ++e)
  {
    const int a = edges[e][0], b = edges[e][1];
    const Point ga = barycentric_gradient(a, dim), gb = barycentric_gradient(b, dim);
    for (int k = 0; k < 3; ++k)
      dN[dim + 1 + e][k] = 4 * (ga[k] * l[b] + l[a] * gb[k]);
  }
}

/// The tensor-product quadratic Lagrange basis (QUAD9, HEX27) of `cell` (dim 2 or 3): node i
/// at r has N_i = Π_k lagrange2(r_k, xi_k). The three 1D functions are evaluated once per
/// coordinate, then multiplied node by node.
inline void tensor2_values(const ReferenceCell &cell, const Point &xi, double *N)
{
  const int dim = cell.dim();
  double l[3][3] = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}; // l[k][r + 1]
  for (int k = 0; k < dim; ++k)
    for (int r = -1; r <= 1; ++r)
      l[k][r + 1] = lagrange2(r, xi[k]);
  for (int i = 0; i < cell.n_nodes(); ++i)
  {
    const Point &r = cell.node(i);
    N[i] = l[0][static_cast<int>(r[0]) + 1] * l[1][static_cast<int>(r[1]) + 1] *
           l[2][static_cast<int>(r[2]) + 1];
  }
}
inline void tensor2_gradients(const ReferenceCell &cell, const Point &xi, Point *dN)
{
  const int dim = cell.dim();
  double l[3][3] = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}, dl[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  for (int k = 0; k < dim; ++k)
    for (int r = -1; r <= 1; ++r)
    {
      l[k][r + 1] = lagrange2(r, xi[k]);
      dl[k][r + 1] = lagrange2_derivative(r, xi[k]);
    }
  for (int i = 0; i < cell.n_nodes(); ++i)
  {
    const Point &r = cell.node(i);
    const int a = static_cast<int>(r[0]) + 1, b = static_cast<int>(r[1]) + 1,
              c = static_cast<int>(r[2]) + 1;
    dN[i] = {dl[0][a] * l[1][b] * l[2][c], l[0][a] * dl[1][b] * l[2][c],
             l[0][a] * l[1][b] * dl[2][c]};
  }
}

/// The quadratic serendipity basis (QUAD8, HEX20) of `cell` (dim 2 or 3): corner r:
/// 2^-dim Π_k (1 + r_k xi_k) (Σ_k r_k xi_k - dim + 1); mid-edge node r (one r_k = 0):
/// 2^(1-dim) Π_k f_k with f_k = 1 - xi_k^2 where r_k = 0, else 1 + r_k xi_k.
inline void serendipity_values(const ReferenceCell &cell, const Point &xi, double *N)
{
  const int dim = cell.dim();
  for (int i = 0; i < cell.n_nodes(); ++i)
  {
    const Point &r = cell.node(i);
    const bool corner = i < cell.n_vertices();
    double product = corner ? 1.0 / (1 << dim) : 1.0 / (1 << (dim - 1)), sum = 1.0 - dim;
    for (int k = 0; k < dim; ++k)
    {
      product *= r[k] == 0 ? 1 - xi[k] * xi[k] : 1 + r[k] * xi[k];
      sum += r[k] * xi[k];
    }
    N[i] = corner ? product * sum : product;
  }
}
inline void serendipity_gradients(const ReferenceCell &cell, const Point &xi, Point *dN)
{
  const int dim = cell.dim();
  for (int i = 0; i < cell.n_nodes(); ++i)
  {
    const Point &r = cell.node(i);
    const bool corner = i < cell.n_vertices();
    const double scale = corner ? 1.0 / (1 << dim) : 1.0 / (1 << (dim - 1));
    double f[3], df[3], sum = 1.0 - dim;
    for (int k = 0; k < dim; ++k)
    {
      f[k] = r[k] == 0 ? 1 - xi[k] * xi[k] : 1 + r[k] * xi[k];
      df[k] = r[k] == 0 ? -2 * xi[k] : r[k];
      sum += r[k] * xi[k];
    }
    dN[i] = {0, 0, 0};
    for (int k = 0; k < dim; ++k)
    {
      double p = scale * df[k], q = scale; // ∂(Π f)/∂xi_k, and Π f
      for (int m = 0; m < dim; ++m)
      {
        q *= f[m];
        if (m != k)
          p *= f[m];
      }
      dN[i][k] = corner ? p * sum + q * r[k] : p;
    }
  }
}

/// The linear simplex basis (TRI3, TETRA4): N_i = l_i.
inline void simplex1_values(const Point &xi, const int dim, double *N)
{
  barycentric(xi, dim, N);
}
inline void simplex1_gradients(const int dim, Point *dN)
{
  for (int i = 0; i <= dim; ++i)
    dN[i] = barycentric_gradient(i, dim);
}
} // namespace kiln::elements
