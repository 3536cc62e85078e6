#include "physics/mechanics/free_motion_finder.hpp"

#include "base/errors.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_LAPACK.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace kiln
{
namespace
{
/// A vector of the unknowns (a_b, w_b L_b) of every body.
using Coefficients = std::vector<double>;

Point cross(const Point &a, const Point &b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double norm(const std::vector<double> &v)
{
  double s = 0.0;
  for (const double x : v)
    s += x * x;
  return std::sqrt(s);
}

/// The eigenvalues (increasing) and orthonormal eigenvectors of the symmetric n x n matrix A
/// (column-major).
std::pair<std::vector<double>, std::vector<Coefficients>> symmetric_eigen(std::vector<double> A,
                                                                          const int n)
{
  std::vector<double> values(n);
  if (n == 0)
    return {};
  const int lwork = std::max(1, 3 * n);
  std::vector<double> work(lwork);
  int info = 0;
  Teuchos::LAPACK<int, double>().SYEV('V', 'U', n, A.data(), n, values.data(), work.data(), lwork,
                                      &info);
  KILN_ASSERT(info == 0, "LAPACK SYEV failed with info " << info);
  std::vector<Coefficients> vectors(n);
  for (int j = 0; j < n; ++j)
    vectors[j].assign(A.begin() + static_cast<std::ptrdiff_t>(j) * n,
                      A.begin() + static_cast<std::ptrdiff_t>(j + 1) * n);
  return {values, vectors};
}

/// The combinations c (orthonormal, each of size basis.size()) for which the rows `rows` of
/// sum_j c_j basis[j] vanish: the null space of the selected rows of the orthonormal basis.
std::vector<Coefficients> combinations_vanishing_on(const std::vector<Coefficients> &basis,
                                                    const std::vector<int> &rows)
{
  const int k = static_cast<int>(basis.size());
  std::vector<double> G(static_cast<std::size_t>(k) * k, 0.0);
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      for (const int r : rows)
        G[static_cast<std::size_t>(j) * k + i] += basis[i][r] * basis[j][r];
  const auto [values, vectors] = symmetric_eigen(G, k);
  std::vector<Coefficients> result;
  for (int j = 0; j < k; ++j)
    if (values[j] < 1e-10)
      result.push_back(vectors[j]);
  return result;
}

Coefficients combine(const std::vector<Coefficients> &basis, const Coefficients &c)
{
  Coefficients v(basis.empty() ? 0 : basis.front().size(), 0.0);
  for (std::size_t j = 0; j < basis.size(); ++j)
    for (std::size_t r = 0; r < v.size(); ++r)
      v[r] += c[j] * basis[j][r];
  return v;
}

/// v minus its components along the orthonormal vectors q.
Coefficients orthogonal_part(Coefficients v, const std::vector<Coefficients> &q)
{
  for (const Coefficients &e : q)
  {
    double d = 0.0;
    for (std::size_t r = 0; r < v.size(); ++r)
      d += e[r] * v[r];
    for (std::size_t r = 0; r < v.size(); ++r)
      v[r] -= d * e[r];
  }
  return v;
}

/// Adds v, normalized, to the orthonormal vectors q if it has a part outside them (relative
/// 1e-6); returns whether it did.
bool add_if_independent(const Coefficients &v, std::vector<Coefficients> &q)
{
  Coefficients w = orthogonal_part(v, q);
  const double length = norm(w);
  if (length <= 1e-6 * std::max(norm(v), 1e-300))
    return false;
  for (double &x : w)
    x /= length;
  q.push_back(std::move(w));
  return true;
}

/// An orthonormal basis of the span of the orthonormal 3-vectors `span`, the coordinate axes
/// first where they lie in it.
std::vector<Point> readable_basis(const std::vector<Point> &span)
{
  std::vector<Coefficients> chosen;
  std::vector<Coefficients> candidates;
  for (int d = 0; d < 3; ++d)
  {
    Coefficients e(3, 0.0);
    e[d] = 1.0;
    // In the span: its projection keeps its length.
    double length2 = 0.0;
    for (const Point &s : span)
      length2 += s[d] * s[d];
    if (length2 > 1.0 - 1e-10)
      candidates.push_back(e);
  }
  for (const Point &s : span)
    candidates.push_back({s[0], s[1], s[2]});
  for (const Coefficients &c : candidates)
    if (chosen.size() < span.size())
      add_if_independent(c, chosen);
  std::vector<Point> result;
  for (const Coefficients &c : chosen)
    result.push_back({c[0], c[1], c[2]});
  return result;
}

/// A number for messages: 6 significant digits, and 0 for what is below `zero`.
std::string number(const double x, const double zero)
{
  std::ostringstream s;
  s << std::setprecision(6) << (std::abs(x) <= zero ? 0.0 : x);
  return s.str();
}

std::string point(const Point &p, const double zero)
{
  return "(" + number(p[0], zero) + ", " + number(p[1], zero) + ", " + number(p[2], zero) + ")";
}

/// The unit vector of an axis, its first non-zero component positive: "(0, 0, 1)".
std::string axis(Point d)
{
  const double length = std::sqrt(dot(d, d));
  double sign = 0.0;
  for (double &x : d)
  {
    x /= length;
    if (sign == 0.0 && std::abs(x) > 1e-9)
      sign = x > 0.0 ? 1.0 : -1.0;
  }
  for (double &x : d)
    x *= sign;
  return point(d, 1e-9);
}

/// "x", "y", "z" for a coordinate axis (either sense), else the unit vector (either sense:
/// its first non-zero component positive).
std::string direction(Point d)
{
  const double length = std::sqrt(dot(d, d));
  for (double &x : d)
    x /= length;
  for (int k = 0; k < 3; ++k)
    if (std::abs(std::abs(d[k]) - 1.0) < 1e-9)
      return std::string(1, static_cast<char>('x' + k));
  return axis(d);
}

/// The smallest combination c of the motions S (of body b alone) whose rotation part R c is
/// w: c = R^T (R R^T)^+ w, R the 3 x k rotation rows of S, the pseudo-inverse of R R^T by its
/// eigenvalues.
Coefficients combination_rotating_by(const std::vector<Coefficients> &S, const int b,
                                     const Point &w)
{
  const int k = static_cast<int>(S.size());
  std::vector<Coefficients> rows(3, Coefficients(k));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < k; ++j)
      rows[i][j] = S[j][6 * b + 3 + i];
  std::vector<double> RRt(9, 0.0);
  for (int i = 0; i < 3; ++i)
    for (int l = 0; l < 3; ++l)
      for (int j = 0; j < k; ++j)
        RRt[l * 3 + i] += rows[i][j] * rows[l][j];
  const auto [lambda, e] = symmetric_eigen(RRt, 3);
  Point y{};
  for (int m = 0; m < 3; ++m)
    if (lambda[m] > 1e-10 * std::max(lambda[2], 1e-300))
    {
      const double projection = e[m][0] * w[0] + e[m][1] * w[1] + e[m][2] * w[2];
      for (int i = 0; i < 3; ++i)
        y[i] += e[m][i] * projection / lambda[m];
    }
  Coefficients c(k, 0.0);
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < 3; ++i)
      c[j] += rows[i][j] * y[i];
  return c;
}

/// The motions of body b alone in the null space `null` (orthonormal, N = 6 x bodies rows),
/// readable: its translations (coordinate axes first), then its rotations (about axes
/// parallel to coordinate axes where possible), each without a part in its translations.
std::vector<Coefficients> motions_of_body(const std::vector<Coefficients> &null, const int b,
                                          const int N)
{
  std::vector<Coefficients> basis;
  std::vector<int> other_rows, rotation_rows;
  for (int r = 0; r < N; ++r)
    if (r / 6 != b)
      other_rows.push_back(r);
  for (int k = 3; k < 6; ++k)
    rotation_rows.push_back(6 * b + k);
  // The motions of body b alone: S, orthonormal.
  std::vector<Coefficients> S;
  for (const Coefficients &c : combinations_vanishing_on(null, other_rows))
  {
    Coefficients v = combine(null, c);
    for (const int r : other_rows)
      v[r] = 0.0;
    S.push_back(std::move(v));
  }
  if (S.empty())
    return basis;
  // Its translations: readable directions of their span.
  std::vector<Point> translations;
  for (const Coefficients &c : combinations_vanishing_on(S, rotation_rows))
  {
    const Coefficients v = combine(S, c);
    translations.push_back({v[6 * b], v[6 * b + 1], v[6 * b + 2]});
  }
  std::vector<Coefficients> translation_vectors;
  for (const Point &a : readable_basis(translations))
  {
    Coefficients v(N, 0.0);
    std::copy(a.begin(), a.end(), v.begin() + 6 * b);
    translation_vectors.push_back(v);
    basis.push_back(v);
  }
  // Its rotations: the rotation parts of S orthonormalized, made readable, and each one's
  // motion found in S without a part in the free translations.
  std::vector<Coefficients> w_span;
  for (const Coefficients &v : S)
  {
    // S's columns have unit length: a rotation part below 1e-6 is round-off of a
    // translation (a rotated mesh leaves 1e-12 and more), not a rotation.
    const Coefficients w{v[6 * b + 3], v[6 * b + 4], v[6 * b + 5]};
    if (norm(w) > 1e-6)
      add_if_independent(w, w_span);
  }
  std::vector<Point> w_points;
  for (const Coefficients &w : w_span)
    w_points.push_back({w[0], w[1], w[2]});
  for (const Point &w : readable_basis(w_points))
  {
    const Coefficients c = combination_rotating_by(S, b, w);
    Coefficients v = orthogonal_part(combine(S, c), translation_vectors);
    const double length = norm(v);
    for (double &x : v)
      x /= length;
    basis.push_back(std::move(v));
  }
  return basis;
}
} // namespace

