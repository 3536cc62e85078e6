// Tests src/mesh/reference_cells.cpp and src/discretization/elements/ (issue 32), for every
// CellType: N_i(node_j) = δ_ij, Σ N_i = 1 and Σ ∇N_i = 0, gradients against central
// differences, linear (and for the quadratic types quadratic) fields reproduced, quadrature
// weights and monomials up to the stated degree, mass and stiffness integrands on the
// reference cell against a high-order rule, and every face: on a supporting plane of the cell
// with the outward right-hand normal, its mid-side nodes where the face type puts them, and
// the face type's basis equal to the cell basis restricted to it. Plus HEX8's tables equal
// Kiln's hex_face_nodes and hex_gauss_points() exactly.
// KILN_TEST_NP: 1
#include "elements/finite_element.hpp"
#include "elements/quadrature_rules.hpp"
#include "elements/reference_cell.hpp"
#include "mesh/hex_geometry.hpp"
#include "mesh/mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace
{
using kiln::CellType;
using kiln::FiniteElement;
using kiln::Point;
using kiln::Quadrature;
using kiln::ReferenceCell;

enum class Shape
{
  cube,
  simplex,
  wedge,
  pyramid
};

Shape shape_of(const CellType t)
{
  switch (t)
  {
  case CellType::tet4:
  case CellType::tet10:
  case CellType::tri3:
  case CellType::tri6:
    return Shape::simplex;
  case CellType::wedge6:
    return Shape::wedge;
  case CellType::pyramid5:
    return Shape::pyramid;
  default:
    return Shape::cube;
  }
}

double factorial(const int n)
{
  return n <= 1 ? 1.0 : n * factorial(n - 1);
}
double line_monomial(const int p) // ∫_{-1}^{1} t^p
{
  return p % 2 ? 0.0 : 2.0 / (p + 1);
}

/// ∫ x^a y^b z^c over the reference cell (c = 0 on faces).
double exact_monomial(const ReferenceCell &cell, const int a, const int b, const int c)
{
  const int dim = cell.dim();
  switch (shape_of(cell.type()))
  {
  case Shape::cube:
    return line_monomial(a) * line_monomial(b) * (dim == 3 ? line_monomial(c) : 1.0);
  case Shape::simplex:
    return factorial(a) * factorial(b) * factorial(c) / factorial(a + b + c + dim);
  case Shape::wedge:
    return factorial(a) * factorial(b) / factorial(a + b + 2) * line_monomial(c);
  case Shape::pyramid:
    return line_monomial(a) * line_monomial(b) * factorial(c) * factorial(a + b + 2) /
           factorial(a + b + c + 3);
  }
  return 0;
}

/// Whether the type's rule is stated (doc/elements.md) to integrate x^a y^b z^c exactly.
bool stated_exact(const CellType t, const int a, const int b, const int c)
{
  const int total = a + b + c;
  switch (t)
  {
  case CellType::hex8:
  case CellType::quad4:
    return std::max({a, b, c}) <= 3;
  case CellType::hex20:
  case CellType::hex27:
  case CellType::quad8:
  case CellType::quad9:
    return std::max({a, b, c}) <= 5;
  case CellType::tet4:
  case CellType::tri3:
    return total <= 2;
  case CellType::tet10:
  case CellType::tri6:
    return total <= 5;
  case CellType::wedge6:
    return a + b <= 2 && c <= 3;
  case CellType::pyramid5:
    return total <= 3;
  }
  return false;
}

double measure(const ReferenceCell &cell)
{
  return exact_monomial(cell, 0, 0, 0);
}

bool inside(const ReferenceCell &cell, const Point &x, const double tol = 1e-14)
{
  const bool d3 = cell.dim() == 3;
  switch (shape_of(cell.type()))
  {
  case Shape::cube:
    return std::abs(x[0]) <= 1 + tol && std::abs(x[1]) <= 1 + tol &&
           (d3 ? std::abs(x[2]) <= 1 + tol : x[2] == 0);
  case Shape::simplex:
    return x[0] >= -tol && x[1] >= -tol && (d3 ? x[2] >= -tol : x[2] == 0) &&
           x[0] + x[1] + x[2] <= 1 + tol;
  case Shape::wedge:
    return x[0] >= -tol && x[1] >= -tol && x[0] + x[1] <= 1 + tol && std::abs(x[2]) <= 1 + tol;
  case Shape::pyramid:
    return x[2] >= -tol && std::abs(x[0]) <= 1 - x[2] + tol && std::abs(x[1]) <= 1 - x[2] + tol;
  }
  return false;
}

/// `n` random points inside the reference cell (pyramid: z <= 0.9, away from the apex).
std::vector<Point> random_points(const ReferenceCell &cell, const int n, const unsigned seed = 7)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Point> points;
  while (static_cast<int>(points.size()) < n)
  {
    Point x{u(rng), u(rng), cell.dim() == 3 ? u(rng) : 0.0};
    if (shape_of(cell.type()) == Shape::simplex)
      x = {0.5 * (x[0] + 1), 0.5 * (x[1] + 1), cell.dim() == 3 ? 0.5 * (x[2] + 1) : 0.0};
    if (shape_of(cell.type()) == Shape::wedge)
      x = {0.5 * (x[0] + 1), 0.5 * (x[1] + 1), x[2]};
    if (shape_of(cell.type()) == Shape::pyramid)
      x = {x[0], x[1], 0.45 * (x[2] + 1)};
    if (inside(cell, x, 0.0))
      points.push_back(x);
  }
  return points;
}

