#pragma once
/// Heat transfer across the split gap with a conductance that follows the contact state.
#include "discretization/element_values.hpp"
#include "discretization/face_values.hpp"
#include "discretization/local_system.hpp"
#include "physics/kernel.hpp"
#include "physics/kernel_of_block.hpp"
#include "physics/materials/constitutive_model.hpp"

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace kiln
{
class Material;
class MaterialMap;

/// The flux from side a to side b is h (T_a - T_b) as in GapConductanceKernel, with
///
///   h(g, p) = h0 L / (L + max(g, 0)) + h_p max(p, 0)
///
/// - g = n . (u_b - u_a), the gap opening at the quadrature point (n: the face's outward
///   normal on side a): an open gap conducts like a gas layer of conductivity h0 L in
///   series with a contact of h0, so h falls from h0 as the gap opens;
/// - p = -n . σ̄ n, the normal compression of the two cells at the face: the mean of the
///   two cells' volume averages σ̄_X = ∫_X σ dΩ / |X|, each cell's σ from its own block's
///   material through the constitutive-model layer (ConstitutiveModel::evaluate at each
///   quadrature point's ε = sym ∇u and T: E(T), ν(T), the secant α(T) as in the elasticity
///   kernel; doc/contact.md). A constant linear-elastic model (σ linear in ε and T) is
///   evaluated once per cell, at the cell's mean strain and temperature, which gives the same
///   average. Pressed together, h grows with the contact pressure. At an open face p is the
///   free surface's normal stress, zero up to the discretization error. Models with state
///   (viscoplastic) are not taken: ThermalPhysics refuses them beside a gap.
/// Both are continuous at closure (g = 0, p = 0: h = h0), and the Jacobian is exact but at
/// the max() kinks (generalized derivative 0 there): dR/dT of the jump and, through ∂σ/∂T, of
/// p; dR/du of g and, through the tangent ∂σ/∂ε, of p.
class ContactConductanceKernel final : public InterfaceKernel
{
public:
  struct Parameters
  {
    double h0 = 0.0;                   ///< h at closure [W/(m^2 K)]
    double length = 0.0;               ///< L [m]
    double pressure_coefficient = 0.0; ///< h_p [W/(m^2 K Pa)]
  };
  /// `models[i]` is material i's mechanical model (Material::mechanical_model(); one without
  /// state, n_state() == 0); `model_of_block` maps every block id of the mesh to one (it may
  /// be empty with one model).
  ContactConductanceKernel(const Parameters &p, const Mesh &mesh,
                           std::vector<std::shared_ptr<const ConstitutiveModel>> models,
                           std::map<int, int> model_of_block);
  /// With the mechanical model of each material of `materials` (or `material`'s alone if it
  /// is null). An InputError naming `parameter` (the input's path of the parameter that asked
  /// for this conductance, `asked_by` its value in words, e.g. "is \"Contact Dependent\"") and
  /// the material if one of the `cells` beside the gap has a model with state (viscoplastic):
  /// its stress needs the state at its points, which the gap's terms do not read; `remedy` ends
  /// the message (what to do instead).
  static ContactConductanceKernel for_materials(const Parameters &p, const Material &material,
                                                const Mesh &mesh, const MaterialMap *materials,
                                                const std::vector<int> &cells,
                                                const std::string &parameter,
                                                const std::string &asked_by,
                                                const std::string &remedy);

  /// fv: the side-a face; fe_a, fe_b: its two cells, `cells` their global indices (their
  /// blocks' models). Local nodes: 0..n-1 the face's n nodes on side a, n..2n-1 their twins;
  /// cell_a[i], cell_b[i]: the local node of each cell's node i. T [K] and u [m] per local node.
  /// Adds [W] and [W/K], [W/m] to `local` (fields T_slot, u_slot..u_slot+2).
  void evaluate(const FaceValues &fv, const ElementValues &fe_a, const ElementValues &fe_b,
                Span<const int> cell_a, Span<const int> cell_b, const std::array<int, 2> &cells,
                const std::vector<double> &T, const std::vector<Point> &u, int T_slot, int u_slot,
                LocalSystem &local) const;

  /// The side-a face nodes, their twins, then the other nodes of both cells (p depends on
  /// them).
  std::vector<int> nodes(const Mesh &mesh, const GapFace &face) const override;
  bool needs_cells() const override { return true; }
  /// The same from a gap face's state.
  void evaluate(const InterfaceState &state, LocalSystem &local) const override;

  /// h at one point [W/(m^2 K)] for an opening g [m] and a pressure p [Pa].
  double conductance(double g, double p) const;
  /// dh/dp at a pressure p [W/(m^2 K Pa)] (0 at p <= 0).
  double conductance_pressure_derivative(double p) const;

  /// p = (p_a + p_b)/2, p_X = -n.σ̄_X n, σ̄_X the volume average of the stress of cell X (global
  /// index cells[X], its block's material's model) [Pa]; `normal` a unit normal of the face
  /// (either sign). fe_a, fe_b: the two cells; cell_a[i], cell_b[i]: the local node of each
  /// cell's node i; T [K] and u [m] per local node. Adds dp/du [Pa/m] and dp/dT [Pa/K] per local
  /// node to dp_du and dp_dT (sized to the local nodes by the caller).
  double pressure(const Point &normal, const ElementValues &fe_a, const ElementValues &fe_b,
                  Span<const int> cell_a, Span<const int> cell_b, const std::array<int, 2> &cells,
                  const std::vector<double> &T, const std::vector<Point> &u,
                  std::vector<Point> &dp_du, std::vector<double> &dp_dT) const;

private:
  Parameters p_;
  std::vector<std::shared_ptr<const ConstitutiveModel>> models_;
  KernelOfBlock model_of_cell_;
};
} // namespace kiln
