// Tests MortarGapHeat (src/physics/heat/mortar_gap_heat): the gap heat flux of a mortar pairing
// (h_c, gas k_gas(T)/(g + g_jump), radiation sigma eps (T_s^4 - T_m^4)) on the mortar segments
// of two separately meshed bodies (tests/support/two_body_mesh). Checks: the point flux by hand;
// finite-difference Jacobians (T-T and T-u) of every cell, open, closed and with secondary faces
// partly covered; conservation; the total heat of two flat faces at uniform temperatures = area
// * q; the heat flow across two faceted cylindrical shells against r theta L q, converging as
// the facets are refined; the parameters (defaults, tables, input errors).
#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "contact/face_search.hpp"
#include "mesh/contact_surface.hpp"
#include "physics/heat/mortar_gap_heat.hpp"
#include "support/jacobian_check.hpp"
#include "support/parameter_lists.hpp"
#include "support/two_body_mesh.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace
{
using kiln::ContactSurface;
using kiln::FaceSearch;
using kiln::FieldSlots;
using kiln::LocalSystem;
using kiln::MortarGapCell;
using kiln::MortarGapHeat;
using kiln::Point;
using testing::HasSubstr;

constexpr double sigma = MortarGapHeat::stefan_boltzmann;

/// Every term on: h_c = 10, k_gas a table in T, g_jump = 1e-3 m, eps_s = 0.6, eps_m = 0.8.
MortarGapHeat all_terms()
{
  Teuchos::ParameterList user;
  user.set("Conductance", 10.0);
  Teuchos::ParameterList &gas = user.sublist("Gas Conductivity");
  gas.set("Type", "Table");
  gas.set("Temperatures", kiln_test::values({300.0, 500.0, 700.0}));
  gas.set("Values", kiln_test::values({0.2, 0.4, 0.5}));
  user.set("Jump Distance", 1e-3);
  user.set("Primary Emissivity", 0.8);
  user.set("Secondary Emissivity", 0.6);
  const auto p =
      kiln::validated(user, MortarGapHeat::valid_parameters(), "in.xml", "Kiln/Heat Transfer");
  return MortarGapHeat(p, "in.xml: Kiln/Heat Transfer");
}

/// The two surfaces of a two-body mesh (primary: side set 1, secondary: side set 2) and the
/// cells of their overlap.
struct Pairing
{
  Pairing(const kiln::Mesh &mesh, const double reach)
      : primary(mesh, 1, "test: primary"), secondary(mesh, 2, "test: secondary"), search(primary),
        cells(MortarGapHeat::cells(secondary, primary, search, reach))
  {
  }
  ContactSurface primary;
  ContactSurface secondary;
  FaceSearch search;
  std::vector<MortarGapCell> cells;
};

/// Local state of a cell in LocalSystem order with fields (T, u_x, u_y, u_z): T and u per
/// local node.
constexpr int n_fields = 4;
const FieldSlots slots{0, 1};

/// The residual of `cell` at `state` (T, u per local node), positions X + u.
std::vector<double> cell_residual(const MortarGapHeat &heat, const MortarGapCell &cell,
                                  const std::vector<Point> &X, const std::vector<double> &state,
                                  const bool with_jacobian, LocalSystem *out = nullptr)
{
  const int n = static_cast<int>(X.size());
  std::vector<double> T(n);
  std::vector<Point> x(n);
  for (int a = 0; a < n; ++a)
  {
    T[a] = state[a * n_fields];
    for (int d = 0; d < 3; ++d)
      x[a][d] = X[a][d] + state[a * n_fields + 1 + d];
  }
  LocalSystem local(n, n_fields, with_jacobian);
  heat.evaluate(cell, T, x, slots, local);
  if (out != nullptr)
    *out = local;
  return local.residual_values();
}

/// The reference positions of a cell's local nodes.
std::vector<Point> cell_positions(const kiln::Mesh &mesh, const Pairing &pairing,
                                  const MortarGapCell &cell)
{
  std::vector<Point> X;
  for (const int node : MortarGapHeat::nodes(pairing.secondary, pairing.primary, cell))
    X.push_back(mesh.coordinates[node]);
  return X;
}

/// The nodes of the cells of block `block`.
std::set<int> block_nodes(const kiln::Mesh &mesh, const int block)
{
  std::set<int> nodes;
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (mesh.block_id[c] == block)
      for (const int n : mesh.cell_nodes(c))
        nodes.insert(n);
  return nodes;
}

/// Moves body 2 (block 2) by `shift`.
void move_body_2(kiln::Mesh &mesh, const Point &shift)
{
  for (const int n : block_nodes(mesh, 2))
    for (int d = 0; d < 3; ++d)
      mesh.coordinates[n][d] += shift[d];
}

/// Compares the Jacobian of every cell with central differences at a state with the secondary
/// nodes near 450 K, the primary ones near 350 K and small displacements; returns the largest
/// T-u entry seen (to tell open from closed). Also checks that each cell's residual sums to 0.
/// Compares the Jacobian of `cell` (local nodes at X, the first n_secondary on the secondary
/// face) with central differences at a state with the secondary nodes near 450 K, the primary
/// ones near 350 K and small displacements (`seed` varies them); checks that its temperature
/// rows sum to 0. Returns the largest T-u entry (to tell open from closed).
double check_cell(const MortarGapHeat &heat, const MortarGapCell &cell, const std::vector<Point> &X,
                  const int n_secondary, int seed)
{
  const int n = static_cast<int>(X.size());
  std::vector<double> state(n * n_fields);
  for (int a = 0; a < n; ++a)
  {
    ++seed;
    state[a * n_fields] = (a < n_secondary ? 450.0 : 350.0) + 7.0 * std::sin(1.3 * seed);
    for (int d = 0; d < 3; ++d)
      state[a * n_fields + 1 + d] = 1e-4 * std::cos(0.7 * seed + d);
  }
  LocalSystem local(n, n_fields);
  const std::vector<double> R = cell_residual(heat, cell, X, state, true, &local);
  double sum = 0.0, scale = 0.0;
  for (int a = 0; a < n; ++a)
  {
    sum += R[a * n_fields];
    scale += std::abs(R[a * n_fields]);
  }
  const std::string name =
      "cell " + std::to_string(cell.secondary_face) + "/" + std::to_string(cell.primary_face);
  EXPECT_GT(scale, 0.0) << name;
  EXPECT_LE(std::abs(sum), 1e-13 * scale) << name;

  const auto residual = [&](const std::vector<double> &s)
  { return cell_residual(heat, cell, X, s, false); };
  const auto eps = [](const int column) { return column % n_fields == 0 ? 1e-3 : 1e-7; };
  const kiln_test::Dense fd = kiln_test::finite_difference_jacobian(residual, state, eps);
  const kiln_test::Dense J = kiln_test::local_jacobian(local);
  EXPECT_LE(kiln_test::max_difference(J, fd), 1e-7 * kiln_test::max_abs(J)) << name;
  double max_Tu = 0.0;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n * n_fields; ++c)
      if (c % n_fields != 0)
        max_Tu = std::max(max_Tu, std::abs(J[r * n_fields][c]));
  return max_Tu;
}