std::vector<double> values(const FiniteElement &fe, const Point &x)
{
  std::vector<double> N(fe.n_shape());
  fe.values(x, N.data());
  return N;
}
std::vector<Point> gradients(const FiniteElement &fe, const Point &x)
{
  std::vector<Point> dN(fe.n_shape());
  fe.gradients(x, dN.data());
  return dN;
}

/// n-point Gauss-Legendre on [-1, 1] (Newton on P_n), for the high-order reference rules.
Quadrature gauss_legendre(const int n)
{
  Quadrature q;
  for (int i = 0; i < n; ++i)
  {
    double x = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it)
    {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k)
      {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16)
        break;
    }
    q.points.push_back({x, 0, 0});
    q.weights.push_back(2 / ((1 - x * x) * dp * dp));
  }
  return q;
}

/// A rule of high degree (about 15) on the reference cell: tensor Gauss, or collapsed Gauss
/// (Duffy) for simplices and the pyramid.
Quadrature reference_rule(const ReferenceCell &cell)
{
  const Quadrature g = gauss_legendre(10);
  Quadrature q;
  const int n = g.size(), nz = cell.dim() == 3 ? n : 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double a = g.points[i][0], b = g.points[j][0],
                     c = cell.dim() == 3 ? g.points[k][0] : 0;
        const double w = g.weights[i] * g.weights[j] * (cell.dim() == 3 ? g.weights[k] : 1);
        const double u = 0.5 * (a + 1), v = 0.5 * (b + 1), t = 0.5 * (c + 1);
        switch (shape_of(cell.type()))
        {
        case Shape::cube:
          q.points.push_back({a, b, c});
          q.weights.push_back(w);
          break;
        case Shape::simplex:
          if (cell.dim() == 2)
          {
            q.points.push_back({u, v * (1 - u), 0});
            q.weights.push_back(w / 4 * (1 - u));
          }
          else
          {
            q.points.push_back({u, v * (1 - u), t * (1 - u) * (1 - v)});
            q.weights.push_back(w / 8 * (1 - u) * (1 - u) * (1 - v));
          }
          break;
        case Shape::wedge:
          q.points.push_back({u, v * (1 - u), c});
          q.weights.push_back(w / 4 * (1 - u));
          break;
        case Shape::pyramid:
          q.points.push_back({a * (1 - t), b * (1 - t), t});
          q.weights.push_back(w / 2 * (1 - t) * (1 - t));
          break;
        }
      }
  return q;
}

