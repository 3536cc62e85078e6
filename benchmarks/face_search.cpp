// The contact search's cost (src/contact/face_search.cpp; the figures in doc/contact.md): two
// flat surfaces of n x n and (n - 1) x (n + 1) faces, perturbed and rotated, 0.001 apart; for
// every secondary face the primary faces within one face diameter, by the bucket search and
// by all pairs (up to n = 128). Prints the times and exits 1 if the two differ.
//   build/tests/benchmarks/bench_face_search 32 64 128 256
#include "contact/face_search.hpp"
#include "mesh/contact_surface.hpp"
#include "support/two_body_mesh.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace
{
double ms_since(const std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

/// Times the surfaces, the search and (n <= 128) all pairs; false if they differ.
bool measure(const int n)
{
  kiln::Mesh mesh = kiln_test::two_flat_bodies({n, n}, {n - 1, n + 1}, 0.001);
  kiln_test::perturb(mesh, 0.1 / n);
  kiln_test::rotate(mesh, 30.0, -20.0);
  auto start = std::chrono::steady_clock::now();
  const kiln::ContactSurface primary(mesh, 1, "primary");
  const kiln::ContactSurface secondary(mesh, 2, "secondary");
  const double surfaces_ms = ms_since(start);
  start = std::chrono::steady_clock::now();
  const kiln::FaceSearch search(primary);
  std::vector<std::vector<int>> found(secondary.n_faces());
  long n_found = 0;
  for (int s = 0; s < secondary.n_faces(); ++s)
  {
    found[s] = search.candidates(secondary.face_box(s), secondary.face_diameter(s));
    n_found += static_cast<long>(found[s].size());
  }
  const double search_ms = ms_since(start);
  std::printf("%3d x %3d faces: surfaces %8.2f ms, search %8.2f ms (%.1f candidates a face)", n, n,
              surfaces_ms, search_ms, double(n_found) / secondary.n_faces());
  bool same = true;
  if (n <= 128)
  {
    start = std::chrono::steady_clock::now();
    for (int s = 0; s < secondary.n_faces(); ++s)
    {
      const kiln::BoundingBox query = secondary.face_box(s).grown(secondary.face_diameter(s));
      std::vector<int> all_pairs;
      for (int p = 0; p < primary.n_faces(); ++p)
        if (primary.face_box(p).overlaps(query))
          all_pairs.push_back(p);
      same = same && all_pairs == found[s];
    }
    std::printf(", all pairs %8.2f ms%s", ms_since(start), same ? "" : ": DIFFERENT");
  }
  std::printf("\n");
  return same;
}
} // namespace

int main(int argc, char **argv)
{
  bool same = true;
  for (int i = 1; i < argc; ++i)
    same = measure(std::atoi(argv[i])) && same;
  if (argc == 1)
    same = measure(32);
  return same ? 0 : 1;
}
