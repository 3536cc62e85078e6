#include "support/manufactured_solutions.hpp"

#include "elements/finite_element.hpp"
#include "support/parallel.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>

namespace kiln_test::mms
{
namespace
{
using kiln::CellType;
using kiln::Point;

// The harmonic h = sin(a x + 0.3) cos(b y + 0.2) exp(c (z - 1)), c^2 = a^2 + b^2 (a 3-4-5
// triangle: smooth on the unit cube, neither polynomial nor aligned with the cells).
constexpr double a = 1.2, b = 1.6, c = 2.0;
constexpr double T0 = 300.0;
constexpr double A = 10.0;     // temperature amplitude [K]
constexpr double scale = 1e-3; // displacement scale [m^2]
constexpr double k0 = 1.0;     // conductivity at T0 [W/(m K)]
constexpr double kb = 0.02;    // its slope beta [1/K]
// Thermo-elasticity: T = T0 + g z, E = E0 exp((T - T0) / g), alpha = alpha0 (1 + (T - T0) / g),
// p = sin(a2 x + 0.3) exp(a2 (y - 1)).
constexpr double g = 20.0, E0 = 2.0, nu = 0.25, alpha0 = 1e-3, a2 = 2.0;
// The uniform sigma_zz [Pa] and M = lambda + 2G at T0: with M(T) = M0 exp(z), u_z depends on E(T).
constexpr double sigma_zz = 0.05, M0 = E0 * (1 - nu) / ((1 + nu) * (1 - 2 * nu));

const std::string h_formula = "sin(1.2*x + 0.3)*cos(1.6*y + 0.2)*exp(2*(z - 1))";

/// h, its gradient and its Hessian.
void harmonic(const Point &x, double &h, Point &dh, std::array<Point, 3> &hess)
{
  const double sx = std::sin(a * x[0] + 0.3), cx = std::cos(a * x[0] + 0.3);
  const double sy = std::sin(b * x[1] + 0.2), cy = std::cos(b * x[1] + 0.2);
  const double ez = std::exp(c * (x[2] - 1));
  h = sx * cy * ez;
  dh = {a * cx * cy * ez, -b * sx * sy * ez, c * sx * cy * ez};
  hess[0] = {-a * a * h, -a * b * cx * sy * ez, a * c * cx * cy * ez};
  hess[1] = {hess[0][1], -b * b * h, -b * c * sx * sy * ez};
  hess[2] = {hess[0][2], hess[1][2], c * c * h};
}

std::string decimal(const double v)
{
  return number(v);
}

/// 5-point Gauss-Legendre on [-1, 1].
constexpr double gl_x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                            0.9061798459386640};
constexpr double gl_w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                            0.4786286704993665, 0.2369268850561891};

/// 5^3 points on the reference cell of `type` (collapsed coordinates for the simplex, wedge and
/// pyramid, the collapse's Jacobian in the weights).
const kiln::Quadrature &error_rule(const CellType type)
{
  static std::map<CellType, kiln::Quadrature> rules;
  const auto found = rules.find(type);
  if (found != rules.end())
    return found->second;
  kiln::Quadrature q;
  const auto unit = [](const int i) { return (1 + gl_x[i]) / 2; }; // on [0, 1], weight w / 2
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 5; ++k)
      {
        const double w = gl_w[i] * gl_w[j] * gl_w[k];
        const double u = unit(i), v = unit(j), t = unit(k);
        switch (kiln::ReferenceCell::of(type).n_vertices())
        {
        case 4: // unit simplex: x = u, y = v (1 - u), z = t (1 - u) (1 - v)
          q.points.push_back({u, v * (1 - u), t * (1 - u) * (1 - v)});
          q.weights.push_back(w / 8 * (1 - u) * (1 - u) * (1 - v));
          break;
        case 6: // unit triangle x [-1, 1]
          q.points.push_back({u, v * (1 - u), gl_x[k]});
          q.weights.push_back(w / 4 * (1 - u));
          break;
        case 5: // base [-1, 1]^2 at z = 0, apex (0, 0, 1): x = a (1 - z), y = b (1 - z)
          q.points.push_back({gl_x[i] * (1 - t), gl_x[j] * (1 - t), t});
          q.weights.push_back(w / 2 * (1 - t) * (1 - t));
          break;
        default: // [-1, 1]^3
          q.points.push_back({gl_x[i], gl_x[j], gl_x[k]});
          q.weights.push_back(w);
        }
      }
  return rules.emplace(type, std::move(q)).first->second;
}