/// check_cell on every cell of a pairing; the largest T-u entry.
double check_cells(const kiln::Mesh &mesh, const Pairing &pairing, const MortarGapHeat &heat)
{
  EXPECT_FALSE(pairing.cells.empty());
  double max_Tu = 0.0;
  int seed = 0;
  for (const MortarGapCell &cell : pairing.cells)
  {
    const int n_secondary =
        static_cast<int>(pairing.secondary.face_nodes(cell.secondary_face).size());
    max_Tu = std::max(
        max_Tu, check_cell(heat, cell, cell_positions(mesh, pairing, cell), n_secondary, seed));
    seed += 8;
  }
  return max_Tu;
}

TEST(MortarGapHeat, PointFluxByHand)
{
  const MortarGapHeat heat = all_terms();
  const double T_s = 420.0, T_m = 380.0, g = 4e-3;
  // T_mean = 400 K: k = 0.3, k' = 0.001 W/(m K^2); eps = 1/(1/0.6 + 1/0.8 - 1).
  const double eps = 1.0 / (1.0 / 0.6 + 1.0 / 0.8 - 1.0);
  EXPECT_NEAR(MortarGapHeat::effective_emissivity(0.6, 0.8), eps, 1e-15);
  const double width = g + 1e-3;
  const double q =
      10.0 * 40.0 + 0.3 / width * 40.0 + sigma * eps * (std::pow(T_s, 4) - std::pow(T_m, 4));
  const MortarGapHeat::PointFlux f = heat.flux(T_s, T_m, g);
  EXPECT_NEAR(f.q, q, 1e-12 * q);
  // The radiation as h: sigma eps (T_s^2 + T_m^2)(T_s + T_m) (T_s - T_m).
  const double h = 10.0 + 0.3 / width + sigma * eps * (T_s * T_s + T_m * T_m) * (T_s + T_m);
  EXPECT_NEAR(f.q, h * (T_s - T_m), 1e-12 * q);
  EXPECT_NEAR(f.dq_dTs,
              10.0 + 0.3 / width + 0.5 * 0.001 / width * 40.0 + 4 * sigma * eps * std::pow(T_s, 3),
              1e-12 * q);
  EXPECT_NEAR(f.dq_dTm,
              -10.0 - 0.3 / width + 0.5 * 0.001 / width * 40.0 - 4 * sigma * eps * std::pow(T_m, 3),
              1e-12 * q);
  EXPECT_NEAR(f.dq_dg, -0.3 / (width * width) * 40.0, 1e-12 * q);
  // Closed: the gas conducts k/g_jump and no longer depends on g.
  const MortarGapHeat::PointFlux closed = heat.flux(T_s, T_m, -2e-3);
  EXPECT_NEAR(closed.q - f.q, 0.3 * 40.0 * (1.0 / 1e-3 - 1.0 / width), 1e-12 * q);
  EXPECT_EQ(closed.dq_dg, 0.0);
  EXPECT_EQ(MortarGapHeat::effective_emissivity(0.0, 0.8), 0.0);
  EXPECT_EQ(MortarGapHeat::effective_emissivity(1.0, 1.0), 1.0);
}