class EveryType : public ::testing::TestWithParam<CellType>
{
protected:
  const FiniteElement &fe = FiniteElement::of(GetParam());
  const ReferenceCell &cell = ReferenceCell::of(GetParam());
};

TEST_P(EveryType, TablesAreConsistent)
{
  EXPECT_EQ(fe.type(), GetParam());
  EXPECT_EQ(cell.type(), GetParam());
  EXPECT_EQ(fe.n_shape(), cell.n_nodes());
  const int expected_nodes[] = {8, 4, 6, 5, 10, 20, 27, 4, 3, 8, 9, 6};
  EXPECT_EQ(cell.n_nodes(), expected_nodes[static_cast<int>(GetParam())]) << cell.name();
  const bool volume = std::count(ReferenceCell::volume_types().begin(),
                                 ReferenceCell::volume_types().end(), GetParam()) == 1;
  EXPECT_EQ(cell.dim(), volume ? 3 : 2);
  EXPECT_EQ(cell.degree(), cell.n_nodes() > cell.n_vertices() ? 2 : 1);
  for (int i = 0; i < cell.n_nodes(); ++i)
    EXPECT_TRUE(inside(cell, cell.node(i))) << cell.name() << " node " << i;
}

TEST_P(EveryType, KroneckerAtNodes)
{
  for (int j = 0; j < cell.n_nodes(); ++j)
  {
    const std::vector<double> N = values(fe, cell.node(j));
    for (int i = 0; i < fe.n_shape(); ++i)
      EXPECT_NEAR(N[i], i == j ? 1.0 : 0.0, 1e-14)
          << cell.name() << ": N_" << i << " at node " << j;
  }
}

TEST_P(EveryType, PartitionOfUnity)
{
  for (const Point &x : random_points(cell, 25))
  {
    const std::vector<double> N = values(fe, x);
    const std::vector<Point> dN = gradients(fe, x);
    double sum = 0;
    Point grad_sum{0, 0, 0};
    for (int i = 0; i < fe.n_shape(); ++i)
    {
      sum += N[i];
      for (int k = 0; k < 3; ++k)
        grad_sum[k] += dN[i][k];
    }
    EXPECT_NEAR(sum, 1.0, 1e-14) << cell.name();
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(grad_sum[k], 0.0, 1e-13) << cell.name() << " component " << k;
  }
}

TEST_P(EveryType, GradientsMatchCentralDifferences)
{
  const double h = 1e-6;
  for (const Point &x : random_points(cell, 25, 11))
  {
    const std::vector<Point> dN = gradients(fe, x);
    for (int k = 0; k < 3; ++k)
    {
      if (k == cell.dim())
      {
        for (int i = 0; i < fe.n_shape(); ++i)
          EXPECT_EQ(dN[i][k], 0.0) << cell.name() << ": a face's third gradient component";
        break;
      }
      Point xp = x, xm = x;
      xp[k] += h;
      xm[k] -= h;
      const std::vector<double> Np = values(fe, xp), Nm = values(fe, xm);
      for (int i = 0; i < fe.n_shape(); ++i)
        EXPECT_NEAR(dN[i][k], (Np[i] - Nm[i]) / (2 * h), 2e-9)
            << cell.name() << ": dN_" << i << "/dxi_" << k;
    }
  }
}

/// The interpolant of f through the nodes, and its gradient, at x.
void check_reproduces(const FiniteElement &fe, const std::function<double(const Point &)> &f,
                      const std::function<Point(const Point &)> &grad_f, const std::string &what)
{
  const ReferenceCell &cell = fe.cell();
  for (const Point &x : random_points(cell, 20, 5))
  {
    const std::vector<double> N = values(fe, x);
    const std::vector<Point> dN = gradients(fe, x);
    double u = 0;
    Point du{0, 0, 0};
    for (int i = 0; i < fe.n_shape(); ++i)
    {
      const double fi = f(cell.node(i));
      u += fi * N[i];
      for (int k = 0; k < 3; ++k)
        du[k] += fi * dN[i][k];
    }
    EXPECT_NEAR(u, f(x), 1e-13) << cell.name() << ", " << what;
    const Point g = grad_f(x);
    for (int k = 0; k < cell.dim(); ++k)
      EXPECT_NEAR(du[k], g[k], 1e-12) << cell.name() << ", " << what << ", d/dxi_" << k;
  }
}

