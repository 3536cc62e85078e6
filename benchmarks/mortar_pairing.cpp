// The mortar pairing's cost (src/contact/mortar_pairing.cpp; the figures in doc/contact.md,
// issue 30's "search and mortar integrals under 20% of a step"): two flat bodies of n x n
// primary and (n - 1) x (n + 1) secondary faces 0.001 apart, rotated by (45, -30) degrees, the
// default reach (the secondary's largest face diameter). For each n, the medians over `repeat`
// runs of: the two surfaces (ContactSurface), the search (FaceSearch and every secondary face's
// facing candidates), the integrals (MortarFaceIntegrals of every secondary face) and the whole
// MortarPairing (all of it plus the rows and, at set-up, the margins), and the search redone
// during a run (MortarPairing in X + u, here with u = 0: no margins). Prints a checksum of the
// integrals (sum D, sum of the weighted gaps) so that a faster version can be seen to give the same
// numbers.
//   build/tests/benchmarks/bench_mortar_pairing [--repeat R] 32 64 128
// (benchmarks/mortar_pairing.sh adds a step of the 32^3 contact box for comparison.)
#include "contact/mortar_pairing.hpp"
#include "contact/face_search.hpp"
#include "contact/mortar_face_integrals.hpp"
#include "mesh/contact_surface.hpp"
#include "support/two_body_mesh.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

double ms_since(const Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

std::vector<kiln::Point> positions(const kiln::ContactSurface &surface, const int f)
{
  std::vector<kiln::Point> x;
  for (const int node : surface.face_nodes(f))
    x.push_back(surface.positions()[node]);
  return x;
}

/// One run: the times [ms] of the surfaces, the search, the integrals and MortarPairing, and
/// the checksums sum D_ii and sum g~_i over the secondary faces.
struct Run
{
  double surfaces = 0, search = 0, integrals = 0, pairing = 0, again = 0;
  double sum_D = 0, sum_gap = 0;
  std::size_t n_rows = 0;
};

Run run_once(const kiln::Mesh &mesh)
{
  Run run;
  auto start = Clock::now();
  const kiln::ContactSurface primary(mesh, 1, "primary");
  const kiln::ContactSurface secondary(mesh, 2, "secondary");
  run.surfaces = ms_since(start);

  start = Clock::now();
  const kiln::FaceSearch search(primary);
  std::vector<std::vector<int>> candidates(secondary.n_faces());
  for (int s = 0; s < secondary.n_faces(); ++s)
    for (const int p : search.candidates(secondary.face_box(s), secondary.max_face_diameter()))
      if (kiln::dot(secondary.face_area_vector(s), primary.face_area_vector(p)) < 0.0)
        candidates[s].push_back(p);
  run.search = ms_since(start);

  start = Clock::now();
  std::vector<std::vector<kiln::Point>> primary_x(primary.n_faces());
  for (int p = 0; p < primary.n_faces(); ++p)
    primary_x[p] = positions(primary, p);
  for (int s = 0; s < secondary.n_faces(); ++s)
  {
    std::vector<kiln::MortarFace> faces;
    for (const int p : candidates[s])
      faces.push_back({primary.face_type(p), primary_x[p]});
    const std::vector<kiln::Point> x = positions(secondary, s);
    const kiln::MortarFaceIntegrals integrals({secondary.face_type(s), x}, faces);
    for (int i = 0; i < integrals.n_shape(); ++i)
    {
      run.sum_D += integrals.D(i, i);
      run.sum_gap += integrals.weighted_gap(i);
    }
  }
  run.integrals = ms_since(start);

  start = Clock::now();
  const kiln::MortarPairing pairing(mesh, 1, 2, {}, "bench_mortar_pairing");
  run.pairing = ms_since(start);
  run.n_rows = pairing.rows().size();

  start = Clock::now();
  const kiln::MortarPairing again(mesh, 1, 2, {}, "bench_mortar_pairing",
                                  [](int) {
                                    return kiln::Point{0, 0, 0};
                                  });
  run.again = ms_since(start);
  return run;
}

void measure(const int n, const int repeat)
{
  kiln::Mesh mesh = kiln_test::two_flat_bodies({n, n}, {n - 1, n + 1}, 0.001);
  kiln_test::rotate(mesh, 45.0, -30.0);
  std::vector<double> surfaces, search, integrals, pairing, again;
  Run run;
  for (int r = 0; r < repeat; ++r)
  {
    run = run_once(mesh);
    surfaces.push_back(run.surfaces);
    search.push_back(run.search);
    integrals.push_back(run.integrals);
    pairing.push_back(run.pairing);
    again.push_back(run.again);
  }
  std::printf("%3d x %3d faces: surfaces %8.2f ms, search %8.2f ms, integrals %9.2f ms, "
              "MortarPairing %9.2f ms, again in X + u %9.2f ms (medians of %d; %zu rows, sum D "
              "%.15f, sum g~ %.15e)\n",
              n, n, median(surfaces), median(search), median(integrals), median(pairing),
              median(again), repeat, run.n_rows, run.sum_D, run.sum_gap);
}
} // namespace

int main(int argc, char **argv)
{
  int repeat = 3;
  std::vector<int> sizes;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc)
      repeat = std::max(1, std::atoi(argv[++i]));
    else
      sizes.push_back(std::atoi(argv[i]));
  if (sizes.empty())
    sizes = {32};
  for (const int n : sizes)
    measure(n, repeat);
  return 0;
}
