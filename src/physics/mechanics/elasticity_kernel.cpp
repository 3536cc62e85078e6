#include "physics/mechanics/elasticity_kernel.hpp"

#include "base/errors.hpp"

namespace kiln
{
namespace
{
/// A 3x3 tensor, [row][column].
using Tensor = std::array<std::array<double, 3>, 3>;

/// ε = sym ∇u at Gauss point q, with (∇u)_dk = ∂u_d/∂x_k [-].
Tensor strain_at(const ElementValues &fe, const ElasticityKernel::NodalDisplacements &u,
                 const int q, const int n)
{
  Tensor grad_u{};
  for (int j = 0; j < n; ++j)
  {
    const Point &grad_phi = fe.grad(j, q);
    for (int d = 0; d < 3; ++d)
      for (int k = 0; k < 3; ++k)
        grad_u[d][k] += u[j][d] * grad_phi[k];
  }
  Tensor strain;
  for (int d = 0; d < 3; ++d)
    for (int k = 0; k < 3; ++k)
      strain[d][k] = 0.5 * (grad_u[d][k] + grad_u[k][d]);
  return strain;
}

/// T_j − T_ref at the nodes [K]. The difference is interpolated, not T: T ~ 300 K and
/// T − T_ref ~ 1 K, so interpolating T first would leave a rounding error of ~1e-14 K that
/// β turns into a spurious stress (and T = T_ref would not give exactly zero).
/// Σ_j φ_j (T_j − T_ref) at point q.
double temperature_change_at(const ElementValues &fe, const ElasticityKernel::NodalValues &T,
                             const double T_ref, const int q)
{
  double value = 0.0;
  for (int j = 0; j < fe.n_shape(); ++j)
    value += fe.shape(j, q) * (T[j] - T_ref);
  return value;
}

/// σ = λ tr(ε) I + 2G ε − β ΔT I [Pa].
Tensor hooke_stress(const double lambda, const double G, const double thermal_modulus,
                    const Tensor &strain, const double dT)
{
  const double volumetric =
      lambda * (strain[0][0] + strain[1][1] + strain[2][2]) - thermal_modulus * dT;
  Tensor stress;
  for (int d = 0; d < 3; ++d)
    for (int k = 0; k < 3; ++k)
      stress[d][k] = 2.0 * G * strain[d][k] + (d == k ? volumetric : 0.0);
  return stress;
}

/// Adds w times the symmetric tensor t to v in Voigt order (xx, yy, zz, xy, xz, yz).
void add_to_voigt(const double w, const Tensor &t, Voigt &v)
{
  v[0] += w * t[0][0];
  v[1] += w * t[1][1];
  v[2] += w * t[2][2];
  v[3] += w * t[0][1];
  v[4] += w * t[0][2];
  v[5] += w * t[1][2];
}
} // namespace

ElasticityKernel::ElasticityKernel(const double lambda, const double G, const double alpha,
                                   const double T_ref, const Point &body_force)
    : lambda_(lambda), G_(G), alpha_(alpha), T_ref_(T_ref),
      thermal_modulus_((3.0 * lambda + 2.0 * G) * alpha), body_force_(body_force)
{
}

void ElasticityKernel::evaluate(const CellState &state, LocalSystem &local) const
{
  evaluate(state.fe, state.u, state.T, body_force_, state.slots.u, state.slots.T, local);
}

/// The cell's terms with per-cell buffers of capacity N >= fe.n_shape(). With `exact` the
/// cell has N nodes, a compile-time loop bound (the loops of the common HEX8 unroll);
/// otherwise the loops run to fe.n_shape().
template <int N, bool exact>
void ElasticityKernel::assemble(const ElementValues &fe, const NodalDisplacements &u,
                                const NodalValues &T_nodes, const Point &body_force,
                                const int u_slot, const int T_slot, LocalSystem &local) const
{
  const int n = exact ? N : fe.n_shape();
  const bool jacobian = local.has_jacobian();
  const bool coupled = T_slot >= 0 && jacobian;

  // Accumulated over the quadrature points, scattered once at the end:
  //   residual[i][d]  = R_{i,d}
  //   gg[i][j][k][l]  = ∫ ∂_k φ_i ∂_l φ_j dΩ  (j >= i only: gg[j][i] is its transpose)
  //   phi_grad[i][j][d] = ∫ φ_j ∂_d φ_i dΩ  (coupled only)
  std::array<Point, N> residual{};
  std::array<std::array<Tensor, N>, N> gg{};
  std::array<std::array<Point, N>, N> phi_grad{};
  std::array<Point, N> grad_JxW;
  std::array<double, N> dT_nodes, phi;
  for (int j = 0; j < n; ++j)
    dT_nodes[j] = T_nodes[j] - T_ref_;
  for (int q = 0; q < fe.n_qpoints(); ++q)
  {
    const double JxW = fe.JxW(q);
    // φ_j(x_q), copied once per point (the table lookup is not free in the inner loops).
    double dT = 0.0;
    for (int j = 0; j < n; ++j)
    {
      phi[j] = fe.shape(j, q);
      dT += phi[j] * dT_nodes[j];
    }
    const Tensor stress = hooke_stress(lambda_, G_, thermal_modulus_, strain_at(fe, u, q, n), dT);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k)
        grad_JxW[i][k] = fe.grad(i, q)[k] * JxW;

    for (int i = 0; i < n; ++i)
    {
      const Point &g_i = grad_JxW[i];
      const double phi_i_JxW = phi[i] * JxW;
      for (int d = 0; d < 3; ++d)
        residual[i][d] += stress[d][0] * g_i[0] + stress[d][1] * g_i[1] + stress[d][2] * g_i[2] -
                          body_force[d] * phi_i_JxW;
      for (int j = i; j < n && jacobian; ++j)
      {
        const Point &g_j = fe.grad(j, q);
        Tensor &gg_ij = gg[i][j];
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l)
            gg_ij[k][l] += g_i[k] * g_j[l];
      }
      if (coupled)
        for (int j = 0; j < n; ++j)
          for (int d = 0; d < 3; ++d)
            phi_grad[i][j][d] += phi[j] * g_i[d];
    }
  }

  for (int i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d)
      local.residual(u_slot + d, i) += residual[i][d];

  if (!jacobian)
    return;
  // K_{(i,d),(j,e)} = λ gg_ij[d][e] + G gg_ij[e][d] + δ_de G tr(gg_ij), symmetric under
  // (i,d) <-> (j,e): the blocks j > i also fill their mirror images.
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j)
    {
      const Tensor &gg_ij = gg[i][j];
      const double G_trace = G_ * (gg_ij[0][0] + gg_ij[1][1] + gg_ij[2][2]);
      for (int d = 0; d < 3; ++d)
        for (int e = 0; e < 3; ++e)
        {
          const double K = lambda_ * gg_ij[d][e] + G_ * gg_ij[e][d] + (d == e ? G_trace : 0.0);
          local.jacobian(u_slot + d, i, u_slot + e, j) += K;
          if (j != i)
            local.jacobian(u_slot + e, j, u_slot + d, i) += K;
        }
    }

  if (coupled)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int d = 0; d < 3; ++d)
          local.jacobian(u_slot + d, i, T_slot, j) -= thermal_modulus_ * phi_grad[i][j][d];
}

