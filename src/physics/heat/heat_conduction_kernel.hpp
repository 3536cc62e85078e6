#pragma once
/// The volume kernel of transient heat conduction on one cell.
#include "discretization/element_values.hpp"
#include "discretization/local_system.hpp"
#include "physics/kernel.hpp"
#include "physics/materials/conductivity_model.hpp"
#include "physics/materials/enthalpy.hpp"

#include <array>

namespace kiln
{
/// Transient heat conduction without sources, in conservative form:
///   dH(T)/dt - div(k(T) grad T) = 0,   H(T) = ∫ rho c dT (Enthalpy), dH/dT = rho c.
///
/// With a constant rho c (H = rho c T, the path of a constant material):
///   R_i       = ∫ (rho c Tdot φ_i + k(T) ∇T·∇φ_i) dΩ
///   dR_i/dT_j = ∫ (rho c a φ_j φ_i + k ∇φ_j·∇φ_i + k'(T) φ_j ∇T·∇φ_i) dΩ,   a = dTdot/dT
/// With rho c of T the time derivative is the integrator's applied to H itself,
///   Hdot = a H(T) + Σ_k w_k H(T_k)   (CellState::history: T_k the past temperatures, w_k
///   their weights: backward Euler (H(T) - H(T_n))/dt, Truchas' form; BDF2 its 3 levels),
/// so the change of ∫ H over the steps equals the heat that came in (doc/heat.md):
///   R_i      = ∫ (Hdot φ_i + k(T) ∇T·∇φ_i) dΩ,   Hdot at the point from T, T_k at the point
///   dR_i/dT_j = ∫ (a rho c(T) φ_j φ_i + k ∇φ_j·∇φ_i + k'(T) φ_j ∇T·∇φ_i) dΩ
///
/// With the lumped (row-sum) capacity the capacity term is the diagonal of the rows' sums,
/// M_ii = Σ_j ∫ φ_j φ_i dΩ = ∫ φ_i dΩ (the shape functions sum to one), at the node:
///   R_i += Hdot_i ∫ φ_i dΩ,   dR_i/dT_i += a rho c(T_i) ∫ φ_i dΩ,   Hdot_i from T_i, T_k,i
/// (rho c Tdot_i with a constant rho c); it keeps a thermal shock from undershooting
/// (doc/heat.md).
///
/// T, Tdot and ∇T are interpolated from the nodal values at the Gauss points;
/// the boundary terms are the BC kernels' (none: insulated). Only the temperature rows
/// and columns (Field::T) of the local system are touched, so the kernel serves the
/// thermal system (1 unknown per node) and the coupled one (4 per node) alike.
class HeatConductionKernel final : public CellKernel
{
public:
  using NodalValues = Span<const double>;
  /// The capacity matrix: consistent ∫ φ_j φ_i, or lumped by rows' sums.
  enum class Capacity
  {
    consistent,
    lumped
  };

  /// H(T) (rho c of T); k(T) [W/(m K)].
  HeatConductionKernel(Enthalpy enthalpy, ConductivityModel conductivity, Capacity capacity);
  /// A constant rho_c [J/(m^3 K)]; k(T) [W/(m K)].
  HeatConductionKernel(double rho_c, ConductivityModel conductivity, Capacity capacity);

  /// Adds the cell's residual [W] and Jacobian [W/K] to `local` (a node per cell node): T [K] and
  /// T_dot [K/s] at the nodes, dTdot_dT = a [1/s], and the past temperatures (needed with a
  /// rho c of T and a != 0: needs_temperature_history()).
  void evaluate(const ElementValues &fe, const NodalValues &T, const NodalValues &T_dot,
                double dTdot_dT, const TemperatureHistory &history, LocalSystem &local) const;
  /// The same without past temperatures (a constant rho c, or a = 0).
  void evaluate(const ElementValues &fe, const NodalValues &T, const NodalValues &T_dot,
                double dTdot_dT, LocalSystem &local) const
  {
    evaluate(fe, T, T_dot, dTdot_dT, TemperatureHistory{}, local);
  }
  /// The same from a cell's state.
  void evaluate(const CellState &state, LocalSystem &local) const override;
  /// With a constant k and rho c: rho c a M + K.
  bool constant_jacobian() const override
  {
    return conductivity_.is_constant() && enthalpy_.is_linear();
  }
  /// Whether the capacity term reads the past temperatures (rho c depends on T).
  bool needs_temperature_history() const { return !enthalpy_.is_linear(); }
  /// k(T).
  const ConductivityModel &conductivity() const { return conductivity_; }
  /// H(T) and rho c(T).
  const Enthalpy &enthalpy() const { return enthalpy_; }
  /// Consistent or lumped.
  Capacity capacity() const { return capacity_; }

private:
  /// `fixed` = hex8_n_nodes: a HEX8 cell (the common case) with compile-time loop bounds; 0:
  /// any type. `linear`: a constant rho c (H = rho c T), the path of a constant material.
  template <int fixed, bool linear>
  void assemble(const ElementValues &fe, const NodalValues &T, const NodalValues &T_dot,
                double dTdot_dT, const TemperatureHistory &history, LocalSystem &local) const;
  /// Hdot = a H(T) + Σ_k w_k H(T_k) from the temperatures T_k at a node or point.
  double enthalpy_rate(double T, const std::array<double, 2> &T_past, double dTdot_dT,
                       const TemperatureHistory &history) const;

  Enthalpy enthalpy_;
  double rho_c_; ///< rho c if enthalpy_.is_linear() [J/(m^3 K)]
  Capacity capacity_;
  ConductivityModel conductivity_;
};
} // namespace kiln