/// The inverse transpose of the 3x3 matrix m (rows) and its determinant.
std::array<Point, 3> inverse_transpose(const std::array<Point, 3> &m, double &det)
{
  std::array<Point, 3> cof;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
    {
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      cof[i][j] = m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1];
    }
  det = m[0][0] * cof[0][0] + m[0][1] * cof[0][1] + m[0][2] * cof[0][2];
  for (auto &row : cof)
    for (double &v : row)
      v /= det;
  return cof;
}

/// A boundary condition of `type` (Temperature or Displacement) on `side_sets` whose value is
/// `formula`; `component` (x, y or z) for a Displacement.
std::string expression_bc(const std::string &type, const std::string &side_sets,
                          const std::string &formula, const std::string &component = "")
{
  std::string s = R"xml(
      <ParameterList name="TYPE SETS COMPONENT">
        <Parameter name="Type" type="string" value="TYPE"/>
        <Parameter name="Side Sets" type="Array(int)" value="{SETS}"/>COMPONENTS
        <ParameterList name="TYPE">
          <Parameter name="Type" type="string" value="Expression"/>
          <Parameter name="Expression" type="string" value="FORMULA"/>
        </ParameterList>
      </ParameterList>)xml";
  replace(s, "COMPONENTS",
          component.empty()
              ? ""
              : "\n        <Parameter name=\"Components\" type=\"Array(string)\" value=\"{" +
                    component + "}\"/>");
  replace(s, "COMPONENT", component);
  replace(s, "TYPE", type);
  replace(s, "SETS", side_sets);
  replace(s, "FORMULA", formula);
  return s;
}

std::string temperature_bc(const std::string &formula, const std::string &side_sets)
{
  return expression_bc("Temperature", side_sets, formula);
}

std::string displacement_bcs(const ExactField &u)
{
  std::string bcs;
  for (int d = 0; d < 3; ++d)
    bcs +=
        expression_bc("Displacement", "1, 2, 3, 4, 5, 6", u.formulas[d], std::string(1, "xyz"[d]));
  return bcs;
}

/// A material property given as a formula in T (Type Expression, checked on [280, 320]).
std::string property_expression(const std::string &name, const std::string &formula)
{
  std::string s = R"xml(
    <ParameterList name="NAME">
      <Parameter name="Type" type="string" value="Expression"/>
      <Parameter name="Expression" type="string" value="FORMULA"/>
      <Parameter name="Temperatures" type="Array(double)" value="{280, 300, 320}"/>
    </ParameterList>)xml";
  replace(s, "NAME", name);
  replace(s, "FORMULA", formula);
  return s;
}

bool is_thermal(const Problem p)
{
  return p == Problem::heat || p == Problem::heat_k_expression || p == Problem::heat_k_table;
}
} // namespace

Errors field_errors(const kiln::Simulation &sim, const std::vector<double> &nodal,
                    const ExactField &exact)
{
  const kiln::Mesh &mesh = sim.mesh();
  const int m = exact.n_components;
  double sum[2] = {0.0, 0.0};
  std::vector<double> N(kiln::max_cell_nodes);
  std::vector<Point> dN(kiln::max_cell_nodes);
  std::vector<double> value(m);
  std::vector<Point> gradient(m);
  for (const int cell : sim.dofs().owned_cells())
  {
    const kiln::FiniteElement &fe = kiln::FiniteElement::of(mesh.cell_type(cell));
    const auto nodes = mesh.cell_nodes(cell);
    const kiln::Quadrature &rule = error_rule(mesh.cell_type(cell));
    for (int q = 0; q < rule.size(); ++q)
    {
      fe.values(rule.points[q], N.data());
      fe.gradients(rule.points[q], dN.data());
      Point x{0, 0, 0};
      std::array<Point, 3> J{}; // J[d][k] = d x_d / d xi_k
      for (int i = 0; i < fe.n_shape(); ++i)
        for (int d = 0; d < 3; ++d)
        {
          x[d] += N[i] * mesh.coordinates[nodes[i]][d];
          for (int k = 0; k < 3; ++k)
            J[d][k] += mesh.coordinates[nodes[i]][d] * dN[i][k];
        }
      double det = 0.0;
      const std::array<Point, 3> Jit = inverse_transpose(J, det); // grad = J^-T grad_xi
      exact.evaluate(x, value.data(), gradient.data());
      for (int comp = 0; comp < m; ++comp)
      {
        double uh = 0.0;
        Point duh{0, 0, 0};
        for (int i = 0; i < fe.n_shape(); ++i)
        {
          const double ui = nodal[static_cast<std::size_t>(nodes[i]) * m + comp];
          uh += N[i] * ui;
          for (int d = 0; d < 3; ++d)
            for (int k = 0; k < 3; ++k)
              duh[d] += Jit[d][k] * dN[i][k] * ui;
        }
        const double w = rule.weights[q] * std::abs(det);
        sum[0] += (uh - value[comp]) * (uh - value[comp]) * w;
        for (int d = 0; d < 3; ++d)
          sum[1] += (duh[d] - gradient[comp][d]) * (duh[d] - gradient[comp][d]) * w;
      }
    }
  }
  double global[2] = {0.0, 0.0};
  Teuchos::reduceAll(*sim.dofs().owned_dof_map()->getComm(), Teuchos::REDUCE_SUM, 2, sum, global);
  return {std::sqrt(global[0]), std::sqrt(global[1])};
}

