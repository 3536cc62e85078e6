#pragma once
/// Shared by the contact-box tests (contact_box_mechanics_test.cpp, contact_box_contact_test.cpp):
/// the uniform open-gap and closed-gap states of ../shared/spec/contact-box.md built from the
/// formulas (with the spec's rotation, not kiln::rotation_matrix, so that the tests do not share
/// the code under test), the exact displacement field of a uniform state, a deck at uniform
/// temperature, and reading the HDF5 output back.
#include "unit/physics/heat_test_support.hpp"

#include <Teuchos_oblackholestream.hpp>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace kiln_test
{
using Matrix3 = std::array<std::array<double, 3>, 3>;

/// The folder of the example decks.
inline const std::string inputs = std::string(KILN_SOURCE_DIR) + "/inputs/";

/// std::cout on rank 0, a black hole elsewhere (measured figures are printed once).
inline std::ostream &rank0_out()
{
  static Teuchos::oblackholestream black_hole;
  return Teuchos::DefaultComm<int>::getComm()->getRank() == 0 ? std::cout : black_hole;
}

/// Voigt index of (i, j): xx, yy, zz, xy, xz, yz.
inline constexpr int voigt_index[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
inline constexpr const char *voigt_name[6] = {"xx", "yy", "zz", "xy", "xz", "yz"};

/// A = Rx(theta) Ry(phi) as the spec writes it.
inline Matrix3 spec_rotation(const double phi_degrees, const double theta_degrees)
{
  const double pi = std::acos(-1.0);
  const double cp = std::cos(phi_degrees * pi / 180), sp = std::sin(phi_degrees * pi / 180);
  const double ct = std::cos(theta_degrees * pi / 180), st = std::sin(theta_degrees * pi / 180);
  const Matrix3 Ry{{{cp, 0, sp}, {0, 1, 0}, {-sp, 0, cp}}};
  const Matrix3 Rx{{{1, 0, 0}, {0, ct, -st}, {0, st, ct}}};
  Matrix3 A{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        A[i][j] += Rx[i][k] * Ry[k][j];
  return A;
}

/// A t A^T in Voigt order, t diagonal (t_xx, t_yy, t_zz) in the box frame.
inline kiln::Voigt rotate_diagonal(const Matrix3 &A, const kiln::Point &t)
{
  kiln::Voigt v{};
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j)
    {
      double s = 0.0;
      for (int k = 0; k < 3; ++k)
        s += A[i][k] * t[k] * A[j][k];
      v[voigt_index[i][j]] = s;
    }
  return v;
}

/// A uniform state of the spec (open or closed gap, uniform temperature) in the mesh frame.
struct UniformState
{
  kiln::Voigt stress{};
  kiln::Voigt strain{};
  kiln::Voigt thermal_strain{};
  double gap_opening = 0.0;         ///< [m]
  double gap_normal_traction = 0.0; ///< -p [Pa], negative in compression
  // For the displacement field: the box-frame strains and the rotation.
  double eps_xx = 0.0;
  double eps_yy = 0.0;
  Matrix3 A{};
};

/// Open gap: sigma_xx = sigma_yy = 0, eps_zz = 0, sigma_zz = -E alpha dT, eps_xx = eps_yy =
/// (1 + nu) alpha dT, gap opening = -2 (half width) eps_xx, no traction; rotated by
/// A = Rx(theta) Ry(phi).
inline UniformState open_gap_state(const double E, const double nu, const double alpha,
                                   const double dT, const double half_width, const double phi,
                                   const double theta)
{
  UniformState s;
  s.A = spec_rotation(phi, theta);
  s.eps_xx = s.eps_yy = (1 + nu) * alpha * dT;
  s.stress = rotate_diagonal(s.A, {0.0, 0.0, -E * alpha * dT});
  s.strain = rotate_diagonal(s.A, {s.eps_xx, s.eps_yy, 0.0});
  s.thermal_strain = {alpha * dT, alpha * dT, alpha * dT, 0.0, 0.0, 0.0}; // isotropic
  s.gap_opening = -2 * half_width * s.eps_xx;
  return s;
}

/// Closed gap: eps_xx = eps_zz = 0, sigma_yy = 0, sigma_xx = sigma_zz = -E alpha dT / (1 - nu),
/// eps_yy = (3 lambda + 2 G) alpha dT / (lambda + 2 G) with lambda and G from E and nu, gap
/// normal traction sigma_xx, gap opening 0; rotated by A = Rx(theta) Ry(phi).
inline UniformState closed_gap_state(const double E, const double nu, const double alpha,
                                     const double dT, const double phi, const double theta)
{
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), G = E / (2 * (1 + nu));
  const double sigma = -E * alpha * dT / (1 - nu);
  UniformState s;
  s.A = spec_rotation(phi, theta);
  s.eps_xx = 0.0;
  s.eps_yy = (3 * lambda + 2 * G) * alpha * dT / (lambda + 2 * G);
  s.stress = rotate_diagonal(s.A, {sigma, 0.0, sigma});
  s.strain = rotate_diagonal(s.A, {0.0, s.eps_yy, 0.0});
  s.thermal_strain = {alpha * dT, alpha * dT, alpha * dT, 0.0, 0.0, 0.0};
  s.gap_normal_traction = sigma;
  s.gap_opening = 0.0;
  return s;
}

/// The spec's material (aluminium): Lame lambda and G, alpha, T_ref; E and nu from them.
inline constexpr double spec_lambda = 5.2e10, spec_G = 2.6e10; // [Pa]
inline constexpr double spec_alpha = 2.2e-5, spec_T_ref = 298; // [1/K], [K]
inline constexpr double spec_E = spec_G * (3 * spec_lambda + 2 * spec_G) / (spec_lambda + spec_G);
inline constexpr double spec_nu = spec_lambda / (2 * (spec_lambda + spec_G));

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
  bool check(const double actual, const double exact, const double rel, const double zero_tol)
  {
    const double error = std::abs(actual - exact);
    if (exact == 0.0)
    {
      absolute_at_zero = std::max(absolute_at_zero, error);
      return error <= zero_tol;
    }
    relative = std::max(relative, error / std::abs(exact));
    return error <= rel * std::abs(exact);
  }
  void reduce(const Teuchos::Comm<int> &comm)
  {
    double local[2] = {relative, absolute_at_zero}, global[2] = {0.0, 0.0};
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 2, local, global);
    relative = global[0];
    absolute_at_zero = global[1];
  }
};