TEST_P(EveryType, ReproducesLinearFields)
{
  const bool d3 = cell.dim() == 3;
  check_reproduces(
      fe, [&](const Point &x) { return 0.3 + 1.1 * x[0] - 0.7 * x[1] + (d3 ? 2.3 * x[2] : 0.0); },
      [&](const Point &) {
        return Point{1.1, -0.7, d3 ? 2.3 : 0.0};
      },
      "linear field");
}

TEST_P(EveryType, QuadraticTypesReproduceQuadraticFields)
{
  if (cell.degree() < 2)
    GTEST_SKIP() << cell.name() << " is linear";
  const double c = cell.dim() == 3 ? 1.0 : 0.0;
  check_reproduces(
      fe,
      [&](const Point &x)
      {
        return 0.5 - x[0] + 2 * x[1] + 0.7 * x[0] * x[0] - 1.3 * x[0] * x[1] + 0.4 * x[1] * x[1] +
               c * (0.9 * x[2] - 0.6 * x[2] * x[2] + 1.7 * x[0] * x[2] - 0.8 * x[1] * x[2]);
      },
      [&](const Point &x)
      {
        return Point{-1 + 1.4 * x[0] - 1.3 * x[1] + c * 1.7 * x[2],
                     2 - 1.3 * x[0] + 0.8 * x[1] - c * 0.8 * x[2],
                     c * (0.9 - 1.2 * x[2] + 1.7 * x[0] - 0.8 * x[1])};
      },
      "quadratic field");
}

TEST_P(EveryType, QuadratureIntegratesMonomialsUpToItsDegree)
{
  const Quadrature &q = fe.quadrature();
  ASSERT_EQ(q.points.size(), q.weights.size());
  double sum = 0;
  for (int p = 0; p < q.size(); ++p)
  {
    EXPECT_GT(q.weights[p], 0.0) << cell.name();
    EXPECT_TRUE(inside(cell, q.points[p])) << cell.name() << " point " << p;
    sum += q.weights[p];
  }
  EXPECT_NEAR(sum, measure(cell), 1e-14) << cell.name();
  int n_checked = 0;
  const int max_c = cell.dim() == 3 ? 6 : 0;
  for (int a = 0; a <= 6; ++a)
    for (int b = 0; b <= 6; ++b)
      for (int c = 0; c <= max_c; ++c)
      {
        if (!stated_exact(GetParam(), a, b, c))
          continue;
        double integral = 0;
        for (int p = 0; p < q.size(); ++p)
          integral += q.weights[p] * std::pow(q.points[p][0], a) * std::pow(q.points[p][1], b) *
                      std::pow(q.points[p][2], c);
        EXPECT_NEAR(integral, exact_monomial(cell, a, b, c), 1e-14)
            << cell.name() << ": x^" << a << " y^" << b << " z^" << c;
        ++n_checked;
      }
  EXPECT_GE(n_checked, 6); // TRI3: 1, x, y, x^2, xy, y^2
}

