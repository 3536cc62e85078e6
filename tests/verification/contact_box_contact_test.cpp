// Frictionless contact across the gap of the contact box (../shared/spec/contact-box.md)
// against the analytic closed-gap state, and the closing and opening of variant A, read back
// from the HDF5 output:
// - the spec's table (7 digits) for the closed gap, dT = +10 and +100, is the formula's;
// - inputs/contact-box-close.xml to 150 s: at 0 s the open-gap state at 288 K; at 50 s every
//   gap pair is open (contact_active 0, gap_opening > 0), at 53 s every pair in contact
//   (contact_active 1, |gap_opening| < 1e-12 m, contact pressure > 0); at 150 s the temperature
//   is 308 K to 1e-9 of dT and the closed-gap state holds: every cell's stress, strain and
//   thermal strain to 1e-9 of the tensor's largest component (1e-3 Pa, 1e-13 where the exact
//   value is 0), every node's displacement to 1e-9 of the largest, the contact pressure at
//   every gap node equal to -sigma_xx = E alpha dT / (1 - nu) of the box frame to 1e-9,
//   contact_active 1 and |gap_opening| < 1e-12 m;
// - inputs/contact-box-open.xml to 53 s: at 0 s (after the initial equilibrium at 308 K) the
//   same closed-gap state; every pair in contact at 50 s, every pair open at 53 s;
// - both on the generated box of the decks and on the Cubit mesh rotated-cube.exo.
// The decks run with tighter tolerances than their own (Newton 1e-12 relative and 1e-11
// absolute, GMRES 1e-13, steps of at most 2 s): with the decks' 5 s steps the temperature at
// 150 s is 308 K only to 7e-7 K (7e-8 of dT); at most 2 s steps make it 7e-12 K.
// - variant B: inputs/contact-box-close-convection.xml closed by 5 s, the dT = +100 state at
//   600 s.
// KILN_TEST_NP: 1 2
#include "io/input_reader.hpp"
#include "support/contact_box.hpp"
#include "support/parallel.hpp"
#include "support/results_files.hpp"
#include "support/simulation_runs.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace
{
using namespace kiln_test;
using kiln::Point;

/// The closed-gap state of the spec's material at temperature T, phi 45, theta -30.
UniformState spec_closed_gap_state(const double T)
{
  return closed_gap_state(spec_E, spec_nu, spec_alpha, T - spec_T_ref, 45.0, -30.0);
}

/// The open-gap state of the spec's material at temperature T (half width 2 cm).
UniformState spec_open_gap_state(const double T)
{
  return open_gap_state(spec_E, spec_nu, spec_alpha, T - spec_T_ref, 0.02, 45.0, -30.0);
}

/// The largest deviation of tensors from an exact one, relative to the exact tensor's largest
/// component; components that are 0 (to the round-off of the rotation: below 1e-12 of the
/// largest) are held to an absolute tolerance instead.
struct TensorDeviation
{
  double relative = 0.0;
  double absolute_at_zero = 0.0;
  /// Records actual[0..5] against `exact`; true if every component is within tolerance.
  bool check(const double *actual, const kiln::Voigt &exact, const double rel,
             const double zero_tol)
  {
    double largest = 0.0;
    for (const double e : exact)
      largest = std::max(largest, std::abs(e));
    bool ok = true;
    for (int k = 0; k < 6; ++k)
    {
      const double error = std::abs(actual[k] - exact[k]);
      if (std::abs(exact[k]) <= 1e-12 * largest)
      {
        absolute_at_zero = std::max(absolute_at_zero, error);
        ok = ok && error <= zero_tol;
      }
      else
      {
        relative = std::max(relative, error / largest);
        ok = ok && error <= rel * largest;
      }
    }
    return ok;
  }
};

std::string tensor_text(const double *t)
{
  std::ostringstream s;
  s << std::setprecision(10) << "(" << t[0];
  for (int k = 1; k < 6; ++k)
    s << ", " << t[k];
  s << ")";
  return s.str();
}

enum class MeshKind
{
  generated, ///< the deck's own Box
  cubit      ///< ../shared/meshes/rotated-cube.exo
};

std::string mesh_name(const MeshKind mesh)
{
  return mesh == MeshKind::generated ? "generated box" : "rotated-cube.exo";
}

/// inputs/<deck> with its results at `base` at the given output times, on the mesh asked for;
/// Newton to 1e-12 relative and 1e-11 absolute, GMRES to 1e-13, steps of at most 2 s.
Teuchos::ParameterList contact_box_deck(const std::string &deck, const MeshKind mesh,
                                        const std::string &base, const std::vector<double> &times)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  Teuchos::ParameterList input = kiln::read_input(inputs + deck, *comm);
  if (mesh == MeshKind::cubit)
  {
    const auto cubit = Teuchos::getParametersFromXmlString("<ParameterList name=\"Mesh\">" +
                                                           cubit_mesh + "</ParameterList>");
    input.remove("Mesh");
    input.sublist("Mesh").setParameters(*cubit);
  }
  input.sublist("Output")
      .set("File Base", base)
      .set("Times", Teuchos::Array<double>(times.begin(), times.end()));
  input.sublist("Time Stepping").set("Maximum Step", 2.0);
  set_solver_tolerances(input, 1e-11, 1e-12, 1e-13);
  return input;
}

