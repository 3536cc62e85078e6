#include "support/contact_box_runs.hpp"

#include "app/simulation.hpp"
#include "io/input_reader.hpp"
#include "physics/coupled_problem.hpp"
#include "support/parallel.hpp"
#include "support/results_files.hpp"
#include "support/simulation_runs.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <limits>
#include <sstream>

namespace kiln_test
{
namespace
{
using kiln::Point;

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

/// The gap nodes of an output step (those with a gap opening), checked against the mesh: two per
/// pair of a split gap, one per row of a contact pair; off them, traction and contact_active are
/// NaN.
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
  EXPECT_EQ(nodes.size(), 2 * r.n_gap_pairs + r.n_pair_rows)
      << label << ": gap nodes in the output";
  return nodes;
}
} // namespace

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
  Teuchos::ParameterList input =
      kiln::read_input(deck.find('/') == std::string::npos ? inputs + deck : deck, *comm);
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

Run run(const Teuchos::ParameterList &input, const std::string &label, const bool split_gap)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto start = std::chrono::steady_clock::now();
  Run r;
  {
    kiln::Simulation sim(input, label, comm);
    sim.run();
    r.mesh = sim.mesh();
    r.n_gap_pairs = sim.mesh().gap_pairs.size();
    // CoupledProblem::n_pairs(): the split gaps' pairs and the contact pairs' rows (none
    // without contact).
    const auto n_pairs = static_cast<std::size_t>(sim.problem().n_pairs());
    r.n_pair_rows = n_pairs > r.n_gap_pairs ? n_pairs - r.n_gap_pairs : 0;
  } // the Simulation closes its output file here
  comm->barrier();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  rank0_out() << label << ": run in " << std::setprecision(3) << r.seconds << " s on "
              << comm->getSize() << " rank(s)\n"
              << std::setprecision(6);
  EXPECT_EQ(r.n_gap_pairs > 0, split_gap) << label;
  return r;
}

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
  check_uniform_state(
      label, h5, step, time, T, exact, closed,
      {rel, zero_stress_tolerance, zero_strain_tolerance, 1e-9 * std::abs(T - spec_T_ref)}, r);
}

