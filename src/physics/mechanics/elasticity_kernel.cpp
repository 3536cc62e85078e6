#include "physics/mechanics/elasticity_kernel.hpp"

#include "base/errors.hpp"
#include "physics/materials/linear_elastic_model.hpp"

#include <algorithm>
#include <cmath>

namespace kiln
{
namespace
{
/// A 3x3 tensor, [row][column].
using Tensor = std::array<std::array<double, 3>, 3>;

/// ε = sym ∇u at a point where the n shape functions have the gradients grad_phi, with
/// (∇u)_dk = ∂u_d/∂x_k [-].
inline Tensor strain_at(const Point *grad_phi_at, const ElasticityKernel::NodalDisplacements &u,
                        const int n)
{
  Tensor grad_u{};
  for (int j = 0; j < n; ++j)
  {
    const Point &grad_phi = grad_phi_at[j];
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
/// The Voigt vector (tensor shear components) of a symmetric tensor.
Voigt to_voigt(const Tensor &t)
{
  return {t[0][0], t[1][1], t[2][2], t[0][1], t[0][2], t[1][2]};
}

/// The Voigt index of tensor component (d, k).
constexpr int voigt_index[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};

/// sqrt(3/2 s:s), s the deviator of σ (Voigt, shear components counted twice) [Pa].
double von_mises_of(const Voigt &s)
{
  const double mean = (s[0] + s[1] + s[2]) / 3.0;
  double ss = 0.0;
  for (int I = 0; I < 3; ++I)
    ss += (s[I] - mean) * (s[I] - mean);
  for (int I = 3; I < 6; ++I)
    ss += 2.0 * s[I] * s[I];
  return std::sqrt(1.5 * ss);
}

/// The fast path's constants of `model` if it is a constant linear-elastic model, else null.
const LinearElasticModel *fast_model(const ConstitutiveModel &model)
{
  return model.constant_linear() ? dynamic_cast<const LinearElasticModel *>(&model) : nullptr;
}
} // namespace

ElasticityKernel::ElasticityKernel(std::shared_ptr<const ConstitutiveModel> model,
                                   const Point &body_force)
    : lambda_(0.0), G_(0.0), alpha_(0.0), T_ref_(0.0), thermal_modulus_(0.0),
      body_force_(body_force)
{
  KILN_ASSERT(model != nullptr, "an elasticity kernel without a model");
  if (const LinearElasticModel *linear = fast_model(*model))
  {
    lambda_ = linear->lame_lambda();
    G_ = linear->shear_modulus();
    alpha_ = linear->thermal_expansion();
    T_ref_ = linear->reference_temperature();
    thermal_modulus_ = (3.0 * lambda_ + 2.0 * G_) * alpha_;
  }
  else
    model_ = std::move(model);
}

void ElasticityKernel::evaluate_points(const ElementValues &fe, const NodalDisplacements &u,
                                       const NodalValues &T, const PointHistory &history,
                                       const bool derivatives,
                                       std::vector<PointResponse> &responses,
                                       std::vector<Voigt> *strains) const
{
  const int n_state = model_->n_state();
  // Without a given state (a cell evaluated outside a run's steps) the points start from the
  // model's initial state and their new state is dropped.
  std::vector<double> scratch_old, scratch_new;
  const double *old_state = history.old_state;
  double *new_state = history.new_state;
  if (n_state > 0 && (old_state == nullptr || new_state == nullptr))
  {
    scratch_old.resize(static_cast<std::size_t>(n_state) * fe.n_qpoints());
    scratch_new.resize(scratch_old.size());
    for (int q = 0; q < fe.n_qpoints(); ++q)
      model_->initial_state(scratch_old.data() + q * n_state);
    old_state = old_state != nullptr ? old_state : scratch_old.data();
    new_state = new_state != nullptr ? new_state : scratch_new.data();
  }
  const bool has_old = history.T_old.size() == T.size();
  responses.resize(fe.n_qpoints());
  if (strains != nullptr)
    strains->resize(fe.n_qpoints());
  for (int q = 0; q < fe.n_qpoints(); ++q)
  {
    PointInput in;
    in.strain = to_voigt(strain_at(fe.grads(q), u, fe.n_shape()));
    for (int j = 0; j < fe.n_shape(); ++j)
    {
      in.temperature += fe.shape(j, q) * T[j];
      in.temperature_old += fe.shape(j, q) * (has_old ? history.T_old[j] : T[j]);
    }
    in.time_step = history.time_step;
    in.derivatives = derivatives;
    in.full_tangent = false; // assemble_general contracts the isotropic form where it is given
    responses[q] = PointResponse{};
    model_->evaluate(in, n_state > 0 ? old_state + q * n_state : nullptr,
                     n_state > 0 ? new_state + q * n_state : nullptr, responses[q]);
    if (strains != nullptr)
      (*strains)[q] = in.strain;
  }
  // A cell where some point has no isotropic form is contracted with the 6x6 tangents: those
  // of the points that gave only the form are built from it.
  if (derivatives && std::any_of(responses.begin(), responses.end(),
                                 [](const PointResponse &r) { return !r.isotropic.valid; }))
    for (PointResponse &r : responses)
      if (r.isotropic.valid)
        r.tangent = r.isotropic.matrix();
}

void ElasticityKernel::assemble_general(const ElementValues &fe, const NodalDisplacements &u,
                                        const NodalValues &T, const PointHistory &history,
                                        const Point &body_force, const int u_slot, const int T_slot,
                                        LocalSystem &local) const
{
  std::vector<PointResponse> responses;
  evaluate_points(fe, u, T, history, local.has_jacobian(), responses, nullptr);
  if (fe.type() == CellType::hex8)
    assemble_general<hex8_n_nodes, true>(fe, responses, body_force, u_slot, T_slot, local);
  else if (fe.n_shape() <= hex8_n_nodes)
    assemble_general<hex8_n_nodes, false>(fe, responses, body_force, u_slot, T_slot, local);
  else
    assemble_general<max_cell_nodes, false>(fe, responses, body_force, u_slot, T_slot, local);
}

/// Whether every point's tangent has the isotropic form with the same λ_t and μ_t and no
/// rank-one term (an elastic cell: the first Newton iteration of a step from rest, a cell
/// that does not flow, or E(T) at a uniform T); `valid`: whether every point has the form.
struct IsotropicCell
{
  bool valid = true;
  bool uniform = true;
};
IsotropicCell isotropic_cell(const std::vector<PointResponse> &responses, const int n_q)
{
  IsotropicCell cell;
  const IsotropicTangent &first = responses[0].isotropic;
  for (int q = 0; q < n_q; ++q)
  {
    const IsotropicTangent &t = responses[q].isotropic;
    cell.valid = cell.valid && t.valid;
    cell.uniform =
        cell.uniform && t.lambda == first.lambda && t.shear == first.shear && t.rank_one == 0.0;
  }
  cell.uniform = cell.uniform && cell.valid;
  return cell;
}

/// The general path's terms from the points' responses, with per-cell buffers of capacity
/// N >= fe.n_shape() (compile-time loop bounds with `exact`, as assemble<N, exact>).
///
/// When every point gives its tangent in isotropic form (IsotropicTangent: λ_t 1⊗1 + 2 μ_t 𝕀 +
/// γ n⊗n), the u–u block is contracted as Hooke's law on the fast path, with weights that
/// vary over the points:
///   dR_{i,d}/du_{j,e} = ∫ (λ_t ∂_d φ_i ∂_e φ_j + μ_t (δ_de ∇φ_i·∇φ_j + ∂_e φ_i ∂_d φ_j)
///                          + γ (n ∇φ_i)_d (n ∇φ_j)_e) dΩ
///                     = M_ij[d][e] + B_ij[e][d] + δ_de tr B_ij,
///   M_ij[d][e] = ∫ (λ_t ∂_d φ_i ∂_e φ_j + γ (n ∇φ_i)_d (n ∇φ_j)_e) dΩ,
///   B_ij[k][l] = ∫ μ_t ∂_k φ_i ∂_l φ_j dΩ,
/// symmetric under (i,d) <-> (j,e), so only the blocks j >= i are accumulated and each fills
/// its mirror image. A cell whose points share λ_t and μ_t and have γ = 0 (isotropic_cell's
/// `uniform`) accumulates the fast path's ∫ ∂_k φ_i ∂_l φ_j dΩ alone and scales it once.
///
/// Otherwise, with the tangent as a fourth-order C_dkel = ∂σ_dk/∂(∇u)_el = tangent[dk][el] w_el
/// (w = 1 on the diagonal, 1/2 off it: ε_el = ((∇u)_el + (∇u)_le)/2),
///   H_j[d][k][e]            = Σ_l C_dkel ∂_l φ_j JxW
///   dR_{i,d}/du_{j,e}      += Σ_k ∂_k φ_i H_j[d][k][e]
/// accumulated in the cell's buffers and added to `local` once.
template <int N, bool exact>
void ElasticityKernel::assemble_general(const ElementValues &fe,
                                        const std::vector<PointResponse> &responses,
                                        const Point &body_force, const int u_slot, const int T_slot,
                                        LocalSystem &local) const
{
  const int n = exact ? N : fe.n_shape();
  const int n_q = exact ? N : fe.n_qpoints();
  const bool jacobian = local.has_jacobian();
  const bool coupled = T_slot >= 0 && jacobian;
  const IsotropicCell form = jacobian ? isotropic_cell(responses, n_q) : IsotropicCell{};
  const bool isotropic = jacobian && form.valid;
  const bool general = jacobian && !isotropic;
  std::array<Point, N> residual{};
  // General: K[i][d][j][e] = dR_{i,d}/du_{j,e}. Isotropic: M[i][j] and B[i][j] (j >= i) as above
  // (uniform: B the geometric sums alone). KT[i][d][j] = dR_{i,d}/dT_j (coupled only).
  using Row = std::array<Point, N>;
  std::array<std::array<Row, 3>, N> K;
  std::array<std::array<Tensor, N>, N> M, B;
  std::array<std::array<std::array<double, N>, 3>, N> KT;
  if (general)
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d)
        std::fill(K[i][d].begin(), K[i][d].begin() + n, Point{});
  if (isotropic)
    for (int i = 0; i < n; ++i)
      for (int j = i; j < n; ++j)
      {
        B[i][j] = Tensor{};
        if (!form.uniform)
          M[i][j] = Tensor{};
      }
  if (coupled)
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d)
        std::fill(KT[i][d].begin(), KT[i][d].begin() + n, 0.0);
  std::array<std::array<Tensor, 3>, N> H; // H[j][d][k][e]
  std::array<Point, N> a, b, v, w; // λ_t JxW ∇φ_i, μ_t JxW ∇φ_i, n ∇φ_i, γ JxW n ∇φ_i
  for (int q = 0; q < n_q; ++q)
  {
    const double JxW = fe.JxW(q);
    const double *phi = fe.shapes(q);
    const Point *grad_phi = fe.grads(q);
    const PointResponse &r = responses[q];
    for (int i = 0; i < n; ++i)
    {
      const Point &g = grad_phi[i];
      for (int d = 0; d < 3; ++d)
      {
        double value = -body_force[d] * phi[i];
        for (int k = 0; k < 3; ++k)
          value += r.stress[voigt_index[d][k]] * g[k];
        residual[i][d] += value * JxW;
      }
    }
    if (coupled)
      for (int i = 0; i < n; ++i)
        for (int d = 0; d < 3; ++d)
        {
          const Point &g = grad_phi[i];
          double s = 0.0;
          for (int k = 0; k < 3; ++k)
            s += r.stress_temperature_derivative[voigt_index[d][k]] * g[k];
          s *= JxW;
          for (int j = 0; j < n; ++j)
            KT[i][d][j] += s * phi[j];
        }
    if (isotropic && form.uniform)
    {
      for (int i = 0; i < n; ++i)
      {
        Point g_i;
        for (int k = 0; k < 3; ++k)
          g_i[k] = grad_phi[i][k] * JxW;
        for (int j = i; j < n; ++j)
        {
          const Point &g_j = grad_phi[j];
          Tensor &B_ij = B[i][j];
          for (int k = 0; k < 3; ++k)
            for (int l = 0; l < 3; ++l)
              B_ij[k][l] += g_i[k] * g_j[l];
        }
      }
    }
    else if (isotropic)
    {
      const IsotropicTangent &t = r.isotropic;
      const double lambda_JxW = t.lambda * JxW, shear_JxW = t.shear * JxW;
      const double rank_one_JxW = t.rank_one * JxW;
      const bool rank_one = rank_one_JxW != 0.0;
      for (int i = 0; i < n; ++i)
      {
        const Point &g = grad_phi[i];
        for (int k = 0; k < 3; ++k)
        {
          a[i][k] = lambda_JxW * g[k];
          b[i][k] = shear_JxW * g[k];
        }
        if (rank_one)
          for (int d = 0; d < 3; ++d)
          {
            v[i][d] = t.n[voigt_index[d][0]] * g[0] + t.n[voigt_index[d][1]] * g[1] +
                      t.n[voigt_index[d][2]] * g[2];
            w[i][d] = rank_one_JxW * v[i][d];
          }
      }
      for (int i = 0; i < n; ++i)
        for (int j = i; j < n; ++j)
        {
          const Point &g_j = grad_phi[j];
          Tensor &M_ij = M[i][j];
          Tensor &B_ij = B[i][j];
          for (int k = 0; k < 3; ++k)
            for (int l = 0; l < 3; ++l)
            {
              M_ij[k][l] += a[i][k] * g_j[l];
              B_ij[k][l] += b[i][k] * g_j[l];
            }
          if (rank_one)
            for (int d = 0; d < 3; ++d)
              for (int e = 0; e < 3; ++e)
                M_ij[d][e] += w[i][d] * v[j][e];
        }
    }
    if (!general)
      continue;
    // C_dkel JxW.
    double C[3][3][3][3];
    for (int d = 0; d < 3; ++d)
      for (int k = 0; k < 3; ++k)
        for (int e = 0; e < 3; ++e)
          for (int l = 0; l < 3; ++l)
            C[d][k][e][l] =
                r.tangent[voigt_index[d][k]][voigt_index[e][l]] * (e == l ? JxW : 0.5 * JxW);
    for (int j = 0; j < n; ++j)
    {
      const Point &g = grad_phi[j];
      for (int d = 0; d < 3; ++d)
        for (int k = 0; k < 3; ++k)
          for (int e = 0; e < 3; ++e)
            H[j][d][k][e] = C[d][k][e][0] * g[0] + C[d][k][e][1] * g[1] + C[d][k][e][2] * g[2];
    }
    for (int i = 0; i < n; ++i)
    {
      const Point &g = grad_phi[i];
      for (int d = 0; d < 3; ++d)
      {
        Row &K_id = K[i][d];
        for (int j = 0; j < n; ++j)
        {
          const Tensor &H_jd = H[j][d];
          for (int e = 0; e < 3; ++e)
            K_id[j][e] += g[0] * H_jd[0][e] + g[1] * H_jd[1][e] + g[2] * H_jd[2][e];
        }
      }
    }
  }
  for (int i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d)
    {
      local.residual(u_slot + d, i) += residual[i][d];
      if (coupled)
        for (int j = 0; j < n; ++j)
          local.jacobian(u_slot + d, i, T_slot, j) += KT[i][d][j];
      if (general)
        for (int j = 0; j < n; ++j)
          for (int e = 0; e < 3; ++e)
            local.jacobian(u_slot + d, i, u_slot + e, j) += K[i][d][j][e];
    }
  if (!isotropic)
    return;
  // Uniform: M = λ_t gg, B = μ_t gg with gg the geometric sums held in B.
  const double lambda = responses[0].isotropic.lambda, shear = responses[0].isotropic.shear;
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j)
    {
      const Tensor &B_ij = B[i][j];
      const double B_trace = B_ij[0][0] + B_ij[1][1] + B_ij[2][2];
      for (int d = 0; d < 3; ++d)
        for (int e = 0; e < 3; ++e)
        {
          const double value = form.uniform ? lambda * B_ij[d][e] + shear * B_ij[e][d] +
                                                  (d == e ? shear * B_trace : 0.0)
                                            : M[i][j][d][e] + B_ij[e][d] + (d == e ? B_trace : 0.0);
          local.jacobian(u_slot + d, i, u_slot + e, j) += value;
          if (j != i)
            local.jacobian(u_slot + e, j, u_slot + d, i) += value;
        }
    }
}