FreeMotionFinder::FreeMotionFinder(std::vector<Body> bodies)
    : bodies_(std::move(bodies)), normal_(36 * bodies_.size() * bodies_.size(), 0.0)
{
}

void FreeMotionFinder::add_direction(const int body, const Point &x, const Point &d)
{
  add_gap(body, -1, x, d);
}

void FreeMotionFinder::add_gap(const int body_a, const int body_b, const Point &x, const Point &n)
{
  if (body_a == body_b)
    return;
  // The row's entries: (n, (x - c) x n / L) for body a, minus those for body b.
  std::array<std::array<double, 6>, 2> entries{};
  const std::array<int, 2> body{body_a, body_b};
  for (int s = 0; s < 2; ++s)
  {
    if (body[s] < 0)
      continue;
    const Body &B = bodies_[body[s]];
    const Point r{x[0] - B.centre[0], x[1] - B.centre[1], x[2] - B.centre[2]};
    const Point m = cross(r, n);
    const double sign = s == 0 ? 1.0 : -1.0;
    for (int k = 0; k < 3; ++k)
    {
      entries[s][k] = sign * n[k];
      entries[s][3 + k] = sign * m[k] / B.size;
    }
  }
  const std::size_t N = 6 * bodies_.size();
  for (int s = 0; s < 2; ++s)
    for (int t = 0; t < 2; ++t)
      if (body[s] >= 0 && body[t] >= 0)
        for (int i = 0; i < 6; ++i)
          for (int j = 0; j < 6; ++j)
            normal_[(6 * body[t] + j) * N + 6 * body[s] + i] += entries[s][i] * entries[t][j];
}