TEST(MortarGapHeat, JacobianOpenGap)
{
  const kiln::Mesh mesh = kiln_test::two_flat_bodies({3, 3}, {4, 2}, 0.01);
  const Pairing pairing(mesh, 0.05);
  const double max_Tu = check_cells(mesh, pairing, all_terms());
  EXPECT_GT(max_Tu, 1.0); // the gas term depends on the gap
}

TEST(MortarGapHeat, JacobianClosedGap)
{
  // The bodies overlap by 5 mm: g < 0, the gas conducts k/g_jump whatever u.
  const kiln::Mesh mesh = kiln_test::two_flat_bodies({3, 3}, {4, 2}, -0.005);
  const Pairing pairing(mesh, 0.05);
  EXPECT_EQ(check_cells(mesh, pairing, all_terms()), 0.0);
}

TEST(MortarGapHeat, JacobianPartlyCovered)
{
  // Body 2 moved off by (0.3, 0.2): the secondary faces along two edges are partly covered,
  // some not at all; rotated out of the coordinate planes.
  kiln::Mesh mesh = kiln_test::two_flat_bodies({3, 3}, {4, 2}, 0.01);
  move_body_2(mesh, {0.3, 0.2, 0.0});
  kiln_test::rotate(mesh, 20.0, -35.0);
  const Pairing pairing(mesh, 0.05);
  const ContactSurface &secondary = pairing.secondary;
  int partly = 0;
  for (const MortarGapCell &cell : pairing.cells)
  {
    double area = 0.0;
    for (const kiln::MortarPoint &p : cell.points)
      area += p.weight;
    const Point &a = secondary.face_area_vector(cell.secondary_face);
    partly += area < 0.99 * std::sqrt(kiln::dot(a, a));
  }
  EXPECT_GT(partly, 0);
  EXPECT_GT(check_cells(mesh, pairing, all_terms()), 1.0);
}