inline std::string number(const double value)
{
  std::ostringstream s;
  s << std::setprecision(17) << value;
  return s.str();
}

/// A results path that no other test (or the same test at another np) uses: in the temp
/// folder, with rank 0's process id.
inline std::string temporary_base(const std::string &name, const Teuchos::Comm<int> &comm)
{
  int pid = static_cast<int>(getpid());
  Teuchos::broadcast(comm, 0, Teuchos::outArg(pid));
  return (std::filesystem::temp_directory_path() /
          ("kiln_contact_box_" + name + "_np" + std::to_string(comm.getSize()) + "_" +
           std::to_string(pid)))
      .string();
}

inline void remove_results(const std::string &base, const Teuchos::Comm<int> &comm)
{
  comm.barrier();
  if (comm.getRank() == 0)
  {
    std::remove((base + ".h5").c_str());
    std::remove((base + ".xmf").c_str());
  }
}

/// Output step `step` of an HDF5 results file (-1: the last): its time and one node or cell
/// field (rows in global id order, components interleaved). Serial read on the calling rank.
inline std::vector<double> read_step(const std::string &h5_path, const std::string &field,
                                     const int step, double &time)
{
  std::vector<double> values;
  const hid_t file = H5Fopen(h5_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(file, 0) << h5_path;
  if (file < 0)
    return values;
  H5G_info_t steps{};
  EXPECT_GE(H5Gget_info_by_name(file, "/steps", &steps, H5P_DEFAULT), 0) << h5_path;
  const int index = step < 0 ? static_cast<int>(steps.nlinks) - 1 : step;
  EXPECT_LT(index, static_cast<int>(steps.nlinks)) << h5_path << ": no output step " << index;
  char group[32];
  std::snprintf(group, sizeof group, "/steps/%06d", index);
  time = std::nan("");
  if (H5Lexists(file, group, H5P_DEFAULT) > 0)
  {
    const hid_t attribute = H5Aopen_by_name(file, group, "time", H5P_DEFAULT, H5P_DEFAULT);
    EXPECT_GE(H5Aread(attribute, H5T_NATIVE_DOUBLE, &time), 0);
    H5Aclose(attribute);
    const std::string path = std::string(group) + "/" + field;
    const hid_t dataset = H5Lexists(file, path.c_str(), H5P_DEFAULT) > 0
                              ? H5Dopen2(file, path.c_str(), H5P_DEFAULT)
                              : H5I_INVALID_HID;
    EXPECT_GE(dataset, 0) << h5_path << ": no " << path;
    if (dataset >= 0)
    {
      const hid_t space = H5Dget_space(dataset);
      values.resize(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
      H5Sclose(space);
      EXPECT_GE(H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
                0);
      H5Dclose(dataset);
    }
  }
  H5Fclose(file);
  return values;
}

/// The last output step of an HDF5 results file: see read_step.
inline std::vector<double> read_last_step(const std::string &h5_path, const std::string &field,
                                          double &time)
{
  return read_step(h5_path, field, -1, time);
}

/// The exact displacement of every node in a uniform state: in the box frame (x' = A^T
/// (x - centre)), u'_x = eps_xx (x' - x'_end) with x'_end the fixed end face of the node's
/// half (x' = -/+ half width), u'_y = eps_yy (y' - y'_3) with y'_3 the plane of side set 3
/// (the y roller), u'_z = 0 (rollers on both z faces); u = A u'.
inline std::vector<kiln::Point> exact_displacements(const kiln::Mesh &mesh, const UniformState &s)
{
  using kiln::Point;
  const int n_nodes = mesh.n_nodes();
  Point centre{};
  for (const Point &x : mesh.coordinates)
    for (int d = 0; d < 3; ++d)
      centre[d] += x[d] / n_nodes;
  const auto box_frame = [&](const int n)
  {
    Point xp{};
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        xp[j] += s.A[i][j] * (mesh.coordinates[n][i] - centre[i]);
    return xp;
  };
  // The half of each node: the sign of x' at the centroids of its cells (twin nodes on the
  // gap belong to the other half than the nodes they copy).
  std::vector<double> side(n_nodes, 0.0);
  for (int c = 0; c < mesh.n_cells(); ++c)
  {
    double x_centroid = 0.0;
    for (const int n : mesh.connectivity[c])
      x_centroid += box_frame(n)[0] / kiln::n_hex_nodes;
    for (const int n : mesh.connectivity[c])
      side[n] = x_centroid < 0 ? -1.0 : 1.0;
  }
  double half_width = 0.0;
  for (int n = 0; n < n_nodes; ++n)
    half_width = std::max(half_width, std::abs(box_frame(n)[0]));
  const kiln::SideSet *rollers_y = mesh.find_side_set(3);
  EXPECT_NE(rollers_y, nullptr);
  if (rollers_y == nullptr)
    return std::vector<Point>(n_nodes, Point{});
  const double y_fixed = box_frame(
      mesh.connectivity[rollers_y->cells[0]][kiln::hex_face_nodes[rollers_y->faces[0]][0]])[1];
  std::vector<Point> u(n_nodes);
  for (int n = 0; n < n_nodes; ++n)
  {
    const Point xp = box_frame(n);
    const Point up{s.eps_xx * (xp[0] - side[n] * half_width), s.eps_yy * (xp[1] - y_fixed), 0.0};
    for (int i = 0; i < 3; ++i)
      u[n][i] = s.A[i][0] * up[0] + s.A[i][1] * up[1] + s.A[i][2] * up[2];
  }
  return u;
}

/// The "Mesh" block of the generated contact box (4 cm, 4^3 cells, phi 45, theta -30).
inline const std::string generated_box_mesh = R"xml(
    <Parameter name="Type" type="string" value="Box"/>
    <Parameter name="Gap Side Set" type="int" value="10"/>
    <ParameterList name="Box">
      <Parameter name="Size" type="Array(double)" value="{0.04, 0.04, 0.04}"/>
      <Parameter name="Cells" type="Array(int)" value="{4, 4, 4}"/>
      <Parameter name="Phi" type="double" value="45"/>
      <Parameter name="Theta" type="double" value="-30"/>
    </ParameterList>)xml";

/// The "Mesh" block of the Cubit mesh ../shared/meshes/rotated-cube.exo (in cm).
inline const std::string cubit_mesh = R"xml(
    <Parameter name="Type" type="string" value="Exodus"/>
    <Parameter name="Gap Side Set" type="int" value="10"/>
    <ParameterList name="Exodus">
      <Parameter name="File" type="string" value=")xml" +
                                      std::string(KILN_SHARED_DIR) +
                                      R"xml(/meshes/rotated-cube.exo"/>
      <Parameter name="Coordinate Scale" type="double" value="0.01"/>
    </ParameterList>)xml";