std::vector<double> all_node_displacements(const kiln::Simulation &sim, const Vector &x)
{
  std::vector<double> local(3 * static_cast<std::size_t>(sim.mesh().n_nodes()), 0.0),
      global(local.size(), 0.0);
  const auto u = const_cast<kiln::Simulation &>(sim).problem().node_displacements(x);
  const auto &owned = sim.dofs().owned_nodes();
  for (std::size_t i = 0; i < owned.size(); ++i)
    for (int d = 0; d < 3; ++d)
      local[3 * static_cast<std::size_t>(owned[i]) + d] = u[i][d];
  Teuchos::reduceAll(*x.getMap()->getComm(), Teuchos::REDUCE_SUM, static_cast<int>(local.size()),
                     local.data(), global.data());
  return global;
}

ExactField exact_solution(const Problem problem)
{
  ExactField f;
  switch (problem)
  {
  case Problem::heat:
    f.evaluate = [](const Point &x, double *T, Point *dT)
    {
      double h;
      std::array<Point, 3> hess;
      harmonic(x, h, dT[0], hess);
      T[0] = T0 + A * h;
      for (double &v : dT[0])
        v *= A;
    };
    f.formulas = {"300 + 10*" + h_formula};
    break;
  case Problem::heat_k_expression:
  case Problem::heat_k_table:
    // k0 (theta + kb theta^2 / 2) = k0 A h; k(T) grad T = k0 A grad h.
    f.evaluate = [](const Point &x, double *T, Point *dT)
    {
      double h;
      std::array<Point, 3> hess;
      harmonic(x, h, dT[0], hess);
      const double root = std::sqrt(1 + 2 * kb * A * h);
      T[0] = T0 + (root - 1) / kb;
      for (double &v : dT[0])
        v *= A / root;
    };
    f.formulas = {"300 + (sqrt(1 + " + decimal(2 * kb * A) + "*" + h_formula + ") - 1)/" +
                  decimal(kb)};
    break;
  case Problem::elasticity:
    f.n_components = 3;
    f.evaluate = [](const Point &x, double *u, Point *du)
    {
      double h;
      Point dh;
      std::array<Point, 3> hess;
      harmonic(x, h, dh, hess);
      for (int i = 0; i < 3; ++i)
      {
        u[i] = scale * dh[i];
        for (int j = 0; j < 3; ++j)
          du[i][j] = scale * hess[i][j];
      }
    };
    {
      const std::string ez = "exp(2*(z - 1))";
      f.formulas = {"0.001*1.2*cos(1.2*x + 0.3)*cos(1.6*y + 0.2)*" + ez,
                    "-0.001*1.6*sin(1.2*x + 0.3)*sin(1.6*y + 0.2)*" + ez,
                    "0.001*2*sin(1.2*x + 0.3)*cos(1.6*y + 0.2)*" + ez};
    }
    break;
  case Problem::thermoelastic_e_alpha_t:
    // sigma_zz = M(z) w' - beta(z) (T - T0), uniform: w' = sigma_zz exp(-z) / M0 + kappa alpha0
    // (1 + z) g z, kappa = beta / M = (1 + nu) / (1 - nu) whatever E: w = sigma_zz (1 -
    // exp(-z)) / M0 + kappa alpha0 g (z^2 / 2 + z^3 / 3).
    f.n_components = 3;
    f.evaluate = [](const Point &x, double *u, Point *du)
    {
      const double kappa = (1 + nu) / (1 - nu);
      const double sx = std::sin(a2 * x[0] + 0.3), cx = std::cos(a2 * x[0] + 0.3);
      const double ey = std::exp(a2 * (x[1] - 1)), z = x[2];
      u[0] = scale * a2 * cx * ey;
      u[1] = scale * a2 * sx * ey;
      u[2] = sigma_zz * (1 - std::exp(-z)) / M0 + kappa * alpha0 * g * (z * z / 2 + z * z * z / 3);
      du[0] = {-scale * a2 * a2 * sx * ey, scale * a2 * a2 * cx * ey, 0.0};
      du[1] = {scale * a2 * a2 * cx * ey, scale * a2 * a2 * sx * ey, 0.0};
      du[2] = {0.0, 0.0, sigma_zz * std::exp(-z) / M0 + kappa * alpha0 * g * (z + z * z)};
    };
    f.formulas = {"0.001*2*cos(2*x + 0.3)*exp(2*(y - 1))", "0.001*2*sin(2*x + 0.3)*exp(2*(y - 1))",
                  decimal(sigma_zz / M0) + "*(1 - exp(-z)) + " +
                      decimal((1 + nu) / (1 - nu) * alpha0 * g) + "*(z^2/2 + z^3/3)"};
    break;
  }
  return f;
}