void check_uniform_state(const std::string &label, const std::string &h5, const int step,
                         const double time, const double T, const UniformState &exact,
                         const bool closed, const StateTolerance &tolerance, const Run &r)
{
  const double rel = tolerance.relative;
  const OutputStep s = read_output_step(h5, step);
  EXPECT_NEAR(s.time, time, 1e-9 * std::max(1.0, time)) << label << ": output step " << step;
  const std::size_t n_nodes = static_cast<std::size_t>(r.mesh.n_nodes());
  const std::size_t n_cells = static_cast<std::size_t>(r.mesh.n_cells());

  double T_deviation = 0.0;
  ASSERT_EQ(s.temperature.size(), n_nodes) << label;
  for (const double t : s.temperature)
    T_deviation = std::max(T_deviation, std::abs(t - T));
  EXPECT_LE(T_deviation, tolerance.temperature) << label << ": temperature";

  TensorDeviation stress, strain, thermal_strain;
  ASSERT_EQ(s.stress.size(), 6 * n_cells) << label;
  ASSERT_EQ(s.strain.size(), 6 * n_cells) << label;
  ASSERT_EQ(s.thermal_strain.size(), 6 * n_cells) << label;
  for (std::size_t c = 0; c < n_cells; ++c)
  {
    const double *sigma = &s.stress[6 * c], *eps = &s.strain[6 * c];
    const double *eps_T = &s.thermal_strain[6 * c];
    EXPECT_TRUE(stress.check(sigma, exact.stress, rel, tolerance.zero_stress))
        << label << ": cell " << c << " stress " << tensor_text(sigma) << ", expected "
        << tensor_text(exact.stress.data());
    EXPECT_TRUE(strain.check(eps, exact.strain, rel, tolerance.zero_strain))
        << label << ": cell " << c << " strain " << tensor_text(eps) << ", expected "
        << tensor_text(exact.strain.data());
    EXPECT_TRUE(thermal_strain.check(eps_T, exact.thermal_strain, rel, tolerance.zero_strain))
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

void check_closing_box(const std::string &deck, const MeshKind mesh)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string label = deck + " on the " + mesh_name(mesh);
  const std::string name = deck.substr(0, deck.rfind('.'));
  const std::string base =
      temporary_base(name + (mesh == MeshKind::generated ? "_generated" : "_cubit"), *comm);
  const Run r = run(contact_box_deck(deck, mesh, base, {0.0, 50.0, 53.0, 150.0}), label);
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
void check_pair_output(const std::string &label, const std::string &base, const double pressure,
                       const bool open_at_start)
{
  SCOPED_TRACE(label + ": the output of the pair \"cut\"");
  const std::string h5 = base + ".h5";
  const double area = 0.04 * 0.04;
  const std::vector<double> nodes = read_dataset(h5, "/pair_cut/node_a");
  const std::vector<double> faces_area = read_dataset(h5, "/pair_cut/area");
  double sum = 0.0;
  for (const double a : faces_area)
    sum += a;
  EXPECT_NEAR(sum, area, 1e-12 * area) << "the secondary surface's area";
  std::ifstream xmf(base + ".xmf");
  const std::string xdmf((std::istreambuf_iterator<char>(xmf)), std::istreambuf_iterator<char>());
  EXPECT_NE(xdmf.find("<Grid Name=\"pair_cut_000003\""), std::string::npos) << "XDMF grid";
  for (const int step : {0, 3})
  {
    const bool closed = step == 3;
    if (!closed && !open_at_start)
      continue;
    const std::string at = "/pair_cut/steps/00000" + std::to_string(step) + "/";
    const std::vector<double> g = read_dataset(h5, at + "gap_opening");
    const std::vector<double> P = read_dataset(h5, at + "contact_pressure");
    const std::vector<double> active = read_dataset(h5, at + "contact_active");
    const std::string csv = base + ".pair_cut-00000" + std::to_string(step) + ".csv";
    const std::vector<double> csv_P = csv_column(csv, "contact_pressure");
    ASSERT_EQ(P.size(), nodes.size());
    ASSERT_EQ(g.size(), nodes.size());
    ASSERT_EQ(active.size(), nodes.size());
    ASSERT_EQ(csv_P.size(), nodes.size()) << csv;
    int rows = 0;
    for (std::size_t p = 0; p < nodes.size(); ++p)
    {
      if (std::isnan(active[p]))
      {
        EXPECT_TRUE(std::isnan(P[p]) && std::isnan(g[p])) << "node " << nodes[p] << ": no row";
        continue;
      }
      ++rows;
      EXPECT_EQ(active[p], closed ? 1.0 : 0.0) << "node " << nodes[p] << " at step " << step;
      if (closed)
      {
        EXPECT_NEAR(P[p], pressure, 1e-9 * std::abs(pressure)) << "node " << nodes[p];
        EXPECT_NEAR(g[p], 0.0, 1e-15) << "node " << nodes[p];
      }
      else
      {
        EXPECT_EQ(P[p], 0.0) << "node " << nodes[p];
        EXPECT_GT(g[p], 0.0) << "node " << nodes[p];
      }
      EXPECT_EQ(csv_P[p], P[p]) << csv << ": node " << nodes[p];
    }
    EXPECT_GT(rows, 0) << "nodes with a row at step " << step;
  }
  const std::vector<double> time = read_dataset(h5, "/history/time");
  const std::vector<double> force = read_dataset(h5, "/history/normal_force_cut");
  const std::vector<double> in_contact = read_dataset(h5, "/history/contact_area_cut");
  ASSERT_FALSE(time.empty());
  ASSERT_EQ(force.size(), time.size());
  ASSERT_EQ(in_contact.size(), time.size());
  EXPECT_EQ(time.front(), 0.0);
  if (open_at_start)
  {
    EXPECT_EQ(force.front(), 0.0);
    EXPECT_EQ(in_contact.front(), 0.0);
  }
  EXPECT_EQ(time.back(), 150.0);
  EXPECT_NEAR(force.back(), pressure * area, 1e-9 * pressure * area);
  EXPECT_NEAR(in_contact.back(), area, 1e-9 * area);
  // The CSV history has the same columns.
  const std::vector<double> csv_force = csv_column(base + ".history.csv", "normal_force_cut");
  ASSERT_FALSE(csv_force.empty());
  EXPECT_EQ(csv_force.back(), force.back());
}
} // namespace kiln_test
