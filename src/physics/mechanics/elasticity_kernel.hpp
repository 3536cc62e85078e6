#pragma once
/// The volume kernel of small-strain isotropic linear thermo-elasticity on one cell.
#include "discretization/element_values.hpp"
#include "discretization/local_system.hpp"
#include "physics/kernel.hpp"
#include "physics/materials/constitutive_model.hpp"

#include <array>
#include <memory>
#include <vector>

namespace kiln
{
/// Static equilibrium of a linear thermo-elastic solid:  -div σ(u, T) = b.
///
///   ε = sym ∇u,   σ = λ tr(ε) I + 2G ε − β (T − T_ref) I,   β = (3λ + 2G) α
///   R_{i,d}              = ∫ (σ : sym(e_d ⊗ ∇φ_i) − b_d φ_i) dΩ = ∫ (σ_dk ∂_k φ_i − b_d φ_i) dΩ
///   dR_{i,d}/du_{j,e}    = ∫ (λ ∂_d φ_i ∂_e φ_j + G (δ_de ∇φ_i·∇φ_j + ∂_e φ_i ∂_d φ_j)) dΩ
///   dR_{i,d}/dT_j        = −∫ β φ_j ∂_d φ_i dΩ
///
/// u, ∇u and T are interpolated from the nodal values at the element's quadrature points; the
/// boundary terms are the BC kernels' (none: traction free). The residual is linear in u and
/// T, so the Jacobian is exact. The u–u block is symmetric. Only the displacement rows
/// (fields u_slot .. u_slot + 2) are touched, and the temperature columns (field T_slot) only
/// when T_slot >= 0, so the kernel serves the mechanical system (3 unknowns per node, T given)
/// and the coupled one (4 per node) alike.
///
/// General path (a kernel made from a ConstitutiveModel that is not constant_linear(): a
/// T-dependent or viscoplastic law): at each point the model gives σ(ε, T, state), its tangent
/// C = ∂σ/∂ε and ∂σ/∂T, and
///   R_{i,d}           = ∫ (σ_dk ∂_k φ_i − b_d φ_i) dΩ
///   dR_{i,d}/du_{j,e} = ∫ ∂_k φ_i C_{dk,I} B_{I,(j,e)} dΩ,  B = ∂ε/∂u (tensor shear strains)
///   dR_{i,d}/dT_j     = ∫ ∂_k φ_i (∂σ/∂T)_dk φ_j dΩ.
/// A constant linear-elastic model keeps the fast Hooke path above (bit-identical results).
class ElasticityKernel final : public CellKernel
{
public:
  /// u at the cell's nodes [m].
  using NodalDisplacements = Span<const Point>;
  /// T at the cell's nodes [K].
  using NodalValues = Span<const double>;

  /// lambda, G [Pa]; alpha [1/K]; T_ref [K] (the temperature of zero thermal strain); the
  /// body force b [N/m^3] of evaluate(CellState).
  ElasticityKernel(double lambda, double G, double alpha, double T_ref,
                   const Point &body_force = Point{});

  /// The kernel of `model` (shared: a block's model serves its cells). A constant_linear()
  /// LinearElasticModel takes the fast Hooke path with its constants; any other model the
  /// general path (state through evaluate_points()).
  ElasticityKernel(std::shared_ptr<const ConstitutiveModel> model, const Point &body_force);