TEST(MortarGapHeat, JacobianTriangleAgainstQuadrilateral)
{
  // A TRI3 secondary face (facing -z, 1 cm up, tilted a little) over a QUAD4 primary face
  // (facing +z) that covers part of it, and the other way round.
  const std::vector<Point> tri{{0.1, 0.1, 0.01}, {0.9, 0.3, 0.012}, {0.4, 1.2, 0.011}};
  const std::vector<Point> tri_down{tri[0], tri[2], tri[1]};
  const std::vector<Point> quad{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<Point> quad_down{
      {0.2, -0.1, 0.01}, {0.2, 0.8, 0.01}, {1.1, 0.8, 0.01}, {1.1, -0.1, 0.01}};
  const std::vector<Point> tri_up{{0.0, 0.0, 0.0}, {0.9, 0.1, 0.0}, {0.3, 0.9, 0.0}};
  const MortarGapHeat heat = all_terms();
  const auto check = [&](const kiln::CellType type_s, const std::vector<Point> &x_s,
                         const kiln::CellType type_m, const std::vector<Point> &x_m)
  {
    const kiln::MortarSegments segments({type_s, x_s}, {type_m, x_m});
    ASSERT_FALSE(segments.empty());
    const Point &n = segments.normal();
    const MortarGapCell cell{0, 0, type_s, type_m, Point{-n[0], -n[1], -n[2]}, segments.points()};
    std::vector<Point> X = x_s;
    X.insert(X.end(), x_m.begin(), x_m.end());
    EXPECT_GT(check_cell(heat, cell, X, static_cast<int>(x_s.size()), 3), 1.0);
  };
  check(kiln::CellType::tri3, tri_down, kiln::CellType::quad4, quad);
  check(kiln::CellType::quad4, quad_down, kiln::CellType::tri3, tri_up);
}

/// The heat from the secondary to the primary side summed over the cells, and the sum of the
/// secondary and of all the temperature rows, at T_s and T_m uniform.
struct Totals
{
  double heat_flow = 0.0;
  double secondary_rows = 0.0;
  double all_rows = 0.0;
};

Totals uniform_totals(const kiln::Mesh &mesh, const Pairing &pairing, const MortarGapHeat &heat,
                      const double T_s, const double T_m)
{
  Totals t;
  for (const MortarGapCell &cell : pairing.cells)
  {
    const std::vector<Point> x = cell_positions(mesh, pairing, cell);
    const int n = static_cast<int>(x.size());
    const int n_secondary =
        static_cast<int>(pairing.secondary.face_nodes(cell.secondary_face).size());
    std::vector<double> T(n);
    for (int a = 0; a < n; ++a)
      T[a] = a < n_secondary ? T_s : T_m;
    LocalSystem local(n, 1, false);
    heat.evaluate(cell, T, x, FieldSlots{0, -1}, local);
    for (int a = 0; a < n; ++a)
    {
      t.all_rows += local.residual(0, a);
      if (a < n_secondary)
        t.secondary_rows += local.residual(0, a);
    }
    t.heat_flow += heat.heat_flow(cell, T, x);
  }
  return t;
}

TEST(MortarGapHeat, FlatFacesAtUniformTemperatures)
{
  // Unit squares 4x4 (primary) and 5x3 (secondary) 2 mm apart: the total heat is 1 m^2 * q.
  const double gap = 2e-3;
  const kiln::Mesh mesh = kiln_test::two_flat_bodies({4, 4}, {5, 3}, gap);
  const Pairing pairing(mesh, 0.01);
  const MortarGapHeat heat = all_terms();
  const double T_s = 600.0, T_m = 330.0;
  const double q = heat.flux(T_s, T_m, gap).q;
  const Totals t = uniform_totals(mesh, pairing, heat, T_s, T_m);
  EXPECT_NEAR(t.heat_flow, q, 1e-13 * q);
  EXPECT_NEAR(t.secondary_rows, q, 1e-13 * q);
  EXPECT_NEAR(t.all_rows, 0.0, 1e-13 * q);
  // Half of the secondary moved off the primary: half the heat.
  kiln::Mesh off = mesh;
  move_body_2(off, {0.5, 0.0, 0.0});
  const Pairing half(off, 0.01);
  EXPECT_NEAR(uniform_totals(off, half, heat, T_s, T_m).heat_flow, 0.5 * q, 1e-13 * q);
}

/// Stretches body 1 (block 1) of two_cylinder_shells from the angles [0, 1] to [-0.1, 1.1]
/// rad, so that it covers the whole of body 2's inner face (else a strip of width about
/// gap dtheta / 2 at each end of the secondary surface is not covered: a first-order error).
void widen_body_1(kiln::Mesh &mesh)
{
  for (const int n : block_nodes(mesh, 1))
  {
    Point &x = mesh.coordinates[n];
    const double r = std::hypot(x[0], x[1]), angle = -0.1 + 1.2 * std::atan2(x[1], x[0]);
    x[0] = r * std::cos(angle);
    x[1] = r * std::sin(angle);
  }
}

TEST(MortarGapHeat, CylindricalShellsConvergeToTheArcArea)
{
  // Shells over 1 rad and 1 m of height, the primary's outer face at r = 2, the secondary's
  // inner face at r = 2 + gap, non-matching facets: the heat across is r theta L q(g) on the
  // secondary surface up to the facets' error, O(dtheta^2): the faceted area (1 - dtheta^2/24)
  // and the faceted gap, which varies across a facet by about r dtheta^2 / 8. Measured
  // (2026-11-29): relative errors 1.16e-2, 3.18e-3, 7.89e-4 for n = 8, 16, 32.
  const double gap = 0.05, T_s = 500.0, T_m = 400.0;
  const MortarGapHeat heat = all_terms();
  const double exact = (2.0 + gap) * 1.0 * 1.0 * heat.flux(T_s, T_m, gap).q;
  std::vector<double> errors;
  for (const int n : {8, 16, 32})
  {
    kiln::Mesh mesh = kiln_test::two_cylinder_shells({n, 2}, {n + n / 2, 3}, gap);
    widen_body_1(mesh);
    const Pairing pairing(mesh, 2 * gap);
    const Totals t = uniform_totals(mesh, pairing, heat, T_s, T_m);
    EXPECT_NEAR(t.all_rows, 0.0, 1e-12 * exact);
    errors.push_back(std::abs(t.heat_flow / exact - 1.0));
    // The primary's facets (1.2/n rad) sag by r dtheta^2 / 8 into the gap: a bound.
    const double dtheta = 1.2 / n;
    EXPECT_LE(errors.back(), 2.0 * dtheta * dtheta / 8.0 / gap) << "n = " << n;
  }
  // Second order in the facet angle.
  EXPECT_GT(errors[0] / errors[1], 3.5);
  EXPECT_GT(errors[1] / errors[2], 3.5);
}

TEST(MortarGapHeat, ParametersDefaultToNoHeat)
{
  const auto p = kiln::validated(Teuchos::ParameterList(), MortarGapHeat::valid_parameters(),
                                 "in.xml", "Kiln/Heat Transfer");
  const MortarGapHeat heat(p, "in.xml: Kiln/Heat Transfer");
  EXPECT_FALSE(heat.active());
  EXPECT_FALSE(heat.depends_on_displacement());
  EXPECT_EQ(heat.flux(500.0, 300.0, 0.01).q, 0.0);
  // A constant conductance alone does not depend on u.
  Teuchos::ParameterList user;
  user.set("Conductance", 5.0);
  user.set("Gas Conductivity", 0.1);
  user.set("Jump Distance", 1e-4);
  const MortarGapHeat gas(
      kiln::validated(user, MortarGapHeat::valid_parameters(), "in.xml", "Kiln/Heat Transfer"),
      "in.xml: Kiln/Heat Transfer");
  EXPECT_TRUE(gas.active());
  EXPECT_TRUE(gas.depends_on_displacement());
  EXPECT_NEAR(gas.flux(301.0, 300.0, 0.0).q, 5.0 + 0.1 / 1e-4, 1e-9);
}

std::string error_of(const Teuchos::ParameterList &user)
{
  return kiln_test::input_error_message(
      [&]
      {
        const auto p = kiln::validated(user, MortarGapHeat::valid_parameters(), "in.xml",
                                       "Kiln/Heat Transfer");
        MortarGapHeat(p, "in.xml: Kiln/Heat Transfer");
      });
}

TEST(MortarGapHeat, InputErrors)
{
  Teuchos::ParameterList gas;
  gas.set("Gas Conductivity", 0.1);
  EXPECT_THAT(error_of(gas),
              HasSubstr("in.xml: Kiln/Heat Transfer/\"Jump Distance\" = 0: must be > 0 "
                        "with a \"Gas Conductivity\""));
  Teuchos::ParameterList one;
  one.set("Primary Emissivity", 0.7);
  EXPECT_THAT(error_of(one), HasSubstr("in.xml: Kiln/Heat Transfer/\"Secondary Emissivity\": must "
                                       "be given with \"Primary Emissivity\" = 0.7"));
  Teuchos::ParameterList other;
  other.set("Secondary Emissivity", 0.7);
  EXPECT_THAT(error_of(other), HasSubstr("\"Primary Emissivity\": must be given with"));
  other.set("Primary Emissivity", 0.0); // given as 0: a mirror, no radiation
  EXPECT_EQ(error_of(other), "");
  Teuchos::ParameterList above_one;
  above_one.set("Primary Emissivity", 1.5);
  EXPECT_THAT(error_of(above_one), HasSubstr("Primary Emissivity"));
  Teuchos::ParameterList negative;
  negative.set("Gas Conductivity", -0.1);
  EXPECT_THAT(error_of(negative), HasSubstr("Gas Conductivity"));
  Teuchos::ParameterList table;
  Teuchos::ParameterList &k = table.sublist("Gas Conductivity");
  k.set("Type", "Table");
  k.set("Temperatures", kiln_test::values({300.0, 600.0}));
  k.set("Values", kiln_test::values({0.1, -0.2}));
  table.set("Jump Distance", 1e-5);
  EXPECT_THAT(error_of(table),
              HasSubstr("in.xml: Kiln/Heat Transfer/Gas Conductivity/\"Values\" entry 2"));
}
} // namespace