std::vector<RigidMotion> FreeMotionFinder::find(const Teuchos::Comm<int> &comm) const
{
  const int N = 6 * n_bodies();
  std::vector<double> A(normal_.size(), 0.0);
  if (N > 0)
  {
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(A.size()), normal_.data(),
                       A.data());
    // Rank 0's sums on every rank, to the last bit: every rank then finds the same motions
    // (and throws the same error, or none).
    Teuchos::broadcast(comm, 0, static_cast<int>(A.size()), A.data());
  }
  const auto [values, vectors] = symmetric_eigen(A, N);
  const double largest = values.empty() ? 0.0 : values.back();
  std::vector<Coefficients> null;
  for (int j = 0; j < N; ++j)
    if (values[j] <= 1e-11 * std::max(largest, 1.0))
      null.push_back(vectors[j]);
  if (null.empty())
    return {};

  // A readable basis of the same space (orthonormal in the unknowns (a, w L)).
  std::vector<Coefficients> basis;
  for (int b = 0; b < n_bodies(); ++b)
    for (Coefficients &v : motions_of_body(null, b, N))
      basis.push_back(std::move(v));
  // The motions of several bodies together: first the rigid motions of each group of bodies
  // that gaps join (A couples them) as one, where free; then what is still not spanned.
  std::vector<Coefficients> orthonormal;
  for (const Coefficients &v : basis)
    add_if_independent(v, orthonormal);
  for (const Coefficients &v : group_motions(A))
  {
    // Free if it lies in the null space.
    const Coefficients outside = orthogonal_part(v, null);
    if (norm(outside) <= 1e-6 * norm(v) && add_if_independent(v, orthonormal))
      basis.push_back(v);
  }
  for (const Coefficients &v : null)
    if (add_if_independent(v, orthonormal))
      basis.push_back(orthonormal.back());
  if (orthonormal.size() != null.size() || basis.size() != null.size())
    basis = null; // the readable basis failed (it should not): the plain one

  std::vector<RigidMotion> motions;
  for (const Coefficients &v : basis)
  {
    RigidMotion m;
    for (int b = 0; b < n_bodies(); ++b)
    {
      m.translation.push_back({v[6 * b], v[6 * b + 1], v[6 * b + 2]});
      const double L = bodies_[b].size;
      m.rotation.push_back({v[6 * b + 3] / L, v[6 * b + 4] / L, v[6 * b + 5] / L});
    }
    motions.push_back(std::move(m));
  }
  return motions;
}

