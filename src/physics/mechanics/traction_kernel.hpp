#pragma once
/// A prescribed load on a boundary face of the solid: a traction vector or a pressure.
#include "discretization/face_values.hpp"
#include "discretization/local_system.hpp"
#include "mesh/mesh.hpp"
#include "physics/materials/time_function.hpp"

namespace kiln
{
/// Prescribed traction t on the face: σ n = t.
///
///   R_{i,d}           = −∫ t_d φ_i dΓ
///   dR_{i,d}/du_{j,e} = 0
///
/// A pressure p pushes on the face: t = −p n with n the outward unit normal at each Gauss
/// point, so R_{i,d} = ∫ p n_d φ_i dΓ. Small strain: the normal and the area are those of the
/// undeformed face, so the load does not follow the deformation and has no Jacobian.
/// Touches the rows of fields u_slot .. u_slot + 2 of a 4-node local system (face-node order).
class TractionKernel final
{
public:
  /// t [Pa] (a fixed direction); adds [N].
  static void evaluate(const FaceValues &fv, const Point &traction, int u_slot, LocalSystem &local);
  /// t [Pa] by components, each a constant or a function of space at the Gauss points.
  static void evaluate(const FaceValues &fv, const std::array<ValueAt, 3> &traction, int u_slot,
                       LocalSystem &local);
  /// p [Pa] (p > 0 compresses); adds [N].
  static void evaluate_pressure(const FaceValues &fv, const ValueAt &pressure, int u_slot,
                                LocalSystem &local);
};
} // namespace kiln
