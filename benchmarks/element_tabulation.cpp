// Kiln's hand-written element bases against Intrepid2's (issue 32, doc/elements.md): for every
// type Intrepid2 has, the largest difference of values and reference gradients at the
// quadrature points, and the time to tabulate them (values and gradients at all quadrature
// points, as ElementValues does once per type) and to evaluate them at one point (as a
// point search does per cell), per call, each the best of 5 runs of `repeat` calls.
//   build/tests/benchmarks/bench_element_tabulation [repeat]   (default 20000)
#include "elements/finite_element.hpp"
#include "support/intrepid2_bases.hpp"

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <vector>

namespace
{
using kiln::CellType;
using kiln::FiniteElement;
using kiln::Point;

/// Nanoseconds per call of f (best of 5 runs of `repeat` calls).
double time_per_call(const int repeat, const std::function<void()> &f)
{
  double best = 1e300;
  for (int run = 0; run < 5; ++run)
  {
    const auto start = std::chrono::steady_clock::now();
    for (int r = 0; r < repeat; ++r)
      f();
    const std::chrono::duration<double, std::nano> t = std::chrono::steady_clock::now() - start;
    best = std::min(best, t.count() / repeat);
  }
  return best;
}

volatile double sink = 0; // keeps the work from being optimised away
} // namespace

int main(int argc, char **argv)
{
  const int repeat = argc > 1 ? std::atoi(argv[1]) : 20000;
  const Kokkos::ScopeGuard kokkos(argc, argv);
  std::printf("%-9s %4s %4s %10s | %11s %11s %13s | %10s %10s\n", "type", "n", "q", "max diff",
              "tab Kiln", "tab Intr2", "tab Intr2+alloc", "pt Kiln", "pt Intr2");
  for (const CellType type :
       {CellType::hex8, CellType::tet4, CellType::wedge6, CellType::pyramid5, CellType::tet10,
        CellType::hex27, CellType::quad4, CellType::tri3, CellType::quad9, CellType::tri6})
  {
    const FiniteElement &fe = FiniteElement::of(type);
    const auto basis = kiln_test::intrepid2_basis(type);
    const int n = fe.n_shape(), dim = fe.cell().dim(), nq = fe.quadrature().size();
    const std::vector<Point> &points = fe.quadrature().points;
    const kiln_test::Intrepid2View x = kiln_test::intrepid2_points(points, dim);
    kiln_test::Intrepid2View N("N", n, nq), dN("dN", n, nq, dim);
    std::vector<double> v(n * nq);
    std::vector<Point> g(n * nq);

    auto kiln_tabulate = [&]
    {
      for (int q = 0; q < nq; ++q)
      {
        fe.values(points[q], &v[q * n]);
        fe.gradients(points[q], &g[q * n]);
      }
      sink = sink + v[0] + g[n * nq - 1][0];
    };
    auto intrepid2_tabulate = [&]
    {
      basis->getValues(N, x, Intrepid2::OPERATOR_VALUE);
      basis->getValues(dN, x, Intrepid2::OPERATOR_GRAD);
      sink = sink + N(0, 0) + dN(n - 1, nq - 1, 0);
    };
    auto intrepid2_tabulate_alloc = [&]
    {
      const kiln_test::Intrepid2View xa = kiln_test::intrepid2_points(points, dim);
      kiln_test::Intrepid2View Na("N", n, nq), dNa("dN", n, nq, dim);
      basis->getValues(Na, xa, Intrepid2::OPERATOR_VALUE);
      basis->getValues(dNa, xa, Intrepid2::OPERATOR_GRAD);
      sink = sink + Na(0, 0) + dNa(n - 1, nq - 1, 0);
    };

    kiln_tabulate();
    intrepid2_tabulate();
    double diff = 0;
    for (int q = 0; q < nq; ++q)
      for (int i = 0; i < n; ++i)
      {
        diff = std::max(diff, std::abs(v[q * n + i] - N(i, q)));
        for (int k = 0; k < dim; ++k)
          diff = std::max(diff, std::abs(g[q * n + i][k] - dN(i, q, k)));
      }

    const kiln_test::Intrepid2View x1 = kiln_test::intrepid2_points({points[0]}, dim);
    kiln_test::Intrepid2View N1("N", n, 1), dN1("dN", n, 1, dim);
    auto kiln_point = [&]
    {
      fe.values(points[0], v.data());
      fe.gradients(points[0], g.data());
      sink = sink + v[0] + g[0][0];
    };
    auto intrepid2_point = [&]
    {
      basis->getValues(N1, x1, Intrepid2::OPERATOR_VALUE);
      basis->getValues(dN1, x1, Intrepid2::OPERATOR_GRAD);
      sink = sink + N1(0, 0) + dN1(0, 0, 0);
    };
    std::printf("%-9s %4d %4d %10.1e | %9.0f ns %9.0f ns %11.0f ns | %7.0f ns %7.0f ns\n",
                fe.cell().name().c_str(), n, nq, diff, time_per_call(repeat, kiln_tabulate),
                time_per_call(repeat, intrepid2_tabulate),
                time_per_call(repeat / 10 + 1, intrepid2_tabulate_alloc),
                time_per_call(repeat, kiln_point), time_per_call(repeat, intrepid2_point));
    if (diff > 1e-13)
    {
      std::printf("%s: Kiln and Intrepid2 differ by %g\n", fe.cell().name().c_str(), diff);
      return 1;
    }
  }
  return 0;
}
