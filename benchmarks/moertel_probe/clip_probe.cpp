// The hand-written alternative to Moertel (doc/contact.md, "Separately meshed bodies (issue 30):
// design"): per secondary face, the primary faces whose bounding boxes meet its own (a bucket
// grid), projected onto the secondary face's plane along its normal, clipped (Sutherland-Hodgman
// on two convex polygons), the overlap cut into triangles around its centroid, a 7-point
// degree-5 rule on each (weights and points in full precision); the dual bilinear basis
// psi_i = sum_j A_ij N_j with A = diag(int N) (int N N)^-1 per secondary face. Same surfaces,
// checks and output line as moertel_probe (serial only).
//
//   clip_probe NX0 NY0 NX1 NY1 [--offset D] [--curve R] [--scale S] [--flat-frame]
//              [--shift S] [--consistent]
//
// --shift S: the secondary surface moved by S along x (before the rotation), so that a column
// of its faces is only partly covered. --consistent: A from the covered part of each face
// (diag(int_cov N) (int_cov N N)^-1) instead of the whole face. Besides moertel_probe's
// figures it prints the smallest D_jj and the gap error with D lumped to its row sums.
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

using V3 = std::array<double, 3>;
using V2 = std::array<double, 2>;
static V3 sub(V3 a, V3 b)
{
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
static V3 add(V3 a, V3 b, double s = 1)
{
  return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]};
}
static double dot(V3 a, V3 b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static V3 cross(V3 a, V3 b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
static V3 unit(V3 a)
{
  const double l = std::sqrt(dot(a, a));
  return {a[0] / l, a[1] / l, a[2] / l};
}
static double rotation_angles[2] = {0.3, 0.2}; // --flat-frame: {0, 0}
static V3 rotate(V3 p)                         // as moertel_probe
{
  const double a = rotation_angles[0], b = rotation_angles[1];
  const double y1 = std::cos(a) * p[1] - std::sin(a) * p[2],
               z1 = std::sin(a) * p[1] + std::cos(a) * p[2];
  return {std::cos(b) * p[0] + std::sin(b) * z1, y1, -std::sin(b) * p[0] + std::cos(b) * z1};
}
struct Surface
{
  std::vector<V3> x;
  std::vector<std::array<int, 4>> faces;
};
static std::array<double, 4> shape(double s, double t)
{
  return {(1 - s) * (1 - t) / 4, (1 + s) * (1 - t) / 4, (1 + s) * (1 + t) / 4,
          (1 - s) * (1 + t) / 4};
}
// The point of face f at (s, t) and its two tangents.
static void map(const Surface &S, int f, double s, double t, V3 &x, V3 &xs, V3 &xt)
{
  x = xs = xt = {0, 0, 0};
  const double ds[4] = {-(1 - t) / 4, (1 - t) / 4, (1 + t) / 4, -(1 + t) / 4};
  const double dt[4] = {-(1 - s) / 4, -(1 + s) / 4, (1 + s) / 4, (1 - s) / 4};
  const auto N = shape(s, t);
  for (int k = 0; k < 4; ++k)
  {
    const V3 &p = S.x[S.faces[f][k]];
    x = add(x, p, N[k]);
    xs = add(xs, p, ds[k]);
    xt = add(xt, p, dt[k]);
  }
}
// (s, t) of face f where the line y + l d meets it (Newton, from the centre).
static V2 meet(const Surface &S, int f, V3 y, V3 d)
{
  double s = 0, t = 0, l = 0;
  for (int it = 0; it < 20; ++it)
  {
    V3 x, xs, xt;
    map(S, f, s, t, x, xs, xt);
    const V3 r = sub(x, add(y, d, l)); // r(s, t, l) = 0; columns xs, xt, -d
    const V3 md = {-d[0], -d[1], -d[2]};
    const double det = dot(xs, cross(xt, md));
    const double ds = dot(r, cross(xt, md)) / det, dt = dot(xs, cross(r, md)) / det,
                 dl = dot(xs, cross(xt, r)) / det;
    s -= ds;
    t -= dt;
    l -= dl;
    if (std::abs(ds) + std::abs(dt) < 1e-15)
      break;
  }
  return {s, t};
}
static std::vector<V2> clip(const std::vector<V2> &poly, const std::vector<V2> &window)
{
  std::vector<V2> out = poly;
  for (std::size_t e = 0; e < window.size() && !out.empty(); ++e)
  {
    const V2 a = window[e], b = window[(e + 1) % window.size()];
    auto side = [&](V2 p) { return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]); };
    std::vector<V2> in = out;
    out.clear();
    for (std::size_t i = 0; i < in.size(); ++i)
    {
      const V2 p = in[i], q = in[(i + 1) % in.size()];
      const double sp = side(p), sq = side(q);
      if (sp >= 0)
        out.push_back(p);
      if ((sp >= 0) != (sq >= 0))
      {
        const double w = sp / (sp - sq);
        out.push_back({p[0] + w * (q[0] - p[0]), p[1] + w * (q[1] - p[1])});
      }
    }
  }
  return out;
}
int main(int argc, char **argv)
{
  int n[2][2] = {{4, 4}, {5, 3}}, positional = 0;
  double offset = 0, radius = 0, scale = 1, shift = 0;
  bool consistent = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--offset")
      offset = std::atof(argv[++i]);
    else if (a == "--curve")
      radius = std::atof(argv[++i]);
    else if (a == "--flat-frame")
      rotation_angles[0] = rotation_angles[1] = 0.0;
    else if (a == "--shift")
      shift = std::atof(argv[++i]);
    else if (a == "--consistent")
      consistent = true;
    else if (a == "--scale")
      scale = std::atof(argv[++i]);
    else if (positional < 4)
    {
      n[positional / 2][positional % 2] = std::atoi(argv[i]);
      ++positional;
    }
  }
  Surface S[2];
  for (int side = 0; side < 2; ++side)
  {
    const int nx = n[side][0], ny = n[side][1];
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
      {
        const double x = double(i) / nx, d = x - 0.5;
        const double z =
            (radius > 0 ? radius - std::sqrt(radius * radius - d * d) : 0) + (side ? offset : 0);
        S[side].x.push_back(
            rotate({scale * (x + (side ? shift : 0)), scale * double(j) / ny, scale * z}));
      }
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        std::array<int, 4> c = {j * (nx + 1) + i, j * (nx + 1) + i + 1, (j + 1) * (nx + 1) + i + 1,
                                (j + 1) * (nx + 1) + i};
        if (side == 1)
          std::swap(c[1], c[3]);
        S[side].faces.push_back(c);
      }
  }
  const auto t0 = std::chrono::steady_clock::now();
  // Bounding boxes of the primary faces, in a uniform grid of buckets (the
  // search).
  const Surface &P = S[0], &Q = S[1];
  std::vector<std::map<int, double>> D(Q.x.size()), M(Q.x.size());
  const double g7 = std::sqrt(15.0);
  const double qa[3] = {1.0 / 3, (6 - g7) / 21, (6 + g7) / 21},
               qb[3] = {1.0 / 3, (9 + 2 * g7) / 21, (9 - 2 * g7) / 21};
  const double qw[3] = {9.0 / 40, (155 - g7) / 1200, (155 + g7) / 1200};
  std::vector<std::pair<V3, V3>> box(P.faces.size());
  double h = 0;
  for (std::size_t f = 0; f < P.faces.size(); ++f)
  {
    V3 lo = P.x[P.faces[f][0]], hi = lo;
    for (int k : P.faces[f])
      for (int c = 0; c < 3; ++c)
      {
        lo[c] = std::min(lo[c], P.x[k][c]);
        hi[c] = std::max(hi[c], P.x[k][c]);
      }
    box[f] = {lo, hi};
    h = std::max(h, std::sqrt(dot(sub(hi, lo), sub(hi, lo))));
  }
  const double reach = std::abs(offset) * scale + 1e-9 * h; // the search distance across the gap
  std::map<std::array<long, 3>, std::vector<int>> bucket;
  auto key = [&](V3 p)
  {
    return std::array<long, 3>{long(std::floor(p[0] / h)), long(std::floor(p[1] / h)),
                               long(std::floor(p[2] / h))};
  };
  for (std::size_t f = 0; f < P.faces.size(); ++f)
    bucket[key(box[f].first)].push_back(int(f));
  for (std::size_t e = 0; e < Q.faces.size(); ++e)
  {
    // The face's plane (planar faces), its in-plane frame, its dual basis
    // coefficients A.
    V3 c, xs, xt;
    map(Q, int(e), 0, 0, c, xs, xt);
    const V3 nrm = unit(cross(xs, xt)), t1 = unit(xs), t2 = cross(nrm, t1);
    auto in_plane = [&](V3 p)
    {
      const V3 d = sub(p, c);
      return V2{dot(d, t1), dot(d, t2)};
    };
    // The quadrature points of the face's overlaps: N of the secondary and primary faces, the
    // weight and the primary face.
    struct QPoint
    {
      std::array<double, 4> Ns, Nm;
      double w;
      int f;
    };
    std::vector<QPoint> points;
    double Me[4][4] = {}, De[4] = {};
    const double gp[3] = {-std::sqrt(0.6), 0, std::sqrt(0.6)}, gw[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
      {
        V3 x, ys, yt;
        map(Q, int(e), gp[a], gp[b], x, ys, yt);
        const double J = std::sqrt(dot(cross(ys, yt), cross(ys, yt))) * gw[a] * gw[b];
        const auto N = shape(gp[a], gp[b]);
        for (int i = 0; i < 4; ++i)
        {
          De[i] += N[i] * J;
          for (int j = 0; j < 4; ++j)
            Me[i][j] += N[i] * N[j] * J;
        }
      }
    std::vector<V2> mine;
    V3 lo = Q.x[Q.faces[e][0]], hi = lo;
    for (int k : Q.faces[e])
    {
      mine.push_back(in_plane(Q.x[k]));
      for (int cc = 0; cc < 3; ++cc)
      {
        lo[cc] = std::min(lo[cc], Q.x[k][cc]);
        hi[cc] = std::max(hi[cc], Q.x[k][cc]);
      }
    }
    const auto klo = key(add(lo, {-reach - h, -reach - h, -reach - h})),
               khi = key(add(hi, {reach, reach, reach}));
    for (long bx = klo[0]; bx <= khi[0]; ++bx)
      for (long by = klo[1]; by <= khi[1]; ++by)
        for (long bz = klo[2]; bz <= khi[2]; ++bz)
        {
          const auto it = bucket.find({bx, by, bz});
          if (it == bucket.end())
            continue;
          for (int f : it->second)
          {
            bool apart = false;
            for (int cc = 0; cc < 3; ++cc)
              apart =
                  apart || box[f].first[cc] > hi[cc] + reach || box[f].second[cc] < lo[cc] - reach;
            if (apart)
              continue;
            std::vector<V2> theirs;
            for (int k : P.faces[f])
              theirs.push_back(in_plane(P.x[k]));
            // Both counter-clockwise about the secondary normal: the primary's
            // order is reversed.
            std::vector<V2> window(theirs.rbegin(), theirs.rend());
            const std::vector<V2> overlap = clip(mine, window);
            if (overlap.size() < 3)
              continue;
            V2 m{0, 0};
            for (V2 p : overlap)
            {
              m[0] += p[0] / overlap.size();
              m[1] += p[1] / overlap.size();
            }
            for (std::size_t k = 0; k < overlap.size(); ++k)
            {
              const V2 p = overlap[k], q = overlap[(k + 1) % overlap.size()];
              const double area =
                  0.5 * ((p[0] - m[0]) * (q[1] - m[1]) - (p[1] - m[1]) * (q[0] - m[0]));
              for (int r = 0; r < 3; ++r)
                for (int perm = 0; perm < (r ? 3 : 1); ++perm)
                {
                  const double w1 = perm == 0 ? qa[r] : (perm == 1 ? qb[r] : qa[r]),
                               w2 = perm == 0 ? qa[r] : (perm == 1 ? qa[r] : qb[r]);
                  const V2 y2 = {m[0] + w1 * (p[0] - m[0]) + w2 * (q[0] - m[0]),
                                 m[1] + w1 * (p[1] - m[1]) + w2 * (q[1] - m[1])};
                  const V3 y = add(add(c, t1, y2[0]), t2, y2[1]);
                  const V2 st = meet(Q, int(e), y, nrm), sm = meet(P, f, y, nrm);
                  const auto Ns = shape(st[0], st[1]), Nm = shape(sm[0], sm[1]);
                  points.push_back({Ns, Nm, qw[r] * area, f});
                }
            }
          }
        }
    if (points.empty())
      continue;
    if (consistent) // A from the covered part of the face (Cichosz and Bischoff 2011)
    {
      for (int i = 0; i < 4; ++i)
      {
        De[i] = 0;
        for (int j = 0; j < 4; ++j)
          Me[i][j] = 0;
      }
      for (const QPoint &q : points)
        for (int i = 0; i < 4; ++i)
        {
          De[i] += q.Ns[i] * q.w;
          for (int j = 0; j < 4; ++j)
            Me[i][j] += q.Ns[i] * q.Ns[j] * q.w;
        }
    }
    double A[4][4], inv[4][8]; // A = diag(De) Me^-1 by Gauss-Jordan
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 8; ++j)
        inv[i][j] = j < 4 ? Me[i][j] : (j - 4 == i);
    for (int i = 0; i < 4; ++i)
    {
      const double p = inv[i][i];
      for (int j = 0; j < 8; ++j)
        inv[i][j] /= p;
      for (int r = 0; r < 4; ++r)
        if (r != i)
        {
          const double m = inv[r][i];
          for (int j = 0; j < 8; ++j)
            inv[r][j] -= m * inv[i][j];
        }
    }
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        A[i][j] = De[i] * inv[i][4 + j];
    for (const QPoint &q : points)
      for (int i = 0; i < 4; ++i)
      {
        double psi = 0;
        for (int j = 0; j < 4; ++j)
          psi += A[i][j] * q.Ns[j];
        for (int j = 0; j < 4; ++j)
          D[Q.faces[e][i]][Q.faces[e][j]] += psi * q.Ns[j] * q.w;
        for (int k2 = 0; k2 < 4; ++k2)
          M[Q.faces[e][i]][P.faces[q.f][k2]] += psi * q.Nm[k2] * q.w;
      }
  }
  const auto t1c = std::chrono::steady_clock::now();
  const V3 normal = rotate({0, 0, 1});
  double sum_D = 0, sum_M = 0, pou = 0, gap = 0, gap_lumped = 0, min_D = 1e300;
  int off = 0, rows = 0;
  for (std::size_t i = 0; i < Q.x.size(); ++i)
  {
    const auto diagonal = D[i].find(int(i));
    if (diagonal == D[i].end())
      continue; // not covered: no multiplier
    const double Dii = diagonal->second;
    double rd = 0, rm = 0, g = 0;
    for (auto [j, v] : D[i])
    {
      rd += v;
      g += v * dot(Q.x[j], normal);
      off += j != int(i) && std::abs(v) > 1e-8 * std::abs(Dii);
    }
    for (auto [k, v] : M[i])
    {
      rm += v;
      g -= v * dot(P.x[k], normal);
    }
    ++rows;
    sum_D += rd;
    sum_M += rm;
    min_D = std::min(min_D, Dii);
    pou = std::max(pou, std::abs(rm - rd));
    gap = std::max(gap, std::abs(g / Dii / scale - offset));
    gap_lumped = std::max(gap_lumped, std::abs(g / rd / scale - offset));
  }
  std::printf("clip %dx%d vs %dx%d%s%s%s offset %g shift %g: rows of D %d, off-diagonal %d, "
              "sum D %.15g, sum M %.15g, min D_ii %.3g, max|rowsum M - rowsum D| %.3g, "
              "max|gap - offset| %.3g (lumped D %.3g), search+integrate %.3f s\n",
              n[0][0], n[0][1], n[1][0], n[1][1], rotation_angles[0] == 0.0 ? " flat-frame" : "",
              radius > 0 ? " curved" : "", consistent ? " consistent" : "", offset, shift, rows,
              off, sum_D, sum_M, min_D, pou, gap, gap_lumped,
              std::chrono::duration<double>(t1c - t0).count());
}
