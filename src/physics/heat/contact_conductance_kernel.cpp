#include "physics/heat/contact_conductance_kernel.hpp"

#include "contact/gap_opening.hpp"

#include <algorithm>
#include <cmath>

namespace kiln
{
std::vector<int> ContactConductanceKernel::nodes(const Mesh &mesh, const GapFace &face) const
{
  std::vector<int> result = InterfaceKernel::nodes(mesh, face);
  for (const int c : {face.cell_a, face.cell_b})
    for (const int n : mesh.cell_nodes(c))
      if (std::find(result.begin(), result.end(), n) == result.end())
        result.push_back(n);
  return result;
}

void ContactConductanceKernel::evaluate(const InterfaceState &state, LocalSystem &local) const
{
  evaluate(state.fv, state.fe_a, state.fe_b, state.cell_a, state.cell_b, state.T, state.u,
           state.slots.T, state.slots.u, local);
}

double ContactConductanceKernel::conductance(const double g, const double p) const
{
  return p_.h0 * p_.length / (p_.length + std::max(g, 0.0)) +
         p_.pressure_coefficient * std::max(p, 0.0);
}

void ContactConductanceKernel::evaluate(const FaceValues &fv, const ElementValues &fe_a,
                                        const ElementValues &fe_b, const Span<const int> cell_a,
                                        const Span<const int> cell_b, const std::vector<double> &T,
                                        const std::vector<Point> &u, const int T_slot,
                                        const int u_slot, LocalSystem &local) const
{
  const int n_local = local.n_nodes();
  const int n_face = fv.n_shape(); // local nodes 0..n_face-1 on side a, then their twins
  // The face's mean normal (a plane face: its normal).
  Point n{};
  for (int q = 0; q < fv.n_qpoints(); ++q)
    for (int d = 0; d < 3; ++d)
      n[d] += fv.normal(q)[d] * fv.JxW(q);
  const double length = std::sqrt(dot(n, n));
  for (double &x : n)
    x /= length;

  // p = (p_a + p_b)/2, p_X = -[lambda tr ε̄ + 2G n.ε̄ n - beta (T̄ - T_ref)], linear in u
  // and T: dp/du_j (a vector) and dp/dT_j per local node.
  std::vector<Point> dp_du(n_local, Point{});
  std::vector<double> dp_dT(n_local, 0.0);
  double p = 0.0;
  const auto add_cell = [&](const ElementValues &fe, const Span<const int> cell)
  {
    double volume = 0.0;
    for (int q = 0; q < fe.n_qpoints(); ++q)
      volume += fe.JxW(q);
    for (int j = 0; j < fe.n_shape(); ++j)
    {
      Point B{};
      double w = 0.0;
      for (int q = 0; q < fe.n_qpoints(); ++q)
      {
        for (int d = 0; d < 3; ++d)
          B[d] += fe.grad(j, q)[d] * fe.JxW(q) / volume;
        w += fe.shape(j, q) * fe.JxW(q) / volume;
      }
      const int l = cell[j];
      const double nB = dot(n, B);
      Point d_u{};
      for (int d = 0; d < 3; ++d)
        d_u[d] = -0.5 * (p_.lambda * B[d] + 2.0 * p_.shear_modulus * nB * n[d]);
      const double d_T = 0.5 * p_.beta * w;
      for (int d = 0; d < 3; ++d)
        dp_du[l][d] += d_u[d];
      dp_dT[l] += d_T;
      p += dot(d_u, u[l]) + d_T * (T[l] - p_.reference_temperature);
    }
  };
  add_cell(fe_a, cell_a);
  add_cell(fe_b, cell_b);
  const double dh_dp = p > 0.0 ? p_.pressure_coefficient : 0.0;

  for (int q = 0; q < fv.n_qpoints(); ++q)
  {
    double jump = 0.0;
    Point u_a{}, u_b{};
    for (int j = 0; j < n_face; ++j)
    {
      jump += fv.shape(j, q) * (T[j] - T[n_face + j]);
      for (int d = 0; d < 3; ++d)
      {
        u_a[d] += fv.shape(j, q) * u[j][d];
        u_b[d] += fv.shape(j, q) * u[n_face + j][d];
      }
    }
    const double g = gap_opening(fv.normal(q), u_a, u_b);
    const double h = conductance(g, p);
    const double dh_dg = g > 0.0 ? -p_.h0 * p_.length / ((p_.length + g) * (p_.length + g)) : 0.0;
    const double JxW = fv.JxW(q);
    for (int i = 0; i < n_face; ++i)
    {
      const double phi = fv.shape(i, q) * JxW;
      local.residual(T_slot, i) += h * jump * phi;
      local.residual(T_slot, n_face + i) -= h * jump * phi;
      if (!local.has_jacobian())
        continue;
      // d/dT of the jump.
      for (int j = 0; j < n_face; ++j)
      {
        const double m = h * fv.shape(j, q) * phi;
        local.jacobian(T_slot, i, T_slot, j) += m;
        local.jacobian(T_slot, i, T_slot, n_face + j) -= m;
        local.jacobian(T_slot, n_face + i, T_slot, j) -= m;
        local.jacobian(T_slot, n_face + i, T_slot, n_face + j) += m;
      }
      // dh/dg dg/du: g depends on the face nodes' u.
      if (dh_dg != 0.0)
        for (int j = 0; j < n_face; ++j)
          for (int d = 0; d < 3; ++d)
          {
            const double v = jump * phi * dh_dg * fv.shape(j, q) * fv.normal(q)[d];
            local.jacobian(T_slot, i, u_slot + d, n_face + j) += v;
            local.jacobian(T_slot, i, u_slot + d, j) -= v;
            local.jacobian(T_slot, n_face + i, u_slot + d, n_face + j) -= v;
            local.jacobian(T_slot, n_face + i, u_slot + d, j) += v;
          }
      // dh/dp dp/d(u, T): p depends on both cells' nodes.
      if (dh_dp != 0.0)
        for (int l = 0; l < n_local; ++l)
        {
          const double s = jump * phi * dh_dp;
          for (int d = 0; d < 3; ++d)
          {
            local.jacobian(T_slot, i, u_slot + d, l) += s * dp_du[l][d];
            local.jacobian(T_slot, n_face + i, u_slot + d, l) -= s * dp_du[l][d];
          }
          local.jacobian(T_slot, i, T_slot, l) += s * dp_dT[l];
          local.jacobian(T_slot, n_face + i, T_slot, l) -= s * dp_dT[l];
        }
    }
  }
}
} // namespace kiln