std::vector<std::vector<double>> FreeMotionFinder::group_motions(const std::vector<double> &A) const
{
  // The groups: bodies joined by a non-zero block of A (a gap between them).
  const int m = n_bodies();
  const auto N = static_cast<std::size_t>(6 * m);
  std::vector<int> group(m);
  for (int b = 0; b < m; ++b)
    group[b] = b;
  const auto root = [&group](int b)
  {
    while (group[b] != b)
      b = group[b] = group[group[b]];
    return b;
  };
  for (int a = 0; a < m; ++a)
    for (int b = a + 1; b < m; ++b)
    {
      bool coupled = false;
      for (int i = 0; i < 6 && !coupled; ++i)
        for (int j = 0; j < 6 && !coupled; ++j)
          coupled = A[(6 * b + j) * N + 6 * a + i] != 0.0;
      if (coupled)
        group[root(b)] = root(a);
    }
  std::vector<std::vector<double>> motions;
  for (int g = 0; g < m; ++g)
  {
    std::vector<int> members;
    Point centre{};
    for (int b = 0; b < m; ++b)
      if (root(b) == g)
      {
        members.push_back(b);
        for (int d = 0; d < 3; ++d)
          centre[d] += bodies_[b].centre[d];
      }
    if (members.size() < 2)
      continue;
    for (double &x : centre)
      x /= static_cast<double>(members.size());
    // Translations e_d, then rotations e_d about the group's centre: a_b = e_d x (c_b - c).
    for (int kind = 0; kind < 2; ++kind)
      for (int d = 0; d < 3; ++d)
      {
        Point e{};
        e[d] = 1.0;
        std::vector<double> v(N, 0.0);
        for (const int b : members)
        {
          const Point &c = bodies_[b].centre;
          const Point a =
              kind == 0 ? e : cross(e, {c[0] - centre[0], c[1] - centre[1], c[2] - centre[2]});
          for (int k = 0; k < 3; ++k)
          {
            v[6 * b + k] = a[k];
            v[6 * b + 3 + k] = kind == 0 ? 0.0 : e[k] * bodies_[b].size;
          }
        }
        motions.push_back(std::move(v));
      }
  }
  return motions;
}