TEST_P(EveryType, MassAndStiffnessIntegrandsExactOnTheReferenceCell)
{
  // On an affine cell J is constant, so the element matrices are combinations of these
  // reference integrals: ∫ N_i N_j and ∫ ∂_k N_i ∂_l N_j.
  const int n = fe.n_shape(), dim = cell.dim();
  auto integrals = [&](const Quadrature &q)
  {
    std::vector<double> m;
    for (int p = 0; p < q.size(); ++p)
    {
      const std::vector<double> N = values(fe, q.points[p]);
      const std::vector<Point> dN = gradients(fe, q.points[p]);
      int e = 0;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
        {
          if (p == 0)
            m.resize(m.size() + 1 + dim * dim, 0.0);
          m[e++] += q.weights[p] * N[i] * N[j];
          for (int k = 0; k < dim; ++k)
            for (int l = 0; l < dim; ++l)
              m[e++] += q.weights[p] * dN[i][k] * dN[j][l];
        }
    }
    return m;
  };
  const std::vector<double> rule = integrals(fe.quadrature());
  const std::vector<double> reference = integrals(reference_rule(cell));
  ASSERT_EQ(rule.size(), reference.size());
  for (std::size_t e = 0; e < rule.size(); ++e)
    EXPECT_NEAR(rule[e], reference[e], 1e-13) << cell.name() << ", integral " << e;
}

/// The face's geometric map: the face type's corner (linear) interpolation of the corners.
Point face_point(const ReferenceCell &cell, const int f, const Point &s)
{
  const ReferenceCell &face = ReferenceCell::of(cell.face_type(f));
  const FiniteElement &linear =
      FiniteElement::of(face.n_vertices() == 4 ? CellType::quad4 : CellType::tri3);
  const std::vector<double> N = values(linear, s);
  Point x{0, 0, 0};
  for (int k = 0; k < face.n_vertices(); ++k)
    for (int d = 0; d < 3; ++d)
      x[d] += N[k] * cell.node(cell.face_nodes(f)[k])[d];
  return x;
}

