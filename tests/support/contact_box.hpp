#pragma once
/// The contact box of ../shared/spec/contact-box.md for the verification tests: its uniform
/// open-gap and closed-gap states built from the formulas (with the spec's rotation, not
/// kiln::rotation_matrix, so that the tests do not share the code under test), the exact
/// displacement field of a uniform state, the spec's material, the Mesh blocks of the generated
/// box and of the Cubit mesh, and a deck at uniform temperature.
#include "mesh/hex_geometry.hpp"
#include "mesh/mesh.hpp"
#include "physics/mechanics/elasticity_kernel.hpp"
#include "support/tensors.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace kiln_test
{
/// A = Rx(theta) Ry(phi) as the spec writes it.
Matrix3 spec_rotation(double phi_degrees, double theta_degrees);

/// A t A^T in Voigt order, t diagonal (t_xx, t_yy, t_zz) in the box frame.
kiln::Voigt rotate_diagonal(const Matrix3 &A, const kiln::Point &t);

/// A uniform state of the spec (open or closed gap, uniform temperature) in the mesh frame.
struct UniformState
{
  kiln::Voigt stress{};
  kiln::Voigt strain{};
  kiln::Voigt thermal_strain{};
  double gap_opening = 0.0;      ///< [m]
  double contact_pressure = 0.0; ///< p [Pa], positive in compression (minus the normal traction)
  // For the displacement field: the box-frame strains and the rotation.
  double eps_xx = 0.0;
  double eps_yy = 0.0;
  Matrix3 A{};
};

/// Open gap: sigma_xx = sigma_yy = 0, eps_zz = 0, sigma_zz = -E alpha dT, eps_xx = eps_yy =
/// (1 + nu) alpha dT, gap opening = -2 (half width) eps_xx, no traction; rotated by
/// A = Rx(theta) Ry(phi).
UniformState open_gap_state(double E, double nu, double alpha, double dT, double half_width,
                            double phi, double theta);

/// Closed gap: eps_xx = eps_zz = 0, sigma_yy = 0, sigma_xx = sigma_zz = -E alpha dT / (1 - nu),
/// eps_yy = (3 lambda + 2 G) alpha dT / (lambda + 2 G) with lambda and G from E and nu, gap
/// normal traction sigma_xx, gap opening 0; rotated by A = Rx(theta) Ry(phi).
UniformState closed_gap_state(double E, double nu, double alpha, double dT, double phi,
                              double theta);

/// The spec's material (aluminium): Lame lambda and G, alpha, T_ref; E and nu from them.
inline constexpr double spec_lambda = 5.2e10, spec_G = 2.6e10; // [Pa]
inline constexpr double spec_alpha = 2.2e-5, spec_T_ref = 298; // [1/K], [K]
inline constexpr double spec_E = spec_G * (3 * spec_lambda + 2 * spec_G) / (spec_lambda + spec_G);
inline constexpr double spec_nu = spec_lambda / (2 * (spec_lambda + spec_G));

/// The closed-gap state of the spec's material at temperature T, phi 45, theta -30.
inline UniformState spec_closed_gap_state(const double T)
{
  return closed_gap_state(spec_E, spec_nu, spec_alpha, T - spec_T_ref, 45.0, -30.0);
}

/// The open-gap state of the spec's material at temperature T (half width 2 cm).
inline UniformState spec_open_gap_state(const double T)
{
  return open_gap_state(spec_E, spec_nu, spec_alpha, T - spec_T_ref, 0.02, 45.0, -30.0);
}

/// A reference state and the relative tolerance to hold the results to; where the reference
/// value is 0, absolute tolerances of 1e-3 Pa (stress) and 1e-13 (strains) apply.
struct Reference
{
  std::string name;
  UniformState state;
  double tolerance;
};
inline constexpr double zero_stress_tolerance = 1e-3; // [Pa]
inline constexpr double zero_strain_tolerance = 1e-13;

/// The largest relative (or, at zero reference values, absolute) difference seen.
struct Deviation
{
  double relative = 0.0;
  double absolute_at_zero = 0.0;
  /// Records `actual` against `exact`: true if |actual - exact| <= rel |exact|, or <= zero_tol
  /// where exact is 0.
  bool check(double actual, double exact, double rel, double zero_tol);
  /// The largest of each over the ranks of comm (collective).
  void reduce(const Teuchos::Comm<int> &comm);
};

/// The exact displacement of every node in a uniform state: in the box frame (x' = A^T
/// (x - centre)), u'_x = eps_xx (x' - x'_end) with x'_end the fixed end face of the node's
/// half (x' = -/+ half width), u'_y = eps_yy (y' - y'_3) with y'_3 the plane of side set 3
/// (the y roller), u'_z = 0 (rollers on both z faces); u = A u'.
std::vector<kiln::Point> exact_displacements(const kiln::Mesh &mesh, const UniformState &s);

/// The "Mesh" block of the generated contact box (4 cm, 4^3 cells, phi 45, theta -30).
extern const std::string generated_box_mesh;
/// The "Mesh" block of the Cubit mesh ../shared/meshes/rotated-cube.exo (in cm).
extern const std::string cubit_mesh;
/// The material of the spec (aluminium) as inputs/contact-box-*.xml give it (mechanics only).
extern const std::string spec_material;

/// A Thermo-Elasticity deck at uniform temperature T (initial and on side sets 1, 2), rollers
/// on 1, 2, 3, 5, 6, one steady solve with tight tolerances, contact as by default; results
/// to `base`.
Teuchos::ParameterList uniform_temperature_deck(const std::string &mesh_xml,
                                                const std::string &material_xml, double T,
                                                const std::string &base);
} // namespace kiln_test
