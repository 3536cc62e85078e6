#include "discretization/element_values.hpp"

#include "base/errors.hpp"

#include <sstream>

namespace kiln
{
void ElementValues::reinit(const Mesh &mesh, const int c)
{
  const Span<const int> nodes = mesh.cell_nodes(c);
  for (int i = 0; i < nodes.size(); ++i)
    x_[i] = mesh.coordinates[nodes[i]];
  reinit(mesh.cell_type(c), x_.data());
}

void ElementValues::reinit(const CellType type, const Point *x)
{
  if (shape_ == nullptr || type != type_)
  {
    const ReferenceValues &ref = ReferenceValues::of(type);
    KILN_ASSERT(ref.n_shape > 0 && ReferenceCell::of(type).dim() == 3,
                "no volume basis for " << ReferenceCell::of(type).name());
    ref_grad_ = ref.grad.data();
    weights_ = ref.weights.data();
    type_ = type;
    n_shape_ = ref.n_shape;
    n_qpoints_ = ref.n_qpoints;
    shape_ = ref.shape.data();
    grad_.resize(ref.grad.size());
    JxW_.resize(n_qpoints_);
    quadrature_point_.resize(n_qpoints_);
  }
  // The common HEX8 through its own table and fixed loop bounds.
  if (type_ == CellType::hex8)
    map_hex8(x);
  else
    map(x);
}

namespace
{
/// J's cofactors C (inv(J)[r][d] = C[d][r] / det) and det(J), J[d][r] = dx_d/dxi_r.
struct Cofactors
{
  double C[3][3];
  double det;
};

/// Always inlined: a call per point (two callers, so GCC keeps it out of line) costs the HEX8
/// map about 15 % of its instructions.
[[gnu::always_inline]] inline Cofactors cofactors(const double (&J)[3][3])
{
  Cofactors c{{{J[1][1] * J[2][2] - J[1][2] * J[2][1], J[1][2] * J[2][0] - J[1][0] * J[2][2],
                J[1][0] * J[2][1] - J[1][1] * J[2][0]},
               {J[0][2] * J[2][1] - J[0][1] * J[2][2], J[0][0] * J[2][2] - J[0][2] * J[2][0],
                J[0][1] * J[2][0] - J[0][0] * J[2][1]},
               {J[0][1] * J[1][2] - J[0][2] * J[1][1], J[0][2] * J[1][0] - J[0][0] * J[1][2],
                J[0][0] * J[1][1] - J[0][1] * J[1][0]}},
              0.0};
  c.det = J[0][0] * c.C[0][0] + J[0][1] * c.C[0][1] + J[0][2] * c.C[0][2];
  return c;
}

/// Throws the InternalError of a cell whose det(dx/dxi) <= 0 at point q.
[[noreturn]] void throw_inverted(const double det, const int q, const CellType type,
                                 const Point &x0)
{
  std::ostringstream msg;
  msg << "ElementValues::reinit: det(dx/dxi) = " << det << " <= 0 at quadrature point " << q
      << " of a " << ReferenceCell::of(type).name()
      << " (an inverted or degenerate cell; node 0 at (" << x0[0] << ", " << x0[1] << ", " << x0[2]
      << "))";
  throw InternalError(msg.str());
}

/// HEX8's reference values (ReferenceValues::of(hex8), the same numbers) laid out for the
/// vector units: per point q and node i the row {N_i, dN_i/dxi_0, dN_i/dxi_1, dN_i/dxi_2}
/// (x_q and J accumulate node by node as one row of 4 per component d), and per point q and
/// reference direction r the 8 nodes' dN_i/dxi_r side by side (the physical gradients are
/// formed for all nodes at once). A static table: constant offsets, no pointer to reload.
struct Hex8Reference
{
  alignas(16) double row[hex8_n_nodes][hex8_n_nodes][4];
  alignas(16) double grad[hex8_n_nodes][3][hex8_n_nodes];
  double weights[hex8_n_nodes];
};

const Hex8Reference &hex8_reference()
{
  static const Hex8Reference table = []
  {
    const ReferenceValues &ref = ReferenceValues::of(CellType::hex8);
    KILN_ASSERT(ref.n_shape == hex8_n_nodes && ref.n_qpoints == hex8_n_nodes,
                "HEX8 with " << ref.n_shape << " shape functions and " << ref.n_qpoints
                             << " points");
    Hex8Reference t{};
    for (int q = 0; q < hex8_n_nodes; ++q)
    {
      for (int i = 0; i < hex8_n_nodes; ++i)
      {
        const std::size_t k = static_cast<std::size_t>(q) * hex8_n_nodes + i;
        t.row[q][i][0] = ref.shape[k];
        for (int r = 0; r < 3; ++r)
          t.row[q][i][1 + r] = t.grad[q][r][i] = ref.grad[k][r];
      }
      t.weights[q] = ref.weights[q];
    }
    return t;
  }();
  return table;
}
} // namespace

void ElementValues::map(const Point *x)
{
  const int n = n_shape_;
  const int n_q = n_qpoints_;
  for (int q = 0; q < n_q; ++q)
  {
    const double *N = shape_ + q * n;
    const Point *dN = ref_grad_ + q * n;
    double J[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}; // J[d][r] = dx_d/dxi_r
    Point xq{0, 0, 0};
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d)
      {
        xq[d] += N[i] * x[i][d];
        for (int r = 0; r < 3; ++r)
          J[d][r] += x[i][d] * dN[i][r];
      }
    const Cofactors c = cofactors(J);
    if (!(c.det > 0.0))
      throw_inverted(c.det, q, type_, x[0]);
    // grad N_i = J^{-T} grad_xi N_i, component d: sum_r inv(J)[r][d] dN_r = sum_r C[d][r] dN_r /
    // det
    const double inv_det = 1.0 / c.det;
    Point *grad = grad_.data() + q * n;
    for (int i = 0; i < n; ++i)
    {
      // A copy: the stores to grad (Points too) would otherwise make the compiler reload
      // dN[i] for every component.
      const Point dN_i = dN[i];
      for (int d = 0; d < 3; ++d)
        grad[i][d] = (c.C[d][0] * dN_i[0] + c.C[d][1] * dN_i[1] + c.C[d][2] * dN_i[2]) * inv_det;
    }
    JxW_[q] = c.det * weights_[q];
    quadrature_point_[q] = xq;
  }
}

