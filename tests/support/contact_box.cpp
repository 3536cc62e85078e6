#include "support/contact_box.hpp"

#include "support/simulation_runs.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace kiln_test
{
Matrix3 spec_rotation(const double phi_degrees, const double theta_degrees)
{
  const double pi = std::acos(-1.0);
  const double cp = std::cos(phi_degrees * pi / 180), sp = std::sin(phi_degrees * pi / 180);
  const double ct = std::cos(theta_degrees * pi / 180), st = std::sin(theta_degrees * pi / 180);
  const Matrix3 Ry{{{cp, 0, sp}, {0, 1, 0}, {-sp, 0, cp}}};
  const Matrix3 Rx{{{1, 0, 0}, {0, ct, -st}, {0, st, ct}}};
  return multiply(Rx, Ry);
}

kiln::Voigt rotate_diagonal(const Matrix3 &A, const kiln::Point &t)
{
  const Matrix3 full = rotated_diagonal(A, t);
  kiln::Voigt v{};
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j)
      v[voigt_index[i][j]] = full[i][j];
  return v;
}

UniformState open_gap_state(const double E, const double nu, const double alpha, const double dT,
                            const double half_width, const double phi, const double theta)
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

UniformState closed_gap_state(const double E, const double nu, const double alpha, const double dT,
                              const double phi, const double theta)
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
  s.contact_pressure = -sigma;
  s.gap_opening = 0.0;
  return s;
}

bool Deviation::check(const double actual, const double exact, const double rel,
                      const double zero_tol)
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

void Deviation::reduce(const Teuchos::Comm<int> &comm)
{
  double local[2] = {relative, absolute_at_zero}, global[2] = {0.0, 0.0};
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 2, local, global);
  relative = global[0];
  absolute_at_zero = global[1];
}

std::vector<kiln::Point> exact_displacements(const kiln::Mesh &mesh, const UniformState &s)
{
  using kiln::Point;
  const int n_nodes = mesh.n_nodes();
  // The box's centre: the middle of the nodes' bounding box (a rotated box's is symmetric
  // about its centre; the mean of the nodes is not where the halves are meshed apart).
  Point low = mesh.coordinates.front(), high = low;
  for (const Point &x : mesh.coordinates)
    for (int d = 0; d < 3; ++d)
    {
      low[d] = std::min(low[d], x[d]);
      high[d] = std::max(high[d], x[d]);
    }
  Point centre{};
  for (int d = 0; d < 3; ++d)
    centre[d] = 0.5 * (low[d] + high[d]);
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
    const auto nodes = mesh.cell_nodes(c);
    for (const int n : nodes)
      x_centroid += box_frame(n)[0] / static_cast<double>(nodes.size());
    for (const int n : mesh.cell_nodes(c))
      side[n] = x_centroid < 0 ? -1.0 : 1.0;
  }
  double half_width = 0.0;
  for (int n = 0; n < n_nodes; ++n)
    half_width = std::max(half_width, std::abs(box_frame(n)[0]));
  const kiln::SideSet *rollers_y = mesh.find_side_set(3);
  EXPECT_NE(rollers_y, nullptr);
  if (rollers_y == nullptr)
    return std::vector<Point>(n_nodes, Point{});
  const double y_fixed = box_frame(mesh.face_node(rollers_y->cells[0], rollers_y->faces[0], 0))[1];
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

const std::string generated_box_mesh = R"xml(
    <Parameter name="Type" type="string" value="Box"/>
    <Parameter name="Gap Side Set" type="int" value="10"/>
    <ParameterList name="Box">
      <Parameter name="Size" type="Array(double)" value="{0.04, 0.04, 0.04}"/>
      <Parameter name="Cells" type="Array(int)" value="{4, 4, 4}"/>
      <Parameter name="Phi" type="double" value="45"/>
      <Parameter name="Theta" type="double" value="-30"/>
    </ParameterList>)xml";

const std::string cubit_mesh = R"xml(
    <Parameter name="Type" type="string" value="Exodus"/>
    <Parameter name="Gap Side Set" type="int" value="10"/>
    <ParameterList name="Exodus">
      <Parameter name="File" type="string" value=")xml" +
                               std::string(KILN_SHARED_DIR) +
                               R"xml(/meshes/rotated-cube.exo"/>
      <Parameter name="Coordinate Scale" type="double" value="0.01"/>
    </ParameterList>)xml";

const std::string spec_material = R"xml(
    <Parameter name="Lame Lambda" type="double" value="5.2e10"/>
    <Parameter name="Shear Modulus" type="double" value="2.6e10"/>
    <Parameter name="Thermal Expansion" type="double" value="2.2e-5"/>
    <Parameter name="Reference Temperature" type="double" value="298"/>)xml";

Teuchos::ParameterList uniform_temperature_deck(const std::string &mesh_xml,
                                                const std::string &material_xml, const double T,
                                                const std::string &base)
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
            <ParameterList name="Block GMRES">
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
