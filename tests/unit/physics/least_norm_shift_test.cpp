// least_norm_shift: the small quadratic programme of the minimum-norm solution with contact
// (doc/contact.md, "Free motions while pairs open"), against answers worked out by hand and,
// for random problems, against every active set tried in turn.
// KILN_TEST_NP: 1
#include "physics/mechanics/least_norm_shift.hpp"

#include <gtest/gtest.h>

#include <Teuchos_LAPACK.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace
{
using kiln::least_norm_shift;

double objective(const int k, const std::vector<double> &M, const std::vector<double> &b,
                 const std::vector<double> &c)
{
  double f = 0.0;
  for (int i = 0; i < k; ++i)
  {
    f += 2.0 * b[i] * c[i];
    for (int j = 0; j < k; ++j)
      f += c[i] * M[i + k * j] * c[j];
  }
  return f;
}

TEST(LeastNormShift, UnconstrainedMinimum)
{
  const std::vector<double> c = least_norm_shift(2, {1, 0, 0, 1}, {-1, 2}, 0, {}, {});
  EXPECT_NEAR(c[0], 1.0, 1e-15);
  EXPECT_NEAR(c[1], -2.0, 1e-15);
}

TEST(LeastNormShift, OneConstraintBinds)
{
  // min |c - (1, 1)|^2 with c0 + c1 <= 1: (1/2, 1/2).
  const std::vector<double> c = least_norm_shift(2, {1, 0, 0, 1}, {-1, -1}, 1, {-1, -1}, {-1});
  EXPECT_NEAR(c[0], 0.5, 1e-15);
  EXPECT_NEAR(c[1], 0.5, 1e-15);
}

TEST(LeastNormShift, DependentConstraintsActiveAtTheStart)
{
  // Three copies of c0 >= 0 and c0 + c1 >= 0, all active at c = 0 (pairs that touch, as on a
  // gap between two free bodies); the unconstrained minimum (-1, 1) is cut off by c0 >= 0:
  // (0, 1), which leaves c0 + c1 >= 0 inactive (it must leave the working set or never join).
  const std::vector<double> A{1, 0, 1, 0, 2, 0, 1, 1};
  const std::vector<double> c = least_norm_shift(2, {1, 0, 0, 1}, {1, -1}, 4, A, {0, 0, 0, 0});
  EXPECT_NEAR(c[0], 0.0, 1e-15);
  EXPECT_NEAR(c[1], 1.0, 1e-15);
}

TEST(LeastNormShift, RandomProblemsAgainstEveryActiveSet)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const int k = 3, m = 7;
  for (int trial = 0; trial < 20; ++trial)
  {
    // M = L L^T + I/2 (unit-ish diagonal), h <= 0.
    std::vector<double> L(k * k), M(k * k, 0.0), b(k), A(m * k), h(m);
    for (double &v : L)
      v = uniform(random) * 0.5;
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j)
      {
        for (int l = 0; l < k; ++l)
          M[i + k * j] += L[i + k * l] * L[j + k * l];
        M[i + k * j] += i == j ? 0.5 : 0.0;
      }
    for (double &v : b)
      v = uniform(random);
    for (double &v : A)
      v = uniform(random);
    for (double &v : h)
      v = -0.3 * std::abs(uniform(random));
    const std::vector<double> c = least_norm_shift(k, M, b, m, A, h);
    for (int i = 0; i < m; ++i)
    {
      double s = 0.0;
      for (int j = 0; j < k; ++j)
        s += A[i * k + j] * c[j];
      EXPECT_GE(s, h[i] - 1e-12) << "trial " << trial << ", constraint " << i;
    }
    // Every subset of at most k constraints held as equalities: the best feasible minimum.
    double best = std::numeric_limits<double>::infinity();
    for (int subset = 0; subset < (1 << m); ++subset)
    {
      std::vector<int> S;
      for (int i = 0; i < m; ++i)
        if (subset & (1 << i))
          S.push_back(i);
      if (static_cast<int>(S.size()) > k)
        continue;
      const int n = k + static_cast<int>(S.size());
      std::vector<double> K(n * n, 0.0), rhs(n, 0.0);
      for (int i = 0; i < k; ++i)
      {
        for (int j = 0; j < k; ++j)
          K[i + n * j] = M[i + k * j];
        rhs[i] = -b[i];
      }
      for (std::size_t r = 0; r < S.size(); ++r)
      {
        for (int j = 0; j < k; ++j)
        {
          K[(k + r) + n * j] = A[S[r] * k + j];
          K[j + n * (k + r)] = A[S[r] * k + j];
        }
        rhs[k + r] = h[S[r]];
      }
      std::vector<int> pivots(n);
      int info = 0;
      Teuchos::LAPACK<int, double>().GESV(n, 1, K.data(), n, pivots.data(), rhs.data(), n, &info);
      if (info != 0)
        continue;
      const std::vector<double> x(rhs.begin(), rhs.begin() + k);
      bool feasible = true;
      for (int i = 0; i < m; ++i)
      {
        double s = 0.0;
        for (int j = 0; j < k; ++j)
          s += A[i * k + j] * x[j];
        feasible = feasible && s >= h[i] - 1e-12;
      }
      if (feasible)
        best = std::min(best, objective(k, M, b, x));
    }
    EXPECT_NEAR(objective(k, M, b, c), best, 1e-12) << "trial " << trial;
  }
}
} // namespace
