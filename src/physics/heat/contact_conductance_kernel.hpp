#pragma once
/// Heat transfer across the split gap with a conductance that follows the contact state.
#include "discretization/element_values.hpp"
#include "discretization/face_values.hpp"
#include "discretization/local_system.hpp"
#include "physics/kernel.hpp"

#include <array>
#include <vector>

namespace kiln
{
/// The flux from side a to side b is h (T_a - T_b) as in GapConductanceKernel, with
///
///   h(g, p) = h0 L / (L + max(g, 0)) + h_p max(p, 0)
///
/// - g = n . (u_b - u_a), the gap opening at the quadrature point (n: the face's outward
///   normal on side a): an open gap conducts like a gas layer of conductivity h0 L in
///   series with a contact of h0, so h falls from h0 as the gap opens;
/// - p = -n . σ n, the normal compression of the two cells at the face (the mean of their
///   volume-averaged stresses, σ = λ tr ε I + 2G ε - β (T - T_ref) I, β = (3λ + 2G) α):
///   pressed together, h grows with the contact pressure. At an open face p is the free
///   surface's normal stress, zero up to the discretization error.
/// Both are continuous at closure (g = 0, p = 0: h = h0), and everything is linear in the
/// nodal u and T but for the max() kinks, so the Jacobian is exact (generalized
/// derivative 0 at the kinks): dR/dT of the jump and of p, dR/du of g and of p.
class ContactConductanceKernel final : public InterfaceKernel
{
public:
  struct Parameters
  {
    double h0 = 0.0;                          ///< h at closure [W/(m^2 K)]
    double length = 0.0;                      ///< L [m]
    double pressure_coefficient = 0.0;        ///< h_p [W/(m^2 K Pa)]
    double lambda = 0.0, shear_modulus = 0.0; ///< [Pa]
    double beta = 0.0;                        ///< (3 lambda + 2G) alpha [Pa/K]
    double reference_temperature = 0.0;       ///< [K]
  };
  explicit ContactConductanceKernel(const Parameters &p) : p_(p) {}

  /// fv: the side-a face; fe_a, fe_b: its two cells. Local nodes: 0..n-1 the face's n nodes
  /// on side a, n..2n-1 their twins; cell_a[i], cell_b[i]: the local node of each cell's node i.
  /// T [K] and u [m] per local node. Adds [W] and [W/K], [W/m] to `local` (fields T_slot,
  /// u_slot..u_slot+2).
  void evaluate(const FaceValues &fv, const ElementValues &fe_a, const ElementValues &fe_b,
                Span<const int> cell_a, Span<const int> cell_b, const std::vector<double> &T,
                const std::vector<Point> &u, int T_slot, int u_slot, LocalSystem &local) const;

  /// The side-a face nodes, their twins, then the other nodes of both cells (p depends on
  /// them).
  std::vector<int> nodes(const Mesh &mesh, const GapFace &face) const override;
  bool needs_cells() const override { return true; }
  /// The same from a gap face's state.
  void evaluate(const InterfaceState &state, LocalSystem &local) const override;

  /// h at one point [W/(m^2 K)] for an opening g [m] and a pressure p [Pa].
  double conductance(double g, double p) const;

private:
  Parameters p_;
};
} // namespace kiln