std::string deck(const Problem problem, const std::string &cell_type, const int n)
{
  std::string s = R"xml(<ParameterList name="Kiln">
  <Parameter name="Physics" type="string" value="PHYSICS"/>
  <ParameterList name="Mesh">
    <Parameter name="Gap Side Set" type="int" value="0"/>
    <ParameterList name="Box">
      <Parameter name="Size" type="Array(double)" value="{1, 1, 1}"/>
      <Parameter name="Cells" type="Array(int)" value="{NCELLS, NCELLS, NCELLS}"/>
      <Parameter name="Translation" type="Array(double)" value="{0.5, 0.5, 0.5}"/>
      <Parameter name="Cell Type" type="string" value="CELL_TYPE"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Material">
    <Parameter name="Density" type="double" value="1"/>
    <Parameter name="Specific Heat" type="double" value="1"/>
    CONDUCTIVITY
    YOUNG
    <Parameter name="Poisson's Ratio" type="double" value="0.25"/>
    ALPHA
    <Parameter name="Reference Temperature" type="double" value="300"/>
  </ParameterList>
  THERMAL
  MECHANICS
  <ParameterList name="Time Stepping">
    <Parameter name="Method" type="string" value="Steady"/>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="File Base" type="string" value="BASE"/>
  </ParameterList>
</ParameterList>)xml";
  const ExactField exact = exact_solution(problem);
  std::string thermal = R"xml(<ParameterList name="Thermal">
    <Parameter name="Initial Temperature" type="double" value="300"/>
    <ParameterList name="Boundary Conditions">BCS
    </ParameterList>
  </ParameterList>)xml";
  std::string conductivity = R"xml(<Parameter name="Conductivity" type="double" value="1"/>)xml";
  if (problem == Problem::heat_k_expression)
    conductivity = property_expression("Conductivity", "1 + 0.02*(T - 300)");
  if (problem == Problem::heat_k_table) // the same line through (280, 0.6) and (320, 1.4)
    conductivity = R"xml(
    <ParameterList name="Conductivity">
      <Parameter name="Type" type="string" value="Table"/>
      <Parameter name="Temperatures" type="Array(double)" value="{280, 320}"/>
      <Parameter name="Values" type="Array(double)" value="{0.6, 1.4}"/>
    </ParameterList>)xml";
  std::string mechanics = R"xml(<ParameterList name="Mechanics">
    <ParameterList name="Boundary Conditions">BCS
    </ParameterList>
  </ParameterList>)xml";
  std::string young = R"xml(<Parameter name="Young's Modulus" type="double" value="2"/>)xml";
  std::string alpha = R"xml(<Parameter name="Thermal Expansion" type="double" value="0.001"/>)xml";
  if (is_thermal(problem))
  {
    replace(s, "PHYSICS", "Heat Conduction");
    replace(thermal, "BCS", temperature_bc(exact.formulas[0], "1, 2, 3, 4, 5, 6"));
    mechanics.clear();
  }
  else
    replace(mechanics, "BCS", displacement_bcs(exact));
  if (problem == Problem::elasticity)
  {
    replace(s, "PHYSICS", "Elasticity");
    thermal.clear();
  }
  else if (problem == Problem::thermoelastic_e_alpha_t)
  {
    replace(s, "PHYSICS", "Thermo-Elasticity");
    replace(thermal, "BCS", temperature_bc("300", "5") + temperature_bc(decimal(T0 + g), "6"));
    young = property_expression("Young's Modulus", "2*exp((T - 300)/20)");
    alpha = property_expression("Thermal Expansion", "0.001*(1 + (T - 300)/20)");
  }
  replace(s, "CONDUCTIVITY", conductivity);
  replace(s, "YOUNG", young);
  replace(s, "ALPHA", alpha);
  replace(s, "THERMAL", thermal);
  replace(s, "MECHANICS", mechanics);
  replace(s, "CELL_TYPE", cell_type);
  replace(s, "NCELLS", std::to_string(n));
  const auto base =
      std::filesystem::temp_directory_path() / ("kiln-mms-" + cell_type + "-" + std::to_string(n) +
                                                "-" + std::to_string(static_cast<int>(problem)));
  replace(s, "BASE", base.string());
  return s;
}

