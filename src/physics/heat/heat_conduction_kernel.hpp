#pragma once
/// The volume kernel of transient heat conduction on one Q1 cell.
#include "discretization/element_values.hpp"
#include "discretization/local_system.hpp"
#include "physics/kernel.hpp"
#include "physics/materials/conductivity_model.hpp"

#include <array>

namespace kiln
{
/// Transient heat conduction without sources:  rho c dT/dt - div(k(T) grad T) = 0.
///
///   R_i       = ∫ (rho c Tdot φ_i + k(T) ∇T·∇φ_i) dΩ
///   dR_i/dT_j = ∫ (rho c a φ_j φ_i + k ∇φ_j·∇φ_i + k'(T) φ_j ∇T·∇φ_i) dΩ,   a = dTdot/dT
///
/// With the lumped (row-sum) capacity the capacity term is the diagonal of the rows' sums,
/// M_ii = Σ_j ∫ φ_j φ_i dΩ = ∫ φ_i dΩ (the shape functions sum to one):
///   R_i      += rho c Tdot_i ∫ φ_i dΩ,   dR_i/dT_i += rho c a ∫ φ_i dΩ
/// instead of ∫ rho c Tdot φ_i dΩ; it keeps a thermal shock from undershooting (doc/heat.md).
///
/// T, Tdot and ∇T are interpolated from the nodal values at the 2x2x2 Gauss points;
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

  /// rho_c [J/(m^3 K)]; k(T) [W/(m K)].
  HeatConductionKernel(double rho_c, ConductivityModel conductivity, Capacity capacity);

  /// Adds the cell's residual [W] and Jacobian [W/K] to `local` (a node per cell node): T [K] and
  /// T_dot [K/s] at the nodes, dTdot_dT = a [1/s].
  void evaluate(const ElementValues &fe, const NodalValues &T, const NodalValues &T_dot,
                double dTdot_dT, LocalSystem &local) const;
  /// The same from a cell's state.
  void evaluate(const CellState &state, LocalSystem &local) const override;
  /// With a constant k: rho c a M + K.
  bool constant_jacobian() const override { return conductivity_.is_constant(); }
  /// k(T).
  const ConductivityModel &conductivity() const { return conductivity_; }
  /// rho c [J/(m^3 K)].
  double heat_capacity() const { return rho_c_; }
  /// Consistent or lumped.
  Capacity capacity() const { return capacity_; }

private:
  /// `fixed` = hex8_n_nodes: a HEX8 cell (the common case) with compile-time loop bounds; 0:
  /// any type.
  template <int fixed>
  void assemble(const ElementValues &fe, const NodalValues &T, const NodalValues &T_dot,
                double dTdot_dT, LocalSystem &local) const;

  double rho_c_;
  Capacity capacity_;
  ConductivityModel conductivity_;
};
} // namespace kiln