/// The material of the spec (aluminium) as inputs/contact-box-*.xml give it (mechanics only).
inline const std::string spec_material = R"xml(
    <Parameter name="Lame Lambda" type="double" value="5.2e10"/>
    <Parameter name="Shear Modulus" type="double" value="2.6e10"/>
    <Parameter name="Thermal Expansion" type="double" value="2.2e-5"/>
    <Parameter name="Reference Temperature" type="double" value="298"/>)xml";

/// A Thermo-Elasticity deck at uniform temperature T (initial and on side sets 1, 2), rollers
/// on 1, 2, 3, 5, 6, one steady solve with tight tolerances, contact as by default.
inline Teuchos::ParameterList uniform_temperature_deck(const std::string &mesh_xml,
                                                       const std::string &material_xml,
                                                       const double T, const std::string &base)
{
  std::string xml = R"xml(
<ParameterList name="Kiln">
  <Parameter name="Physics" type="string" value="Thermo-Elasticity"/>
  <ParameterList name="Mesh">MESH</ParameterList>
  <ParameterList name="Material">MATERIAL</ParameterList>
  <ParameterList name="Thermal">
    <Parameter name="Initial Temperature" type="double" value="TEMPERATURE"/>
    <ParameterList name="Boundary Conditions">
      <ParameterList name="ends">
        <Parameter name="Type" type="string" value="Temperature"/>
        <Parameter name="Side Sets" type="Array(int)" value="{1, 2}"/>
        <ParameterList name="Temperature">
          <Parameter name="Type" type="string" value="Constant"/>
          <Parameter name="Value" type="double" value="TEMPERATURE"/>
        </ParameterList>
      </ParameterList>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Mechanics">
    <ParameterList name="Boundary Conditions">
      <ParameterList name="rollers">
        <Parameter name="Type" type="string" value="Normal Displacement"/>
        <Parameter name="Side Sets" type="Array(int)" value="{1, 2, 3, 5, 6}"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Time Stepping">
    <Parameter name="Method" type="string" value="Steady"/>
  </ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Relative Tolerance" type="double" value="1e-12"/>
    <ParameterList name="Linear Solver">
      <ParameterList name="Linear Solver Types">
        <ParameterList name="Belos">
          <ParameterList name="Solver Types">
            <ParameterList name="Pseudo Block GMRES">
              <Parameter name="Convergence Tolerance" type="double" value="1e-13"/>
            </ParameterList>
          </ParameterList>
        </ParameterList>
      </ParameterList>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="File Base" type="string" value="BASE"/>
    <Parameter name="Times" type="Array(double)" value="{0}"/>
  </ParameterList>
</ParameterList>)xml";
  replace(xml, "MESH", mesh_xml);
  replace(xml, "MATERIAL", material_xml);
  replace(xml, "TEMPERATURE", number(T));
  replace(xml, "BASE", base);
  return *Teuchos::getParametersFromXmlString(xml);
}
} // namespace kiln_test