std::vector<int> FreeMotionFinder::bodies_moved(const RigidMotion &motion) const
{
  double largest = 0.0;
  for (int b = 0; b < n_bodies(); ++b)
    largest = std::max({largest, std::sqrt(dot(motion.translation[b], motion.translation[b])),
                        bodies_[b].size * std::sqrt(dot(motion.rotation[b], motion.rotation[b]))});
  std::vector<int> moved;
  for (int b = 0; b < n_bodies(); ++b)
    if (std::sqrt(dot(motion.translation[b], motion.translation[b])) > 1e-8 * largest ||
        bodies_[b].size * std::sqrt(dot(motion.rotation[b], motion.rotation[b])) > 1e-8 * largest)
      moved.push_back(b);
  return moved;
}

std::string FreeMotionFinder::describe_as_one(const RigidMotion &motion,
                                              const std::vector<int> &moved) const
{
  // One rigid motion of the bodies: the same w, and a_b = a_0 + w x (c_b - c_0).
  const int first = moved.front();
  const Point &w = motion.rotation[first];
  const Point &c0 = bodies_[first].centre;
  const Point &a0 = motion.translation[first];
  double size = 0.0;
  for (const int b : moved)
    size = std::max(size, bodies_[b].size);
  const double scale = std::sqrt(dot(a0, a0)) + size * std::sqrt(dot(w, w));
  for (const int b : moved)
  {
    const Point &c = bodies_[b].centre;
    const Point shift = cross(w, {c[0] - c0[0], c[1] - c0[1], c[2] - c0[2]});
    for (int k = 0; k < 3; ++k)
      if (std::abs(motion.rotation[b][k] - w[k]) * size > 1e-8 * scale ||
          std::abs(motion.translation[b][k] - a0[k] - shift[k]) > 1e-8 * scale)
        return "";
  }
  // As a motion of one body at the group's centre.
  Point centre{};
  for (const int b : moved)
    for (int d = 0; d < 3; ++d)
      centre[d] += bodies_[b].centre[d] / static_cast<double>(moved.size());
  const Point shift = cross(w, {centre[0] - c0[0], centre[1] - c0[1], centre[2] - c0[2]});
  FreeMotionFinder one({{centre, size}});
  RigidMotion as_one;
  as_one.translation = {{a0[0] + shift[0], a0[1] + shift[1], a0[2] + shift[2]}};
  as_one.rotation = {w};
  std::string names;
  for (std::size_t i = 0; i < moved.size(); ++i)
    names += (i == 0 ? "" : i + 1 == moved.size() ? " and " : ", ") + std::to_string(moved[i] + 1);
  return "bodies " + names + " together: " + one.describe(as_one);
}

std::string FreeMotionFinder::describe(const RigidMotion &motion) const
{
  const std::vector<int> moved = bodies_moved(motion);
  double largest = 0.0;
  for (const int b : moved)
    largest = std::max({largest, std::sqrt(dot(motion.translation[b], motion.translation[b])),
                        bodies_[b].size * std::sqrt(dot(motion.rotation[b], motion.rotation[b]))});
  if (moved.size() > 1)
    if (const std::string one = describe_as_one(motion, moved); !one.empty())
      return one;
  std::string text;
  for (const int b : moved)
  {
    const Point &a = motion.translation[b];
    const Point &w = motion.rotation[b];
    const Body &B = bodies_[b];
    const double w2 = dot(w, w);
    std::string part;
    if (B.size * std::sqrt(w2) <= 1e-8 * largest)
      part = "translation along " + direction(a);
    else
    {
      // r(x) = a + w x (x - c) = w x (x - p) + s w: the axis through p, a screw of pitch s.
      const Point wa = cross(w, a);
      const Point p{B.centre[0] + wa[0] / w2, B.centre[1] + wa[1] / w2, B.centre[2] + wa[2] / w2};
      part = "rotation about the axis " + axis(w) + " through " + point(p, 1e-9 * B.size);
      const double pitch = dot(w, a) / w2;
      if (std::abs(pitch) > 1e-8 * B.size)
        part += " with a translation along the axis of " + number(pitch, 0.0) + " m per radian";
    }
    if (moved.size() > 1)
      part = "body " + std::to_string(b + 1) + ": " + part;
    text += (text.empty() ? "" : ", ") + part;
  }
  if (moved.size() > 1)
    text += ", together";
  return text;
}
} // namespace kiln
