#pragma once
/// A prescribed heat flux into the body through a boundary face.
#include "discretization/face_values.hpp"
#include "discretization/local_system.hpp"
#include "physics/materials/time_function.hpp"

namespace kiln
{
/// Prescribed flux q into the body (q > 0 heats it): -k ∇T·n = -q on the face.
///
///   R_i       = -∫ q φ_i dΓ
///   dR_i/dT_j = 0
///
/// Touches the Field::T rows of a 4-node local system (face-node order).
class HeatFluxKernel final
{
public:
  /// q [W/m^2] at each Gauss point (a constant or a function of space); adds [W].
  static void evaluate(const FaceValues &fv, const ValueAt &q, LocalSystem &local);
};
} // namespace kiln