/// What a run leaves for the checks (the output file is closed when it returns).
struct Run
{
  kiln::Mesh mesh;
  std::size_t n_gap_pairs = 0;
  double seconds = 0.0;
};

Run run(const Teuchos::ParameterList &input, const std::string &label)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto start = std::chrono::steady_clock::now();
  Run r;
  {
    kiln::Simulation sim(input, label, comm);
    sim.run();
    r.mesh = sim.mesh();
    r.n_gap_pairs = sim.mesh().gap_pairs.size();
  } // the Simulation closes its output file here
  comm->barrier();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  rank0_out() << label << ": run in " << std::setprecision(3) << r.seconds << " s on "
              << comm->getSize() << " rank(s)\n"
              << std::setprecision(6);
  EXPECT_GT(r.n_gap_pairs, 0u) << label;
  return r;
}

/// One output step of BASE.h5 (rank 0 reads it).
struct OutputStep
{
  double time = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> temperature, displacement, stress, strain, thermal_strain;
  std::vector<double> gap_opening, contact_pressure, contact_active;
};

OutputStep read_output_step(const std::string &h5, const int step)
{
  OutputStep s;
  double t = 0.0;
  s.temperature = read_step(h5, "temperature", step, s.time);
  s.displacement = read_step(h5, "displacement", step, t);
  s.stress = read_step(h5, "stress", step, t);
  s.strain = read_step(h5, "strain", step, t);
  s.thermal_strain = read_step(h5, "thermal_strain", step, t);
  s.gap_opening = read_step(h5, "gap_opening", step, t);
  s.contact_pressure = read_step(h5, "contact_pressure", step, t);
  s.contact_active = read_step(h5, "contact_active", step, t);
  return s;
}

/// The gap nodes of an output step (those with a gap opening), checked against the mesh: two per
/// pair; off the gap, traction and contact_active are NaN.
std::vector<int> gap_nodes(const std::string &label, const OutputStep &s, const Run &r)
{
  std::vector<int> nodes;
  const std::size_t n_nodes = static_cast<std::size_t>(r.mesh.n_nodes());
  EXPECT_EQ(s.gap_opening.size(), n_nodes) << label;
  EXPECT_EQ(s.contact_pressure.size(), n_nodes) << label;
  EXPECT_EQ(s.contact_active.size(), n_nodes) << label;
  if (s.gap_opening.size() != n_nodes || s.contact_pressure.size() != n_nodes ||
      s.contact_active.size() != n_nodes)
    return nodes;
  for (std::size_t n = 0; n < n_nodes; ++n)
  {
    if (!std::isnan(s.gap_opening[n]))
      nodes.push_back(static_cast<int>(n));
    else
    {
      EXPECT_TRUE(std::isnan(s.contact_pressure[n]))
          << label << ": node " << n << " off the gap has contact_pressure "
          << s.contact_pressure[n];
      EXPECT_TRUE(std::isnan(s.contact_active[n]))
          << label << ": node " << n << " off the gap has contact_active " << s.contact_active[n];
    }
  }
  EXPECT_EQ(nodes.size(), 2 * r.n_gap_pairs) << label << ": gap nodes in the output";
  return nodes;
}