ElasticityKernel::PointAverages ElasticityKernel::point_averages(const ElementValues &fe,
                                                                 const NodalDisplacements &u,
                                                                 const NodalValues &T,
                                                                 const PointHistory &history) const
{
  PointAverages averages;
  if (model_ == nullptr)
  {
    const CellAverages cell = cell_averages(fe, u, T);
    averages.stress = cell.stress;
    averages.strain = cell.strain;
    averages.thermal_strain = cell.thermal_strain;
    averages.von_mises = von_mises_of(cell.stress);
    return averages;
  }
  std::vector<PointResponse> responses;
  std::vector<Voigt> strains;
  // The points at the state `history.old_state` with Δt = 0: the stress of that state, whose
  // next state goes to a scratch copy (the averages never move the state).
  std::vector<double> scratch(static_cast<std::size_t>(model_->n_state()) * fe.n_qpoints());
  PointHistory copy = history;
  copy.time_step = 0.0;
  copy.new_state = scratch.empty() ? nullptr : scratch.data();
  evaluate_points(fe, u, T, copy, false, responses, &strains);
  double volume = 0.0;
  const int n_state = model_->n_state();
  for (int q = 0; q < fe.n_qpoints(); ++q)
  {
    const double JxW = fe.JxW(q);
    for (int I = 0; I < 6; ++I)
    {
      averages.stress[I] += JxW * responses[q].stress[I];
      averages.strain[I] += JxW * strains[q][I];
    }
    averages.von_mises += JxW * von_mises_of(responses[q].stress);
    double T_q = 0.0;
    for (int i = 0; i < fe.n_shape(); ++i)
      T_q += fe.shape(i, q) * T[i];
    const double thermal = model_->thermal_strain(T_q);
    for (int d = 0; d < 3; ++d)
      averages.thermal_strain[d] += JxW * thermal;
    if (n_state > 0 && history.old_state != nullptr)
    {
      const double *state = history.old_state + q * n_state;
      averages.plastic_strain += JxW * model_->equivalent_plastic_strain(state);
      averages.plastic_strain_rate += JxW * model_->plastic_strain_rate(state);
    }
    volume += JxW;
  }
  for (double &v : averages.stress)
    v /= volume;
  for (double &v : averages.strain)
    v /= volume;
  for (double &v : averages.thermal_strain)
    v /= volume;
  averages.von_mises /= volume;
  averages.plastic_strain /= volume;
  averages.plastic_strain_rate /= volume;
  return averages;
}