  /// The general path's inputs beyond the cell's u and T: the temperature at t_n at the nodes
  /// (the last accepted state's, CellState::history.T_old; empty: T itself), Δt [s], and the cell's
  /// state at t_n and t_{n+1}, n_state() doubles per point, point after point
  /// (QuadratureState::old(c, 0), current(c, 0); null if no state).
  struct PointHistory
  {
    Span<const double> T_old{nullptr, 0};
    double time_step = 0.0;
    const double *old_state = nullptr;
    double *new_state = nullptr;
  };
  /// Whether the kernel runs the general path (a model that is not constant_linear()).
  bool general() const { return model_ != nullptr; }
  /// Its model on the general path (null on the fast path).
  const ConstitutiveModel *model() const { return model_.get(); }
  /// As evaluate(fe, ...) with the point history of the general path (on the fast path the
  /// history is ignored).
  void evaluate(const ElementValues &fe, const NodalDisplacements &u, const NodalValues &T,
                const PointHistory &history, const Point &body_force, int u_slot, int T_slot,
                LocalSystem &local) const;
  /// The general path's cell averages of σ, ε, the von Mises stress [Pa], the equivalent
  /// plastic strain [-] and its rate [1/s] at the points' state `history.old_state` (for
  /// output: the state of the step's end), the model taken with Δt = 0 (the stress of that
  /// state, the state unchanged); the history's other members are not read.
  struct PointAverages
  {
    Voigt stress{};
    Voigt strain{};
    Voigt thermal_strain{}; ///< ε_th(T) I averaged (the model's thermal_strain)
    double von_mises = 0.0;
    double plastic_strain = 0.0;
    double plastic_strain_rate = 0.0;
  };
  PointAverages point_averages(const ElementValues &fe, const NodalDisplacements &u,
                               const NodalValues &T, const PointHistory &history) const;

  /// Adds to `local` (one node per cell node) the residual [N] at local field index u_slot + d (d =
  /// 0, 1, 2) of local node i, the Jacobian d/du_{j,e} [N/m] (field u_slot + e) and, if T_slot >=
  /// 0, d/dT_j [N/K] (field T_slot). body_force b [N/m^3] is constant over the cell.
  void evaluate(const ElementValues &fe, const NodalDisplacements &u, const NodalValues &T,
                const Point &body_force, int u_slot, int T_slot, LocalSystem &local) const;
  /// The same from a cell's state, with the body force given at construction.
  void evaluate(const CellState &state, LocalSystem &local) const override;
  /// Linear thermo-elasticity (the fast path).
  bool constant_jacobian() const override { return model_ == nullptr; }

  /// Volume averages over the cell: stress [Pa], total strain ε [-] and thermal strain
  /// α (T − T_ref) I [-].
  struct CellAverages
  {
    Voigt stress;
    Voigt strain;
    Voigt thermal_strain;
  };
  /// ∫ (.) dΩ / ∫ dΩ, both by the quadrature rule of `fe`.
  CellAverages cell_averages(const ElementValues &fe, const NodalDisplacements &u,
                             const NodalValues &T) const;

  /// b [N/m^3], the body force of evaluate(CellState).
  const Point &body_force() const { return body_force_; }
  /// λ [Pa] (0 on the general path).
  double lambda() const { return lambda_; }
  /// G [Pa].
  double shear_modulus() const { return G_; }
  /// α [1/K].
  double alpha() const { return alpha_; }
  /// T_ref [K].
  double reference_temperature() const { return T_ref_; }

private:
  /// assemble<hex8_n_nodes, true>: a HEX8 (the common case) with compile-time loop bounds;
  /// the other cells of at most hex8_n_nodes nodes share its buffers, larger ones use
  /// max_cell_nodes.
  template <int N, bool exact>
  void assemble(const ElementValues &fe, const NodalDisplacements &u, const NodalValues &T,
                const Point &body_force, int u_slot, int T_slot, LocalSystem &local) const;

  double lambda_;
  double G_;
  double alpha_;
  double T_ref_;
  /// β = (3λ + 2G) α [Pa/K]: the stress of a blocked unit temperature rise.
  double thermal_modulus_;
  Point body_force_;
  /// The general path's model (null: the fast path).
  std::shared_ptr<const ConstitutiveModel> model_;
  /// σ at each point of the general path, by calling the model, and with `derivatives` C and
  /// ∂σ/∂T (PointInput::derivatives).
  void evaluate_points(const ElementValues &fe, const NodalDisplacements &u, const NodalValues &T,
                       const PointHistory &history, bool derivatives,
                       std::vector<PointResponse> &responses, std::vector<Voigt> *strains) const;
  void assemble_general(const ElementValues &fe, const NodalDisplacements &u, const NodalValues &T,
                        const PointHistory &history, const Point &body_force, int u_slot,
                        int T_slot, LocalSystem &local) const;
  template <int N, bool exact>
  void assemble_general(const ElementValues &fe, const std::vector<PointResponse> &responses,
                        const Point &body_force, int u_slot, int T_slot, LocalSystem &local) const;
};
} // namespace kiln