constexpr double closed_opening_tolerance = 1e-12; // [m]

/// Output step `step` (at `time`): every gap pair in contact (closed) or open. In contact:
/// contact_active 1, |gap_opening| < 1e-12 m, a positive (compressive) contact pressure; open:
/// contact_active 0, gap_opening > 0, pressure 0.
void check_gap(const std::string &label, const std::string &h5, const int step, const double time,
               const bool closed, const Run &r)
{
  const OutputStep s = read_output_step(h5, step);
  EXPECT_NEAR(s.time, time, 1e-9 * std::max(1.0, time)) << label << ": output step " << step;
  double opening_min = std::numeric_limits<double>::infinity(), opening_max = -opening_min;
  double traction_min = opening_min, traction_max = -opening_min;
  for (const int n : gap_nodes(label, s, r))
  {
    const double g = s.gap_opening[n], p = s.contact_pressure[n];
    opening_min = std::min(opening_min, g);
    opening_max = std::max(opening_max, g);
    traction_min = std::min(traction_min, p);
    traction_max = std::max(traction_max, p);
    EXPECT_EQ(s.contact_active[n], closed ? 1.0 : 0.0) << label << ": gap node " << n;
    if (closed)
    {
      EXPECT_LT(std::abs(g), closed_opening_tolerance) << label << ": gap node " << n;
      EXPECT_GT(p, 0.0) << label << ": gap node " << n << " contact pressure";
    }
    else
    {
      EXPECT_GT(g, 0.0) << label << ": gap node " << n;
      EXPECT_EQ(p, 0.0) << label << ": gap node " << n << " contact pressure";
    }
  }
  rank0_out() << label << ": gap " << (closed ? "closed" : "open") << " at t = " << s.time
              << " s: gap opening in [" << opening_min << ", " << opening_max
              << "] m, contact pressure in [" << traction_min << ", " << traction_max << "] Pa\n";
}

