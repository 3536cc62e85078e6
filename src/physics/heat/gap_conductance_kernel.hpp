#pragma once
/// Heat transfer across the split gap, between a side-a face and its twin face.
#include "discretization/face_values.hpp"
#include "discretization/local_system.hpp"
#include "physics/kernel.hpp"

#include <array>

namespace kiln
{
/// Interface conductance h between the two sides of the gap: the flux from side a to
/// side b is h (T_a - T_b), integrated over the side-a face (the twin face coincides
/// with it). With φ_i the face's shape functions, local nodes 0-3 on side a and 4-7
/// their twins (same order), and [T] = T_a - T_b = Σ_j φ_j (T_a,j - T_b,j):
///
///   R_a,i = ∫ h [T] φ_i dΓ,     R_b,i = -∫ h [T] φ_i dΓ
///   dR_a,i/dT_a,j = -dR_a,i/dT_b,j = ∫ h φ_j φ_i dΓ,   and the opposite for R_b,i
///
/// Equal nodal temperatures on both sides give [T] = 0 exactly at every quadrature
/// point, hence exactly zero flux; the two residuals always sum to zero (no heat is
/// made or lost at the gap).
class GapConductanceKernel final : public InterfaceKernel
{
public:
  /// h [W/(m^2 K)].
  explicit GapConductanceKernel(double conductance) : h_(conductance) {}

  /// fv: the side-a face; T_a, T_b [K] at its nodes and at their twins. Adds [W] and
  /// [W/K] to an 8-node local system.
  void evaluate(const FaceValues &fv, Span<const double> T_a, Span<const double> T_b,
                LocalSystem &local) const;
  /// The same from a gap face's state (local nodes 0..n-1 on side a, n..2n-1 their twins).
  void evaluate(const InterfaceState &state, LocalSystem &local) const override;
  /// A constant conductance.
  bool constant_jacobian() const override { return true; }
  /// The heat across the gap depends on the temperatures alone.
  bool depends_on_displacement() const override { return false; }

private:
  double h_;
};
} // namespace kiln