Point sub(const Point &a, const Point &b)
{
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double dot(const Point &a, const Point &b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

TEST_P(EveryType, FacesAreOutwardAndMatchTheirFaceType)
{
  if (cell.dim() != 3)
  {
    EXPECT_EQ(cell.n_faces(), 0);
    return;
  }
  const int expected_faces[] = {6, 4, 5, 5, 4, 6, 6};
  EXPECT_EQ(cell.n_faces(), expected_faces[static_cast<int>(GetParam())]);
  for (int f = 0; f < cell.n_faces(); ++f)
  {
    const std::vector<int> &nodes = cell.face_nodes(f);
    const ReferenceCell &face = ReferenceCell::of(cell.face_type(f));
    ASSERT_EQ(face.dim(), 2);
    ASSERT_EQ(static_cast<int>(nodes.size()), face.n_nodes()) << cell.name() << " face " << f;
    EXPECT_EQ(face.degree(), cell.degree());
    // Corners first, then the others.
    for (int k = 0; k < face.n_nodes(); ++k)
      EXPECT_EQ(nodes[k] < cell.n_vertices(), k < face.n_vertices())
          << cell.name() << " face " << f;
    // Right-hand normal from the corners; every turn of the corner polygon agrees.
    const int nv = face.n_vertices();
    auto corner = [&](int k) { return cell.node(nodes[k % nv]); };
    Point n{0, 0, 0};
    for (int k = 0; k < nv; ++k)
    {
      const Point a = sub(corner(k + 1), corner(k)), b = sub(corner(k + 2), corner(k + 1));
      const Point turn{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                       a[0] * b[1] - a[1] * b[0]};
      if (k == 0)
        n = turn;
      EXPECT_GT(dot(turn, n), 0.0) << cell.name() << " face " << f << " corner " << k;
    }
    // A supporting plane: the face's nodes on it, every other node strictly inside (n points out).
    for (int i = 0; i < cell.n_nodes(); ++i)
    {
      const double h = dot(n, sub(cell.node(i), corner(0)));
      if (std::count(nodes.begin(), nodes.end(), i))
        EXPECT_NEAR(h, 0.0, 1e-14) << cell.name() << " face " << f << " node " << i;
      else
        EXPECT_LT(h, -1e-3) << cell.name() << " face " << f << " node " << i;
    }
    // The face's nodes where the face type puts its nodes.
    for (int k = 0; k < face.n_nodes(); ++k)
    {
      const Point x = face_point(cell, f, face.node(k));
      for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(x[d], cell.node(nodes[k])[d], 1e-15)
            << cell.name() << " face " << f << " node " << k << " (cell node " << nodes[k] << ")";
    }
    // The face type's basis is the cell's restricted to the face; the others vanish there.
    const FiniteElement &face_fe = FiniteElement::of(cell.face_type(f));
    for (const Point &s : random_points(face, 10, 3 + f))
    {
      const std::vector<double> Nf = values(face_fe, s);
      const std::vector<double> N = values(fe, face_point(cell, f, s));
      for (int i = 0; i < cell.n_nodes(); ++i)
      {
        const auto k = std::find(nodes.begin(), nodes.end(), i) - nodes.begin();
        const double expected = k < static_cast<long>(nodes.size()) ? Nf[k] : 0.0;
        EXPECT_NEAR(N[i], expected, 1e-14) << cell.name() << " face " << f << " N_" << i;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllCellTypes, EveryType,
                         ::testing::Values(CellType::hex8, CellType::tet4, CellType::wedge6,
                                           CellType::pyramid5, CellType::tet10, CellType::hex20,
                                           CellType::hex27, CellType::quad4, CellType::tri3,
                                           CellType::quad8, CellType::quad9, CellType::tri6),
                         [](const ::testing::TestParamInfo<CellType> &type_info)
                         { return ReferenceCell::of(type_info.param).name(); });

TEST(Hex8, FacesAndGaussPointsAreKilnsOwn)
{
  const ReferenceCell &hex = ReferenceCell::of(CellType::hex8);
  EXPECT_EQ(hex.name(), "HEX8");
  for (int f = 0; f < kiln::n_hex_faces; ++f)
    EXPECT_EQ(hex.face_nodes(f),
              std::vector<int>(kiln::hex_face_nodes[f], kiln::hex_face_nodes[f] + 4))
        << "face " << f;
  const Quadrature &q = FiniteElement::of(CellType::hex8).quadrature();
  ASSERT_EQ(q.size(), 8);
  for (int p = 0; p < 8; ++p)
  {
    EXPECT_EQ(q.points[p], kiln::hex_gauss_points()[p]) << "point " << p;
    EXPECT_EQ(q.weights[p], 1.0);
    EXPECT_EQ(hex.node(p), kiln::hex_reference_node(p));
  }
  // The values bit for bit as ElementValues has always tabulated them.
  const std::vector<double> N = values(FiniteElement::of(CellType::hex8), q.points[3]);
  for (int i = 0; i < 8; ++i)
  {
    const Point r = kiln::hex_reference_node(i);
    const Point &x = q.points[3];
    EXPECT_EQ(N[i], 0.125 * (1 + r[0] * x[0]) * (1 + r[1] * x[1]) * (1 + r[2] * x[2]));
  }
}

TEST(Hex8, FastPathSizeIsTheReferenceCellsNodesAndPoints)
{
  // hex8_n_nodes is the compile-time bound of ElementValues' and the kernels' HEX8 path for
  // both the shape functions and the quadrature points.
  const ReferenceCell &hex = ReferenceCell::of(CellType::hex8);
  EXPECT_EQ(hex.n_nodes(), kiln::hex8_n_nodes);
  for (int i = 0; i < kiln::hex8_n_nodes; ++i)
    EXPECT_EQ(hex.node(i), kiln::hex8_corners[i]) << "node " << i;
  const kiln::ReferenceValues &ref = kiln::ReferenceValues::of(CellType::hex8);
  EXPECT_EQ(ref.n_shape, kiln::hex8_n_nodes);
  EXPECT_EQ(ref.n_qpoints, kiln::hex8_n_nodes);
  EXPECT_EQ(FiniteElement::of(CellType::hex8).quadrature().size(), kiln::hex8_n_nodes);
}

TEST(Quad4, GaussPointsInCornerOrder)
{
  const Quadrature &q = FiniteElement::of(CellType::quad4).quadrature();
  const double g = 1 / std::sqrt(3.0);
  const Point expected[4] = {{-g, -g, 0}, {g, -g, 0}, {g, g, 0}, {-g, g, 0}};
  ASSERT_EQ(q.size(), 4);
  for (int p = 0; p < 4; ++p)
    EXPECT_EQ(q.points[p], expected[p]);
}

TEST(Hex27, ExodusCentroidThenFaceCentresMinusZPlusZMinusXPlusXMinusYPlusY)
{
  // Exodus II / Ioss_Hex27: node 20 (0-based) the centroid, 21..26 the centres of sides
  // 5, 6, 4, 2, 1, 3; each face's last node is its centre.
  const ReferenceCell &hex = ReferenceCell::of(CellType::hex27);
  const Point expected[7] = {{0, 0, 0}, {0, 0, -1}, {0, 0, 1}, {-1, 0, 0},
                             {1, 0, 0}, {0, -1, 0}, {0, 1, 0}};
  for (int i = 0; i < 7; ++i)
    EXPECT_EQ(hex.node(20 + i), expected[i]) << "node " << 20 + i;
  const int centre_of_side[6] = {25, 24, 26, 23, 21, 22};
  for (int f = 0; f < 6; ++f)
    EXPECT_EQ(hex.face_nodes(f).back(), centre_of_side[f]) << "side " << f + 1;
}

TEST(Serendipity, HandDerivedValues)
{
  // QUAD8 at (1/2, -1/4): corner 0: (1 - x)(1 - y)(-x - y - 1)/4; mid-edge 4 (0, -1):
  // (1 - x^2)(1 - y)/2; d/dx of corner 0: (1 - y)(2x + y)/4.
  double q[8];
  Point dq[8];
  FiniteElement::of(CellType::quad8).values({0.5, -0.25, 0}, q);
  FiniteElement::of(CellType::quad8).gradients({0.5, -0.25, 0}, dq);
  EXPECT_DOUBLE_EQ(q[0], 0.25 * 0.5 * 1.25 * -1.25);
  EXPECT_DOUBLE_EQ(q[4], 0.5 * 0.75 * 1.25);
  EXPECT_DOUBLE_EQ(dq[0][0], 0.25 * 1.25 * 0.75);
  // HEX20 at (1/2, 1/4, -1/2): corner 0: (1 - x)(1 - y)(1 - z)(-x - y - z - 2)/8; mid-edge 12
  // (edge 0-4, at (-1, -1, 0)): (1 - x)(1 - y)(1 - z^2)/4.
  double h[20];
  FiniteElement::of(CellType::hex20).values({0.5, 0.25, -0.5}, h);
  EXPECT_DOUBLE_EQ(h[0], 0.125 * 0.5 * 0.75 * 1.5 * -2.25);
  EXPECT_DOUBLE_EQ(h[12], 0.25 * 0.5 * 0.75 * 0.75);
}

TEST(ReferenceCell, NamesAndXdmfCodes)
{
  const std::vector<std::pair<CellType, std::pair<std::string, int>>> expected = {
      {CellType::hex8, {"HEX8", 9}},      {CellType::tet4, {"TETRA4", 6}},
      {CellType::wedge6, {"WEDGE6", 8}},  {CellType::pyramid5, {"PYRAMID5", 7}},
      {CellType::tet10, {"TETRA10", 38}}, {CellType::hex20, {"HEX20", 48}},
      {CellType::hex27, {"HEX27", 50}},   {CellType::quad4, {"QUAD4", 5}},
      {CellType::tri3, {"TRI3", 4}},      {CellType::quad8, {"QUAD8", 37}},
      {CellType::quad9, {"QUAD9", 35}},   {CellType::tri6, {"TRI6", 36}}};
  for (const auto &[type, name_code] : expected)
  {
    EXPECT_EQ(ReferenceCell::of(type).name(), name_code.first);
    EXPECT_EQ(ReferenceCell::of(type).xdmf_code(), name_code.second) << name_code.first;
  }
  EXPECT_EQ(ReferenceCell::volume_types().size(), 7u);
}
} // namespace