/// Output step `step` (at `time`) is the uniform state `exact` at temperature T: the temperature
/// of every node to 1e-9 of |T - T_ref|, every cell's stress, strain and thermal strain to `rel`
/// of the tensor's largest component (zero_stress_tolerance, zero_strain_tolerance where 0),
/// every node's displacement to `rel` of the largest, and at every gap node the state of the gap
/// (contact_active 1, |gap_opening| < 1e-12 m and the traction to `rel` when closed; contact
/// active 0, the opening to `rel` and traction 0 when open).
void check_uniform_state(const std::string &label, const std::string &h5, const int step,
                         const double time, const double T, const UniformState &exact,
                         const bool closed, const double rel, const Run &r)
{
  const OutputStep s = read_output_step(h5, step);
  EXPECT_NEAR(s.time, time, 1e-9 * std::max(1.0, time)) << label << ": output step " << step;
  const std::size_t n_nodes = static_cast<std::size_t>(r.mesh.n_nodes());
  const std::size_t n_cells = static_cast<std::size_t>(r.mesh.n_cells());

  double T_deviation = 0.0;
  ASSERT_EQ(s.temperature.size(), n_nodes) << label;
  for (const double t : s.temperature)
    T_deviation = std::max(T_deviation, std::abs(t - T));
  EXPECT_LE(T_deviation, 1e-9 * std::abs(T - spec_T_ref)) << label << ": temperature";

  TensorDeviation stress, strain, thermal_strain;
  ASSERT_EQ(s.stress.size(), 6 * n_cells) << label;
  ASSERT_EQ(s.strain.size(), 6 * n_cells) << label;
  ASSERT_EQ(s.thermal_strain.size(), 6 * n_cells) << label;
  for (std::size_t c = 0; c < n_cells; ++c)
  {
    const double *sigma = &s.stress[6 * c], *eps = &s.strain[6 * c];
    const double *eps_T = &s.thermal_strain[6 * c];
    EXPECT_TRUE(stress.check(sigma, exact.stress, rel, zero_stress_tolerance))
        << label << ": cell " << c << " stress " << tensor_text(sigma) << ", expected "
        << tensor_text(exact.stress.data());
    EXPECT_TRUE(strain.check(eps, exact.strain, rel, zero_strain_tolerance))
        << label << ": cell " << c << " strain " << tensor_text(eps) << ", expected "
        << tensor_text(exact.strain.data());
    EXPECT_TRUE(thermal_strain.check(eps_T, exact.thermal_strain, rel, zero_strain_tolerance))
        << label << ": cell " << c << " thermal strain " << tensor_text(eps_T) << ", expected "
        << tensor_text(exact.thermal_strain.data());
  }

  const std::vector<Point> u_exact = exact_displacements(r.mesh, exact);
  ASSERT_EQ(s.displacement.size(), 3 * n_nodes) << label;
  double u_scale = 0.0, u_error = 0.0;
  for (const Point &v : u_exact)
    for (const double vd : v)
      u_scale = std::max(u_scale, std::abs(vd));
  for (std::size_t n = 0; n < n_nodes; ++n)
    for (int d = 0; d < 3; ++d)
    {
      const double e = std::abs(s.displacement[3 * n + d] - u_exact[n][d]);
      u_error = std::max(u_error, e);
      EXPECT_LE(e, rel * u_scale) << label << ": node " << n << " u_" << d << " = "
                                  << s.displacement[3 * n + d] << ", expected " << u_exact[n][d];
    }

  Deviation traction, opening;
  double opening_closed = 0.0; // max |gap opening| where closed
  for (const int n : gap_nodes(label, s, r))
  {
    const double g = s.gap_opening[n], p = s.contact_pressure[n];
    EXPECT_EQ(s.contact_active[n], closed ? 1.0 : 0.0) << label << ": gap node " << n;
    EXPECT_TRUE(traction.check(p, exact.contact_pressure, rel, 0.0))
        << label << ": gap node " << n << " contact pressure " << std::setprecision(12) << p
        << " Pa, expected " << exact.contact_pressure;
    if (closed)
    {
      opening_closed = std::max(opening_closed, std::abs(g));
      EXPECT_LT(std::abs(g), closed_opening_tolerance) << label << ": gap node " << n;
    }
    else
    {
      EXPECT_TRUE(opening.check(g, exact.gap_opening, rel, 0.0))
          << label << ": gap node " << n << " gap opening " << g << " m, expected "
          << exact.gap_opening;
    }
  }

  rank0_out() << label << " at t = " << s.time << " s (tolerance " << rel << "): max |T - " << T
              << "| = " << T_deviation << " K; max deviation / largest component of stress "
              << stress.relative << ", strain " << strain.relative << ", thermal strain "
              << thermal_strain.relative << "; where 0: stress " << stress.absolute_at_zero
              << " Pa, strain " << strain.absolute_at_zero << "; max |u - u_exact| / max |u_exact| "
              << u_error / u_scale << "; contact pressure "
              << (closed ? traction.relative : traction.absolute_at_zero)
              << (closed ? " relative" : " Pa") << ", gap opening "
              << (closed ? opening_closed : opening.relative) << (closed ? " m" : " relative")
              << "\n";
}

/// inputs/contact-box-close.xml to 150 s: open-gap state at 0 s, open at 50 s, closed at 53 s,
/// the closed-gap state at 150 s.
void check_closing_box(const MeshKind mesh)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string label = "contact-box-close.xml on the " + mesh_name(mesh);
  const std::string base =
      temporary_base(mesh == MeshKind::generated ? "close_generated" : "close_cubit", *comm);
  const Run r =
      run(contact_box_deck("contact-box-close.xml", mesh, base, {0.0, 50.0, 53.0, 150.0}), label);
  if (comm->getRank() == 0)
  {
    const std::string h5 = base + ".h5";
    check_uniform_state(label, h5, 0, 0.0, 288.0, spec_open_gap_state(288.0), false, 1e-9, r);
    check_gap(label, h5, 1, 50.0, false, r);
    check_gap(label, h5, 2, 53.0, true, r);
    check_uniform_state(label, h5, 3, 150.0, 308.0, spec_closed_gap_state(308.0), true, 1e-9, r);
  }
  remove_results(base, *comm);
}

