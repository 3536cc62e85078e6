// Patch tests (issue 32) for every cell type the box generator makes: on a 4 x 3 x 3 box with
// its interior nodes moved off the grid (non-affine hexahedra, curved quadratic cells), a
// linear temperature (Laplace) and a linear displacement (isotropic elasticity) prescribed at
// the boundary nodes are reproduced at the interior nodes to round-off. The stiffness is
// assembled here from ElementValues (shape gradients, JxW): it tests the elements (basis,
// quadrature, isoparametric map), not Kiln's physics kernels.
// KILN_TEST_NP: 1
#include "discretization/element_values.hpp"
#include "mesh/box_mesh_generator.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
using kiln::Mesh;
using kiln::Point;

/// Solves A x = b (dense, partial pivoting); A is n x n row-major.
std::vector<double> solve(std::vector<double> A, std::vector<double> b)
{
  const std::size_t n = b.size();
  for (std::size_t k = 0; k < n; ++k)
  {
    std::size_t p = k;
    for (std::size_t i = k + 1; i < n; ++i)
      if (std::abs(A[i * n + k]) > std::abs(A[p * n + k]))
        p = i;
    for (std::size_t j = 0; j < n; ++j)
      std::swap(A[k * n + j], A[p * n + j]);
    std::swap(b[k], b[p]);
    for (std::size_t i = k + 1; i < n; ++i)
    {
      const double f = A[i * n + k] / A[k * n + k];
      for (std::size_t j = k; j < n; ++j)
        A[i * n + j] -= f * A[k * n + j];
      b[i] -= f * b[k];
    }
  }
  std::vector<double> x(n);
  for (std::size_t k = n; k-- > 0;)
  {
    double s = b[k];
    for (std::size_t j = k + 1; j < n; ++j)
      s -= A[k * n + j] * x[j];
    x[k] = s / A[k * n + k];
  }
  return x;
}

/// The distorted box of `type` (unit cube, 4 x 3 x 3 hexahedra) and which nodes are inside.
Mesh distorted_box(const std::string &type, std::vector<bool> &inside)
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  p.set("Cells", Teuchos::Array<int>(Teuchos::tuple(4, 3, 3)));
  p.set("Size", Teuchos::Array<double>(Teuchos::tuple(1.0, 1.0, 1.0)));
  p.set("Cell Type", type);
  Mesh mesh = kiln::BoxMeshGenerator(p, "test/Box").generate();
  inside.assign(mesh.n_nodes(), false);
  for (int n = 0; n < mesh.n_nodes(); ++n)
  {
    Point &x = mesh.coordinates[n];
    bool in = true;
    for (int d = 0; d < 3; ++d)
      in = in && std::abs(std::abs(x[d]) - 0.5) > 1e-12;
    inside[n] = in;
    // A deterministic shift of up to 0.04 (a quarter of the smallest half-spacing); TETRA10's
    // small tets with curved edges would invert: 0.01.
    const double amplitude = type == "TETRA10" ? 0.01 : 0.04;
    if (in)
      for (int d = 0; d < 3; ++d)
        x[d] += amplitude * std::sin(1.7 * n + 2.3 * d + 0.5);
  }
  return mesh;
}

/// Solves K u = 0 with u = exact at the boundary dofs; the largest |u - exact| inside.
double patch_error(const Mesh &mesh, const std::vector<bool> &inside, const int components,
                   const std::vector<double> &exact, const double lambda, const double mu)
{
  const std::size_t n = exact.size();
  std::vector<double> K(n * n, 0.0);
  kiln::ElementValues fe;
  for (int c = 0; c < mesh.n_cells(); ++c)
  {
    fe.reinit(mesh, c);
    const auto nodes = mesh.cell_nodes(c);
    for (int q = 0; q < fe.n_qpoints(); ++q)
      for (int i = 0; i < fe.n_shape(); ++i)
        for (int j = 0; j < fe.n_shape(); ++j)
        {
          const Point &gi = fe.grad(i, q), &gj = fe.grad(j, q);
          const double gg = kiln::dot(gi, gj) * fe.JxW(q);
          for (int a = 0; a < components; ++a)
            for (int b = 0; b < components; ++b)
            {
              double k = 0;
              if (components == 1)
                k = gg;
              else
                k = (lambda * gi[a] * gj[b] + mu * gi[b] * gj[a]) * fe.JxW(q) +
                    (a == b ? mu * gg : 0.0);
              K[(nodes[i] * components + a) * n + nodes[j] * components + b] += k;
            }
        }
  }
  // Boundary rows: the identity and the exact value.
  std::vector<double> rhs(n, 0.0);
  for (std::size_t r = 0; r < n; ++r)
    if (!inside[r / components])
    {
      for (std::size_t j = 0; j < n; ++j)
        K[r * n + j] = j == r ? 1.0 : 0.0;
      rhs[r] = exact[r];
    }
  const std::vector<double> u = solve(K, rhs);
  double error = 0;
  for (std::size_t r = 0; r < n; ++r)
    error = std::max(error, std::abs(u[r] - exact[r]));
  return error;
}

class PatchTest : public testing::TestWithParam<std::string>
{
};

TEST_P(PatchTest, LinearTemperatureAndDisplacementAreReproduced)
{
  std::vector<bool> inside;
  const Mesh mesh = distorted_box(GetParam(), inside);
  int n_inside = 0;
  for (const bool in : inside)
    n_inside += in;
  ASSERT_GT(n_inside, 0);
  std::vector<double> T(mesh.n_nodes()), u(3 * mesh.n_nodes());
  for (int n = 0; n < mesh.n_nodes(); ++n)
  {
    const Point &x = mesh.coordinates[n];
    T[n] = 300 + 2 * x[0] - 3 * x[1] + 5 * x[2];
    u[3 * n + 0] = 0.01 + 0.2 * x[0] - 0.1 * x[1] + 0.3 * x[2];
    u[3 * n + 1] = -0.02 + 0.1 * x[0] + 0.4 * x[1] - 0.2 * x[2];
    u[3 * n + 2] = 0.03 - 0.3 * x[0] + 0.2 * x[1] + 0.1 * x[2];
  }
  const double heat = patch_error(mesh, inside, 1, T, 0, 0);
  const double elastic = patch_error(mesh, inside, 3, u, 2.0, 1.0);
  std::printf("%s: %d interior nodes, max |T - T_exact| = %.2e K (T ~ 300), "
              "max |u - u_exact| = %.2e (u ~ 0.5)\n",
              GetParam().c_str(), n_inside, heat, elastic);
  EXPECT_LT(heat, 1e-13 * 300); // relative round-off
  EXPECT_LT(elastic, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(EveryBoxType, PatchTest,
                         testing::Values("HEX8", "TETRA4", "WEDGE6", "HEX20", "HEX27", "TETRA10"));
} // namespace
