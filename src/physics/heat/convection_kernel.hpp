#pragma once
/// Convective heat loss through a boundary face.
#include "discretization/face_values.hpp"
#include "discretization/local_system.hpp"
#include "physics/materials/time_function.hpp"

#include <array>

namespace kiln
{
/// Convection (Newton cooling): outward flux -k ∇T·n = h (T - T_amb) on the face.
///
///   R_i       = ∫ h (T - T_amb) φ_i dΓ
///   dR_i/dT_j = ∫ h φ_j φ_i dΓ
///
/// with T interpolated from the face's 4 nodes at the 2x2 Gauss points. Touches the
/// Field::T rows and columns of a 4-node local system (face-node order).
class ConvectionKernel final
{
public:
  /// h [W/(m^2 K)].
  explicit ConvectionKernel(double coefficient) : h_(coefficient) {}

  /// T [K] at the face nodes, T_ambient [K]; adds [W] and [W/K].
  void evaluate(const FaceValues &fv, Span<const double> T, const ValueAt &T_ambient,
                LocalSystem &local) const;

private:
  double h_;
};
} // namespace kiln