/// inputs/contact-box-open.xml to 53 s: the closed-gap state at 0 s, closed at 50 s, open at 53 s.
void check_opening_box(const MeshKind mesh)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string label = "contact-box-open.xml on the " + mesh_name(mesh);
  const std::string base =
      temporary_base(mesh == MeshKind::generated ? "open_generated" : "open_cubit", *comm);
  const Run r = run(contact_box_deck("contact-box-open.xml", mesh, base, {0.0, 50.0, 53.0}), label);
  if (comm->getRank() == 0)
  {
    const std::string h5 = base + ".h5";
    check_uniform_state(label, h5, 0, 0.0, 308.0, spec_closed_gap_state(308.0), true, 1e-9, r);
    check_gap(label, h5, 1, 50.0, true, r);
    check_gap(label, h5, 2, 53.0, false, r);
  }
  remove_results(base, *comm);
}
/// Variant B, inputs/contact-box-close-convection.xml to 600 s (its own steps, up to 50 s):
/// the open-gap state at 0 s, closed by 5 s, and at 600 s the closed-gap state of the spec's
/// dT = +100 column (398 K).
void check_closing_by_convection(const MeshKind mesh)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string label = "contact-box-close-convection.xml on the " + mesh_name(mesh);
  const std::string base = temporary_base(
      mesh == MeshKind::generated ? "close_convection_generated" : "close_convection_cubit", *comm);
  Teuchos::ParameterList input =
      contact_box_deck("contact-box-close-convection.xml", mesh, base, {0.0, 5.0, 600.0});
  input.sublist("Time Stepping").set("Maximum Step", 50.0);
  const Run r = run(input, label);
  if (comm->getRank() == 0)
  {
    const std::string h5 = base + ".h5";
    check_uniform_state(label, h5, 0, 0.0, 288.0, spec_open_gap_state(288.0), false, 1e-9, r);
    check_gap(label, h5, 1, 5.0, true, r);
    check_uniform_state(label, h5, 2, 600.0, 398.0, spec_closed_gap_state(398.0), true, 1e-9, r);
  }
  remove_results(base, *comm);
}
} // namespace

TEST(ContactBoxContact, ClosingByConvectionOnGeneratedMesh)
{
  check_closing_by_convection(MeshKind::generated);
}

TEST(ContactBoxContact, ClosingByConvectionOnCubitMesh)
{
  check_closing_by_convection(MeshKind::cubit);
}

TEST(ContactBoxContact, SpecTableIsTheClosedGapFormula)
{
  // The "closed" columns of the table (dT = +10 and +100, 7 significant digits).
  const kiln::Voigt stress_10{-2.288e7, -5.72e6, -1.716e7, 0.0, 0.0, -9.907331e6};
  const kiln::Voigt strain_10{0.0, 3.3e-4, 1.1e-4, 0.0, 0.0, -1.905256e-4};
  for (const double dT : {10.0, 100.0})
  {
    const UniformState formula = spec_closed_gap_state(spec_T_ref + dT);
    const double factor = dT / 10.0; // the state is linear in dT
    for (int k = 0; k < 6; ++k)
    {
      // Where the table has 0: to 1e-12 of the largest component (round-off of the rotation).
      EXPECT_NEAR(formula.stress[k], factor * stress_10[k],
                  std::max(1e-6 * std::abs(factor * stress_10[k]), 1e-12 * 2.288e7 * factor))
          << "dT " << dT << ": stress " << voigt_name[k];
      EXPECT_NEAR(formula.strain[k], factor * strain_10[k],
                  std::max(1e-6 * std::abs(factor * strain_10[k]), 1e-12 * 3.3e-4 * factor))
          << "dT " << dT << ": strain " << voigt_name[k];
    }
    EXPECT_NEAR(formula.contact_pressure, 2.288e7 * factor, 1e-6 * 2.288e7 * factor);
    EXPECT_EQ(formula.gap_opening, 0.0);
  }
}

TEST(ContactBoxContact, ClosingBoxOnGeneratedMesh)
{
  check_closing_box(MeshKind::generated);
}

TEST(ContactBoxContact, ClosingBoxOnCubitMesh)
{
  check_closing_box(MeshKind::cubit);
}

TEST(ContactBoxContact, OpeningBoxOnGeneratedMesh)
{
  check_opening_box(MeshKind::generated);
}

TEST(ContactBoxContact, OpeningBoxOnCubitMesh)
{
  check_opening_box(MeshKind::cubit);
}
