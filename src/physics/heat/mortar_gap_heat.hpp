#pragma once
/// Heat across the gap of a mortar pairing (issue 30, doc/contact.md "Heat on the same
/// segments"): on the mortar segments of each secondary face with the primary faces it overlaps
/// (MortarSegments), with the standard bases of both sides.
#include "contact/mortar_segments.hpp"
#include "discretization/local_system.hpp"
#include "physics/kernel.hpp"
#include "physics/materials/temperature_function.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace kiln
{
class ContactSurface;
class FaceSearch;

/// One integration cell: secondary face `secondary_face` of its ContactSurface against primary
/// face `primary_face`, their overlap's points (xi_s, xi_m, weight [m^2]) and the unit normal
/// n from the primary to the secondary side (minus the secondary face's outward normal at its
/// centre), all as found in the configuration the cells were built in.
struct MortarGapCell
{
  int secondary_face = -1;
  int primary_face = -1;
  CellType secondary_type = CellType::quad4;
  CellType primary_type = CellType::quad4;
  Point normal{0, 0, 0};
  std::vector<MortarPoint> points;
};

/// The gap heat flux from the secondary to the primary side at a point of the overlap,
///
///   q = h (T_s - T_m),  h = h_c + k_gas(T̄) / (g⁺ + g_jump) + σ ε (T_s² + T_m²)(T_s + T_m),
///
/// i.e. q = h_c ΔT + k_gas ΔT / (g⁺ + g_jump) + σ ε (T_s⁴ - T_m⁴): a constant conductance h_c,
/// gas conduction through the gap (k_gas a constant or a table in T̄ = (T_s + T_m)/2), and grey
/// radiation with view factor 1 across a thin gap, ε = 1 / (1/ε_s + 1/ε_m - 1) (0 if either is
/// 0). T_s = Σ N_i(xi_s) T_i and T_m = Σ N_k(xi_m) T_k from both faces' standard bases;
/// g = n . (x_s - x_m) (gap_opening) with x = X + u, g⁺ = max(g, 0): a closed gap (g <= 0)
/// conducts k_gas / g_jump. Per cell (the local nodes: the secondary face's ns nodes, then the
/// primary face's nm nodes),
///
///   R_i = + Σ_q w_q N_i(xi_s) q       (secondary node i)
///   R_k = - Σ_q w_q N_k(xi_m) q       (primary node k; Σ R = 0: conservative)
///   dR/dT: the T-T blocks of both faces' nodes through T_s, T_m;
///   dR/du: the T-u blocks through g (the gas term): dg/du_i = N_i(xi_s) n, dg/du_k = -N_k(xi_m) n
///          (0 where g <= 0, the generalized derivative of max).
///
/// Small sliding, as the mortar pairing's D and M: the points (xi_s, xi_m, w) and n are those
/// of the configuration the cells were built in (cells(), at a search), and g follows the
/// current positions at those reference coordinates; the Jacobian is exact for that (the
/// segments' own motion between searches is not differentiated).
///
/// With a "Gap Pressure Coefficient" h_p, the contact conductance h_p max(p, 0) of the split
/// gap's "Contact Dependent" model adds to h, p the normal compression of the two cells at the
/// cell's faces (ContactConductanceKernel::pressure: the mean of their volume-averaged
/// stresses; PairGapHeat computes it and passes it as a ContactTerm): dR/du and dR/dT of every
/// node of the two cells through p.
class MortarGapHeat
{
public:
  /// sigma [W/(m^2 K^4)] (CODATA 2018, exact).
  static constexpr double stefan_boltzmann = 5.670374419e-8;

  struct Parameters
  {
    double conductance = 0.0;                                                  ///< h_c [W/(m^2 K)]
    TemperatureFunction gas_conductivity = TemperatureFunction::constant(0.0); ///< [W/(m K)]
    double jump_distance = 0.0;                                                ///< g_jump [m]
    double primary_emissivity = 0.0;                                           ///< ε_m [-]
    double secondary_emissivity = 0.0;                                         ///< ε_s [-]
    double pressure_coefficient = 0.0; ///< h_p of the contact conductance [W/(m^2 K Pa)]
  };

  /// The contact conductance of a cell, h = h_p max(p, 0) at its pressure p (constant over
  /// the cell), and its derivatives per local node (the cell's local nodes, then any others).
  struct ContactTerm
  {
    double h = 0.0;            ///< [W/(m^2 K)]
    std::vector<Point> dh_du;  ///< [W/(m^3 K)]
    std::vector<double> dh_dT; ///< [W/(m^2 K^2)]
  };

  /// The value of q and its derivatives at one point.
  struct PointFlux
  {
    double q = 0.0;      ///< [W/m^2]
    double dq_dTs = 0.0; ///< [W/(m^2 K)]
    double dq_dTm = 0.0; ///< [W/(m^2 K)]
    double dq_dg = 0.0;  ///< [W/m^3]
  };

  /// The "Heat Transfer" sublist of a pair (every term 0 by default: no heat crosses).
  static Teuchos::ParameterList valid_parameters();
  /// `validated_params` has been through kiln::validated() against valid_parameters(); `where`
  /// names the sublist in messages ("in.xml: Kiln/Mechanics/Contact/Pairs/pin/Heat Transfer").
  /// Throws InputError for a gas conductivity without a jump distance, one emissivity > 0
  /// without the other, or a gas conductivity table or formula out of range.
  MortarGapHeat(const Teuchos::ParameterList &validated_params, const std::string &where);
  explicit MortarGapHeat(const Parameters &p);

  /// The cells of `secondary` (its faces) against the primary faces `search` (over `primary`)
  /// finds within `reach` [m] of each, in both surfaces' current positions; pairs that do not
  /// overlap give none. In secondary face order, then primary face order.
  static std::vector<MortarGapCell> cells(const ContactSurface &secondary,
                                          const ContactSurface &primary, const FaceSearch &search,
                                          double reach);
  /// The mesh nodes of a cell's local nodes: the secondary face's, then the primary face's.
  static std::vector<int> nodes(const ContactSurface &secondary, const ContactSurface &primary,
                                const MortarGapCell &cell);

  /// Adds the cell's terms to `local` (its n_nodes() = ns + nm) at the local nodes'
  /// temperatures T [K] and current positions x = X + u [m]: the residual in field slots.T [W],
  /// and with a Jacobian its T-T [W/K] and, if slots.u >= 0 and the gas term is on, its T-u
  /// [W/m] blocks (fields slots.u .. slots.u + 2).
  /// With a `contact` term, its h adds to q's conductance and its derivatives give the T-u and
  /// T-T entries of every local node it lists (the local system may then have more nodes than
  /// the two faces': the cells' other nodes, after them).
  void evaluate(const MortarGapCell &cell, const std::vector<double> &T,
                const std::vector<Point> &x, const FieldSlots &slots, LocalSystem &local,
                const ContactTerm *contact = nullptr) const;
  /// The heat flow across the cell from the secondary to the primary side, Σ_q w_q q [W].
  double heat_flow(const MortarGapCell &cell, const std::vector<double> &T,
                   const std::vector<Point> &x, const ContactTerm *contact = nullptr) const;

  /// q and its derivatives at T_s, T_m [K] and an opening g [m]; h_contact [W/(m^2 K)] the
  /// contact conductance (ContactTerm::h).
  PointFlux flux(double T_s, double T_m, double g, double h_contact = 0.0) const;
  /// h_p [W/(m^2 K Pa)].
  double pressure_coefficient() const { return p_.pressure_coefficient; }
  /// ε = 1 / (1/ε_s + 1/ε_m - 1), 0 if either is 0 [-].
  static double effective_emissivity(double secondary, double primary);
  /// Whether some term is on (else every cell adds 0).
  bool active() const;
  /// Whether q depends on the displacement (the gas term, the contact conductance: the graph
  /// needs the T-u links).
  bool depends_on_displacement() const { return gas_ || p_.pressure_coefficient > 0.0; }

private:
  Parameters p_;
  bool gas_ = false;
  double sigma_eps_ = 0.0; ///< σ ε [W/(m^2 K^4)]
};
} // namespace kiln