void ElasticityKernel::evaluate(const ElementValues &fe, const NodalDisplacements &u,
                                const NodalValues &T_nodes, const Point &body_force,
                                const int u_slot, const int T_slot, LocalSystem &local) const
{
  KILN_ASSERT(local.n_nodes() == fe.n_shape() && u.size() == fe.n_shape() &&
                  T_nodes.size() == fe.n_shape(),
              "a cell of " << fe.n_shape() << " nodes, a local system of " << local.n_nodes());
  KILN_ASSERT(u_slot >= 0 && u_slot + 3 <= local.n_fields(),
              "u_slot " << u_slot << " out of range for " << local.n_fields() << " fields");
  KILN_ASSERT(T_slot < local.n_fields() && (T_slot < u_slot || T_slot >= u_slot + 3),
              "T_slot " << T_slot << " out of range or overlapping u_slot " << u_slot);
  if (fe.n_shape() == small_cell_nodes)
    assemble<small_cell_nodes, true>(fe, u, T_nodes, body_force, u_slot, T_slot, local);
  else if (fe.n_shape() < small_cell_nodes)
    assemble<small_cell_nodes, false>(fe, u, T_nodes, body_force, u_slot, T_slot, local);
  else
    assemble<max_cell_nodes, false>(fe, u, T_nodes, body_force, u_slot, T_slot, local);
}

ElasticityKernel::CellAverages ElasticityKernel::cell_averages(const ElementValues &fe,
                                                               const NodalDisplacements &u,
                                                               const NodalValues &T_nodes) const
{
  CellAverages averages{};
  double volume = 0.0;
  for (int q = 0; q < fe.n_qpoints(); ++q)
  {
    const double JxW = fe.JxW(q);
    const Tensor strain = strain_at(fe, u, q, fe.n_shape());
    const double dT = temperature_change_at(fe, T_nodes, T_ref_, q);
    add_to_voigt(JxW, strain, averages.strain);
    add_to_voigt(JxW, hooke_stress(lambda_, G_, thermal_modulus_, strain, dT), averages.stress);
    for (int d = 0; d < 3; ++d)
      averages.thermal_strain[d] += JxW * alpha_ * dT;
    volume += JxW;
  }
  for (Voigt *v : {&averages.stress, &averages.strain, &averages.thermal_strain})
    for (double &component : *v)
      component /= volume;
  return averages;
}
} // namespace kiln