Errors run(const Problem problem, const std::string &cell_type, const int n)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto input = Teuchos::getParametersFromXmlString(deck(problem, cell_type, n));
  set_solver_tolerances(*input, 1e-13, 1e-12, 1e-12);
  auto sim = std::make_unique<kiln::Simulation>(*input, "mms.xml", comm);
  sim->run();
  const ExactField exact = exact_solution(problem);
  const std::vector<double> nodal = is_thermal(problem)
                                        ? all_node_values(*sim, sim->solution())
                                        : all_node_displacements(*sim, sim->solution());
  return field_errors(*sim, nodal, exact);
}

Errors orders(const Errors &coarse, const Errors &fine)
{
  return {std::log2(coarse.l2 / fine.l2), std::log2(coarse.h1 / fine.h1)};
}

std::vector<Errors> study(const Problem problem, const std::string &label,
                          const std::string &cell_type, const std::vector<int> &cells)
{
  std::vector<Errors> errors;
  for (const int n : cells)
  {
    errors.push_back(run(problem, cell_type, n));
    rank0_out() << label << " " << cell_type << " " << n << ": L2 " << errors.back().l2 << ", H1 "
                << errors.back().h1;
    if (errors.size() > 1)
    {
      const Errors o = orders(errors[errors.size() - 2], errors.back());
      rank0_out() << ", orders " << o.l2 << " " << o.h1;
    }
    rank0_out() << "\n";
  }
  return errors;
}

void check_orders(const Problem problem, const std::string &label, const Case &c)
{
  const std::vector<Errors> e = study(problem, label, c.cell_type, c.cells);
  const Errors o = orders(e[e.size() - 2], e.back());
  EXPECT_GE(o.l2, c.min_l2_order) << label << " " << c.cell_type;
  EXPECT_GE(o.h1, c.min_h1_order) << label << " " << c.cell_type;
}

const std::vector<Case> &linear_types()
{
  static const std::vector<Case> cases = {{"HEX8", {4, 8, 16}, 1.8, 0.9},
                                          {"TETRA4", {4, 8, 16}, 1.8, 0.9},
                                          {"WEDGE6", {4, 8, 16}, 1.8, 0.9},
                                          {"PYRAMID5", {4, 8, 16}, 1.8, 0.9},
                                          {"MIXED", {4, 8, 16}, 1.8, 0.9}};
  return cases;
}

const std::vector<Case> &quadratic_types()
{
  static const std::vector<Case> cases = {{"TETRA10", {2, 4, 8}, 2.8, 1.8},
                                          {"HEX20", {2, 4, 8}, 2.8, 1.8},
                                          {"HEX27", {2, 4, 8}, 2.8, 1.8}};
  return cases;
}

std::vector<Case> every_type()
{
  std::vector<Case> cases = linear_types();
  cases.insert(cases.end(), quadratic_types().begin(), quadratic_types().end());
  return cases;
}
std::vector<Case> hex_and_tet()
{
  return {linear_types()[0], linear_types()[1]};
}
} // namespace kiln_test::mms