void ElementValues::map_hex8(const Point *x)
{
  // The same sums in the same order as map() (bit-identical results: each lane of a pair is
  // one of map()'s scalar sums), two at a time in the vector registers (GCC/Clang vector
  // extension; SSE2 on x86-64). The scalar loops cost a HEX8 residual pass about 10 %.
  using Pair = double __attribute__((vector_size(16)));
  constexpr int n = hex8_n_nodes;
  const Hex8Reference &t = hex8_reference();
  Point *const grad_out = grad_.data();
  double *const JxW_out = JxW_.data();
  Point *const xq_out = quadrature_point_.data();
  for (int q = 0; q < n; ++q)
  {
    // acc[d] = {x_q[d], J[d][0]} and {J[d][1], J[d][2]}: Σ_i x_i[d] {N_i, dN_i/dxi_r}.
    Pair acc[3][2] = {};
    for (int i = 0; i < n; ++i)
    {
      const Pair *row = reinterpret_cast<const Pair *>(t.row[q][i]);
      for (int d = 0; d < 3; ++d)
      {
        const Pair x_id = {x[i][d], x[i][d]};
        acc[d][0] += x_id * row[0];
        acc[d][1] += x_id * row[1];
      }
    }
    const double J[3][3] = {{acc[0][0][1], acc[0][1][0], acc[0][1][1]},
                            {acc[1][0][1], acc[1][1][0], acc[1][1][1]},
                            {acc[2][0][1], acc[2][1][0], acc[2][1][1]}};
    const Cofactors c = cofactors(J);
    if (!(c.det > 0.0))
      throw_inverted(c.det, q, type_, x[0]);
    const double inv_det = 1.0 / c.det;
    const Pair inv = {inv_det, inv_det};
    Point *grad = grad_out + q * n;
    for (int p = 0; p < n / 2; ++p)
    {
      Pair g[3];
      for (int d = 0; d < 3; ++d)
      {
        const Pair C0 = {c.C[d][0], c.C[d][0]}, C1 = {c.C[d][1], c.C[d][1]},
                   C2 = {c.C[d][2], c.C[d][2]};
        const Pair *G = reinterpret_cast<const Pair *>(t.grad[q][0]);
        g[d] = (C0 * G[p] + C1 * G[n / 2 + p] + C2 * G[n + p]) * inv;
      }
      grad[2 * p] = {g[0][0], g[1][0], g[2][0]};
      grad[2 * p + 1] = {g[0][1], g[1][1], g[2][1]};
    }
    JxW_out[q] = c.det * t.weights[q];
    xq_out[q] = {acc[0][0][0], acc[1][0][0], acc[2][0][0]};
  }
}
} // namespace kiln
