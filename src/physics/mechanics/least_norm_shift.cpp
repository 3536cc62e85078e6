#include "physics/mechanics/least_norm_shift.hpp"

#include <Teuchos_LAPACK.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace kiln
{
namespace
{
/// The step p (k) and the multipliers (per working constraint) of the equality-constrained
/// problem min (c + p)^T M (c + p) + 2 b^T (c + p) with A_W p = 0: the KKT system
/// [M A_W^T; A_W 0] [p; -lambda/2] = [-(M c + b); 0].
void equality_step(const int k, const std::vector<double> &M, const std::vector<double> &g,
                   const std::vector<double> &A, const std::vector<int> &working,
                   std::vector<double> &p, std::vector<double> &lambda)
{
  const int w = static_cast<int>(working.size());
  const int n = k + w;
  std::vector<double> K(static_cast<std::size_t>(n) * n, 0.0), rhs(n, 0.0);
  for (int i = 0; i < k; ++i)
  {
    for (int j = 0; j < k; ++j)
      K[i + n * j] = M[i + k * j];
    rhs[i] = -g[i];
  }
  for (int r = 0; r < w; ++r)
    for (int j = 0; j < k; ++j)
    {
      const double a = A[static_cast<std::size_t>(working[r]) * k + j];
      K[(k + r) + n * j] = a;
      K[j + n * (k + r)] = a;
    }
  std::vector<int> pivots(n);
  int info = 0;
  Teuchos::LAPACK<int, double>().GESV(n, 1, K.data(), n, pivots.data(), rhs.data(), n, &info);
  if (info != 0)
    throw std::runtime_error("least_norm_shift: singular KKT system");
  p.assign(rhs.begin(), rhs.begin() + k);
  lambda.resize(w);
  for (int r = 0; r < w; ++r)
    lambda[r] = -rhs[k + r];
}
} // namespace

std::vector<double> least_norm_shift(const int k, const std::vector<double> &M,
                                     const std::vector<double> &b, const int m,
                                     const std::vector<double> &A, const std::vector<double> &h)
{
  std::vector<double> c(k, 0.0), p, lambda, g(k);
  std::vector<int> working;
  // Scales for "zero": the size of the gradient at 0 and of each constraint row.
  double size = 0.0;
  for (const double v : b)
    size = std::max(size, std::abs(v));
  const auto dot_row = [&](const int i, const std::vector<double> &v)
  {
    double s = 0.0;
    for (int j = 0; j < k; ++j)
      s += A[static_cast<std::size_t>(i) * k + j] * v[j];
    return s;
  };
  const int limit = 10 * (k + m) + 100;
  for (int iteration = 0; iteration < limit; ++iteration)
  {
    for (int i = 0; i < k; ++i)
    {
      g[i] = b[i];
      for (int j = 0; j < k; ++j)
        g[i] += M[i + k * j] * c[j];
    }
    equality_step(k, M, g, A, working, p, lambda);
    double step = 0.0, largest = 0.0;
    for (int j = 0; j < k; ++j)
    {
      step = std::max(step, std::abs(p[j]));
      largest = std::max(largest, std::abs(c[j]));
    }
    if (step <= 1e-14 * std::max(largest, size))
    {
      // At the minimum over the working set: done unless a constraint pulls the wrong way.
      int leave = -1;
      double most = 0.0;
      for (std::size_t r = 0; r < working.size(); ++r)
        if (lambda[r] < most)
        {
          most = lambda[r];
          leave = static_cast<int>(r);
        }
      if (leave < 0 || most >= -1e-12 * size)
        return c;
      working.erase(working.begin() + leave);
      continue;
    }
    // Along p as far as the constraints outside the working set allow.
    double alpha = 1.0;
    int blocking = -1;
    for (int i = 0; i < m; ++i)
    {
      if (std::find(working.begin(), working.end(), i) != working.end())
        continue;
      const double ap = dot_row(i, p);
      if (ap >= 0.0)
        continue;
      const double limit_i = std::max(0.0, dot_row(i, c) - h[i]) / -ap;
      if (limit_i < alpha)
      {
        alpha = limit_i;
        blocking = i;
      }
    }
    for (int j = 0; j < k; ++j)
      c[j] += alpha * p[j];
    if (blocking >= 0)
      working.push_back(blocking);
  }
  throw std::runtime_error("least_norm_shift: no convergence (a degenerate cycle)");
}
} // namespace kiln