ElasticityKernel::ElasticityKernel(const double lambda, const double G, const double alpha,
                                   const double T_ref, const Point &body_force)
    : lambda_(lambda), G_(G), alpha_(alpha), T_ref_(T_ref),
      thermal_modulus_((3.0 * lambda + 2.0 * G) * alpha), body_force_(body_force)
{
}

void ElasticityKernel::evaluate(const CellState &state, LocalSystem &local) const
{
  if (model_ != nullptr)
    assemble_general(state.fe, state.u, state.T, PointHistory{}, body_force_, state.slots.u,
                     state.slots.T, local);
  else
    evaluate(state.fe, state.u, state.T, body_force_, state.slots.u, state.slots.T, local);
}

void ElasticityKernel::evaluate(const ElementValues &fe, const NodalDisplacements &u,
                                const NodalValues &T, const PointHistory &history,
                                const Point &body_force, const int u_slot, const int T_slot,
                                LocalSystem &local) const
{
  if (model_ == nullptr)
    evaluate(fe, u, T, body_force, u_slot, T_slot, local);
  else
    assemble_general(fe, u, T, history, body_force, u_slot, T_slot, local);
}

/// The cell's terms with per-cell buffers of capacity N >= fe.n_shape(). With `exact` the
/// cell is a HEX8 of N nodes and N quadrature points, compile-time loop bounds (its loops
/// unroll); otherwise the loops run to fe.n_shape() and fe.n_qpoints().
template <int N, bool exact>
void ElasticityKernel::assemble(const ElementValues &fe, const NodalDisplacements &u,
                                const NodalValues &T_nodes, const Point &body_force,
                                const int u_slot, const int T_slot, LocalSystem &local) const
{
  const int n = exact ? N : fe.n_shape();
  const int n_q = exact ? N : fe.n_qpoints();
  const bool jacobian = local.has_jacobian();
  const bool coupled = T_slot >= 0 && jacobian;

  // Accumulated over the quadrature points, scattered once at the end:
  //   residual[i][d]  = R_{i,d}
  //   gg[i][j][k][l]  = ∫ ∂_k φ_i ∂_l φ_j dΩ  (j >= i only: gg[j][i] is its transpose)
  //   phi_grad[i][j][d] = ∫ φ_j ∂_d φ_i dΩ  (coupled only)
  // gg and phi_grad (6 KB for a HEX8) are cleared only where the pass uses them: a residual
  // pass needs neither.
  std::array<Point, N> residual{};
  std::array<std::array<Tensor, N>, N> gg;
  std::array<std::array<Point, N>, N> phi_grad;
  if (jacobian)
    for (int i = 0; i < n; ++i)
      for (int j = i; j < n; ++j)
        gg[i][j] = Tensor{};
  if (coupled)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        phi_grad[i][j] = Point{};
  std::array<Point, N> grad_JxW;
  std::array<double, N> dT_nodes;
  for (int j = 0; j < n; ++j)
    dT_nodes[j] = T_nodes[j] - T_ref_;
  for (int q = 0; q < n_q; ++q)
  {
    const double JxW = fe.JxW(q);
    const double *phi = fe.shapes(q);
    const Point *grad_phi = fe.grads(q);
    double dT = 0.0;
    for (int j = 0; j < n; ++j)
      dT += phi[j] * dT_nodes[j];
    const Tensor stress =
        hooke_stress(lambda_, G_, thermal_modulus_, strain_at(grad_phi, u, n), dT);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k)
        grad_JxW[i][k] = grad_phi[i][k] * JxW;

    for (int i = 0; i < n; ++i)
    {
      const Point &g_i = grad_JxW[i];
      const double phi_i_JxW = phi[i] * JxW;
      for (int d = 0; d < 3; ++d)
        residual[i][d] += stress[d][0] * g_i[0] + stress[d][1] * g_i[1] + stress[d][2] * g_i[2] -
                          body_force[d] * phi_i_JxW;
      for (int j = i; j < n && jacobian; ++j)
      {
        const Point &g_j = grad_phi[j];
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
  if (fe.type() == CellType::hex8)
    assemble<hex8_n_nodes, true>(fe, u, T_nodes, body_force, u_slot, T_slot, local);
  else if (fe.n_shape() <= hex8_n_nodes)
    assemble<hex8_n_nodes, false>(fe, u, T_nodes, body_force, u_slot, T_slot, local);
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
    const Tensor strain = strain_at(fe.grads(q), u, fe.n_shape());
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
