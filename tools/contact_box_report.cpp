// kiln_contact_box_report: compares the last output step of a contact-box run with the
// analytic uniform state of ../shared/spec/contact-box.md (closed gap or open gap, uniform
// temperature), rotated to the mesh frame by A = Rx(theta) Ry(phi). It reports, it does not
// judge: exit status 0 when it could read and compare, 1 with a message when the deck or the
// results cannot be read or lack a field, 2 for a bad command line.
//
// usage: kiln_contact_box_report [--phi DEG] [--theta DEG] DECK.xml RESULTS.h5
//   The material (elastic constants, alpha, T_ref) and the box (Phi, Theta, Size) come from
//   the deck, validated as kiln does (defaults included). For an Exodus mesh the angles are
//   --phi/--theta (default 45/-30 for rotated-cube.exo, 0/0 for any other file) and the half
//   width comes from the mesh coordinates; --phi/--theta also override a Box deck's angles.
//   Elastic constants and an expansion coefficient that depend on T (Table, Expression) are
//   evaluated at the mean temperature of the last step: the uniform state at T is the
//   constant-property state with the material's values at T (alpha the secant coefficient).
#include "app/simulation.hpp"
#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "io/input_reader.hpp"
#include "physics/materials/material.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_DefaultSerialComm.hpp>
#include <hdf5.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using Matrix = std::array<std::array<double, 3>, 3>;
using Voigt = std::array<double, 6>;

/// The tensor components in the order of the results file (doc/output-format.md).
const char *const voigt_names[6] = {"xx", "yy", "zz", "xy", "yz", "xz"};
const int voigt_i[6] = {0, 1, 2, 0, 1, 0};
const int voigt_j[6] = {0, 1, 2, 1, 2, 2};

/// A problem with the deck or the results: reported, exit status 1.
struct ReportError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// --- the analytic solution (spec, "Analytic solution for the uniform states") -----------

/// A = Rx(theta) Ry(phi), angles in degrees, written out from the spec (not Kiln's own
/// rotation, so that the comparison does not share its code).
Matrix rotation(const double phi_degrees, const double theta_degrees)
{
  const double pi = std::acos(-1.0);
  const double p = phi_degrees * pi / 180.0, t = theta_degrees * pi / 180.0;
  const Matrix Ry{
      {{std::cos(p), 0.0, std::sin(p)}, {0.0, 1.0, 0.0}, {-std::sin(p), 0.0, std::cos(p)}}};
  const Matrix Rx{
      {{1.0, 0.0, 0.0}, {0.0, std::cos(t), -std::sin(t)}, {0.0, std::sin(t), std::cos(t)}}};
  Matrix A{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        A[i][j] += Rx[i][k] * Ry[k][j];
  return A;
}

/// A S A^T of a diagonal tensor S = diag(d), in the file's order (tensor shear components).
/// Components below 1e-14 of the largest are round-off of the rotation and set to 0.
Voigt rotated_diagonal(const Matrix &A, const std::array<double, 3> &d)
{
  Voigt v{};
  double largest = 0.0;
  for (int k = 0; k < 6; ++k)
  {
    for (int m = 0; m < 3; ++m)
      v[k] += A[voigt_i[k]][m] * d[m] * A[voigt_j[k]][m];
    largest = std::max(largest, std::abs(v[k]));
  }
  for (double &c : v)
    if (std::abs(c) < 1e-14 * largest)
      c = 0.0;
  return v;
}

struct ExactState
{
  Voigt stress{}, strain{};
  double contact_pressure = 0.0, gap_opening = 0.0; ///< [Pa] > 0 in compression, [m]
};

/// The uniform state at temperature T (dT = T - T_ref), closed or open gap, in the mesh frame.
/// The material is evaluated at T (E(T), nu(T), alpha(T): a uniform state at T is the
/// constant-property state of the material's values at T; alpha is the secant coefficient from
/// T_ref, doc/materials.md).
ExactState exact_state(const bool closed, const kiln::Material &m, const double T,
                       const double half_width, const Matrix &A)
{
  const double dT = T - m.reference_temperature();
  const double E = m.youngs_modulus(T), nu = m.poissons_ratio(T), alpha = m.thermal_expansion(T);
  const double lambda = m.lame_lambda(T), G = m.shear_modulus(T);
  ExactState s;
  if (closed)
  {
    const double sigma = -E * alpha * dT / (1.0 - nu);
    s.stress = rotated_diagonal(A, {sigma, 0.0, sigma});
    s.strain =
        rotated_diagonal(A, {0.0, (3 * lambda + 2 * G) * alpha * dT / (lambda + 2 * G), 0.0});
    s.contact_pressure = -sigma;
    s.gap_opening = 0.0;
  }
  else
  {
    const double eps = (1.0 + nu) * alpha * dT;
    s.stress = rotated_diagonal(A, {0.0, 0.0, -E * alpha * dT});
    s.strain = rotated_diagonal(A, {eps, eps, 0.0});
    s.contact_pressure = 0.0;
    s.gap_opening = -2.0 * half_width * eps;
  }
  return s;
}

// --- the results file (doc/output-format.md) --------------------------------------------

/// One dataset: rows x cols values, row-major.
struct Field
{
  std::vector<double> values;
  std::size_t rows = 0, cols = 1;
  double at(const std::size_t row, const std::size_t col = 0) const
  {
    return values[row * cols + col];
  }
};

class Results
{
public:
  explicit Results(const std::string &path) : path_(path)
  {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // errors are reported here, not by HDF5
    if (!std::filesystem::is_regular_file(path))
      throw ReportError(path + ": no such file (run kiln on the deck first)");
    if (H5Fis_hdf5(path.c_str()) <= 0)
      throw ReportError(path + ": not an HDF5 file");
    file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file_ < 0)
      throw ReportError(path + ": cannot open the HDF5 file");
  }
  ~Results()
  {
    if (file_ >= 0)
      H5Fclose(file_);
  }
  Results(const Results &) = delete;
  Results &operator=(const Results &) = delete;

  /// The group of the last output step ("/steps/000003") and its time attribute.
  std::string last_step(double &time) const
  {
    H5G_info_t info{};
    if (H5Lexists(file_, "/steps", H5P_DEFAULT) <= 0 ||
        H5Gget_info_by_name(file_, "/steps", &info, H5P_DEFAULT) < 0 || info.nlinks == 0)
      throw ReportError(path_ + ": no output step (no group /steps/000000)");
    char group[32];
    std::snprintf(group, sizeof group, "/steps/%06d", static_cast<int>(info.nlinks) - 1);
    if (H5Lexists(file_, group, H5P_DEFAULT) <= 0)
      throw ReportError(path_ + ": /steps holds " + std::to_string(info.nlinks) +
                        " groups but no " + group + " (not a Kiln results file?)");
    time = std::numeric_limits<double>::quiet_NaN();
    const hid_t attribute = H5Aopen_by_name(file_, group, "time", H5P_DEFAULT, H5P_DEFAULT);
    const bool ok = attribute >= 0 && H5Aread(attribute, H5T_NATIVE_DOUBLE, &time) >= 0;
    if (attribute >= 0)
      H5Aclose(attribute);
    if (!ok)
      throw ReportError(path_ + ": " + group + " has no attribute \"time\"");
    return group;
  }

  /// Dataset `path`, which must have `rows` rows (0: any) and `cols` components (1: a 1-D
  /// dataset). `hint` ends the message when the dataset is missing.
  Field read(const std::string &path, const std::size_t rows, const std::size_t cols,
             const std::string &hint = "") const
  {
    if (H5Lexists(file_, path.c_str(), H5P_DEFAULT) <= 0)
      throw ReportError(path_ + ": no dataset " + path + hint);
    const hid_t dataset = H5Dopen2(file_, path.c_str(), H5P_DEFAULT);
    if (dataset < 0)
      throw ReportError(path_ + ": cannot open dataset " + path);
    const hid_t space = H5Dget_space(dataset);
    const int rank = H5Sget_simple_extent_ndims(space);
    hsize_t dims[2] = {0, 1};
    if (rank == 1 || rank == 2)
      H5Sget_simple_extent_dims(space, dims, nullptr);
    H5Sclose(space);
    Field f;
    f.rows = dims[0];
    f.cols = rank == 2 ? dims[1] : 1;
    const bool shape_ok = (rank == 1 || rank == 2) && (rows == 0 || f.rows == rows) &&
                          f.cols == cols && (cols == 1) == (rank == 1);
    if (!shape_ok)
    {
      H5Dclose(dataset);
      std::ostringstream s;
      s << path_ << ": dataset " << path << " has " << rank << " dimension(s) (" << dims[0];
      if (rank == 2)
        s << " x " << dims[1];
      s << "), expected ";
      if (rows != 0)
        s << rows << (cols > 1 ? " x " + std::to_string(cols) : std::string());
      else
        s << (cols > 1 ? std::to_string(cols) + " components" : std::string("1 component"));
      throw ReportError(s.str());
    }
    f.values.resize(f.rows * f.cols);
    const herr_t status =
        H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, f.values.data());
    H5Dclose(dataset);
    if (status < 0)
      throw ReportError(path_ + ": cannot read dataset " + path);
    return f;
  }

private:
  std::string path_;
  hid_t file_ = H5I_INVALID_HID;
};

// --- the deck ----------------------------------------------------------------------------

struct Geometry
{
  double phi = 0.0, theta = 0.0;
  std::string angles_from;
  double half_width = 0.0; ///< 0: from the mesh coordinates
  std::string mesh;
};

struct Options
{
  std::string deck, results;
  bool phi_given = false, theta_given = false;
  double phi = 0.0, theta = 0.0;
};

double parse_angle(const std::string &option, const std::string &text)
{
  std::size_t end = 0;
  double value = 0.0;
  try
  {
    value = std::stod(text, &end);
  }
  catch (const std::exception &)
  {
    end = 0;
  }
  if (end == 0 || end != text.size())
    throw std::invalid_argument(option + " needs an angle in degrees, got \"" + text + "\"");
  return value;
}

Options parse_command_line(const std::vector<std::string> &args)
{
  Options o;
  std::vector<std::string> positional;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string &a = args[i];
    if (a == "--phi" || a == "--theta")
    {
      if (i + 1 == args.size())
        throw std::invalid_argument(a + " needs an angle in degrees");
      (a == "--phi" ? o.phi : o.theta) = parse_angle(a, args[++i]);
      (a == "--phi" ? o.phi_given : o.theta_given) = true;
    }
    else if (a.size() > 1 && a[0] == '-')
      throw std::invalid_argument("unknown option " + a);
    else
      positional.push_back(a);
  }
  if (positional.size() != 2)
    throw std::invalid_argument("expected DECK.xml and RESULTS.h5, got " +
                                std::to_string(positional.size()) + " file argument(s)");
  o.deck = positional[0];
  o.results = positional[1];
  return o;
}

Geometry geometry_of(const Teuchos::ParameterList &mesh, const Options &o)
{
  Geometry g;
  if (mesh.get<std::string>("Type") == "Box")
  {
    const Teuchos::ParameterList &box = mesh.sublist("Box");
    g.phi = box.get<double>("Phi");
    g.theta = box.get<double>("Theta");
    g.angles_from = "deck";
    g.half_width = box.get<Teuchos::Array<double>>("Size")[0] / 2.0;
    g.mesh = "Box";
  }
  else
  {
    const std::string file = mesh.sublist("Exodus").get<std::string>("File");
    const bool rotated = std::filesystem::path(file).filename() == "rotated-cube.exo";
    g.phi = rotated ? 45.0 : 0.0;
    g.theta = rotated ? -30.0 : 0.0;
    g.angles_from = rotated ? "default for rotated-cube.exo" : "default for an Exodus mesh";
    g.mesh = "Exodus " + file;
  }
  if (o.phi_given || o.theta_given)
  {
    g.phi = o.phi_given ? o.phi : g.phi;
    g.theta = o.theta_given ? o.theta : g.theta;
    g.angles_from = "command line";
  }
  return g;
}

// --- the comparison ----------------------------------------------------------------------

std::string sci(const double v, const int digits = 5)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*e", digits, v);
  return buffer;
}

std::string padded(std::string s, const std::size_t width)
{
  if (s.size() < width)
    s.append(width - s.size(), ' ');
  return s + (s.size() > width ? " " : "");
}

/// One table row: the range of `values`, the exact value and the error, relative to `scale`
/// (absolute when scale is 0, marked "abs.").
void print_row(const std::string &name, const std::vector<double> &values, const double exact,
               const double scale, const std::string &unit_if_absolute = "")
{
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  double error = 0.0;
  for (const double v : values)
    error = std::max(error, std::abs(v - exact));
  std::string error_text;
  if (scale > 0.0)
    error_text = sci(error / scale, 1);
  else
    error_text = sci(error, 1) + (unit_if_absolute.empty() ? "" : " " + unit_if_absolute) + " abs.";
  std::cout << "  " << padded(name, 26) << padded(sci(*lo) + " .. " + sci(*hi), 34)
            << padded(sci(exact), 17) << error_text << "\n";
}

int report(const Options &o)
{
  // The deck, validated as kiln validates it (unknown names, types; defaults filled in).
  const Teuchos::SerialComm<int> serial;
  const Teuchos::ParameterList deck = kiln::validated(
      kiln::read_input(o.deck, serial), kiln::Simulation::valid_parameters(), o.deck, "Kiln");
  const std::string physics = deck.get<std::string>("Physics");
  if (physics != "Thermo-Elasticity")
    throw ReportError(o.deck + ": Kiln/\"Physics\" is \"" + physics +
                      "\"; the contact box is \"Thermo-Elasticity\"");
  const kiln::Material material(deck.sublist("Material"), o.deck + ": Kiln/Material");
  Geometry geometry = geometry_of(deck.sublist("Mesh"), o);
  const Matrix A = rotation(geometry.phi, geometry.theta);

  // The results: mesh sizes, then the fields of the last step.
  const Results results(o.results);
  const Field coordinates = results.read("/mesh/coordinates", 0, 3);
  // The cells of any type: one block id each.
  const Field connectivity = results.read("/mesh/block_id", 0, 1);
  const std::size_t n_nodes = coordinates.rows, n_cells = connectivity.rows;
  if (n_nodes == 0 || n_cells == 0)
    throw ReportError(o.results + ": the mesh is empty");
  double time = 0.0;
  const std::string step = results.last_step(time);
  const std::string needs_mechanics = " (written by a Thermo-Elasticity run)";
  const std::string needs_gap =
      " (written by a Thermo-Elasticity run on a mesh with a gap, Mesh/\"Gap Side Set\")";
  const Field temperature = results.read(step + "/temperature", n_nodes, 1);
  const Field stress = results.read(step + "/stress", n_cells, 6, needs_mechanics);
  const Field strain = results.read(step + "/strain", n_cells, 6, needs_mechanics);
  const Field pressure = results.read(step + "/contact_pressure", n_nodes, 1, needs_gap);
  const Field active = results.read(step + "/contact_active", n_nodes, 1, needs_gap);
  const Field opening = results.read(step + "/gap_opening", n_nodes, 1, needs_gap);

  // Half the extent of the mesh along the gap normal (the first column of A): the half
  // width for an Exodus mesh, a cross-check of the deck's Box Size otherwise.
  double lo = std::numeric_limits<double>::max(), hi = -lo;
  for (std::size_t n = 0; n < n_nodes; ++n)
  {
    double x_normal = 0.0;
    for (int i = 0; i < 3; ++i)
      x_normal += A[i][0] * coordinates.at(n, i);
    lo = std::min(lo, x_normal);
    hi = std::max(hi, x_normal);
  }
  const double mesh_half_width = (hi - lo) / 2.0;
  std::string width_note;
  if (geometry.half_width == 0.0)
    geometry.half_width = mesh_half_width;
  else if (std::abs(mesh_half_width - geometry.half_width) > 1e-9 * geometry.half_width)
    width_note =
        "  note: the results' mesh has a half width of " + std::to_string(mesh_half_width) +
        " m along the gap normal, the deck's Box \"Size\" " + std::to_string(geometry.half_width) +
        " m (another mesh, kiln --mesh?); the deck's is used\n";

  // Temperature: mean and spread over the nodes.
  double T_sum = 0.0, T_min = temperature.at(0), T_max = temperature.at(0);
  for (const double T : temperature.values)
  {
    T_sum += T;
    T_min = std::min(T_min, T);
    T_max = std::max(T_max, T);
  }
  const double T_mean = T_sum / static_cast<double>(n_nodes);
  const double dT = T_mean - material.reference_temperature();

  // The gap: its nodes are those with a gap opening (NaN elsewhere).
  std::vector<double> gap_pressure, gap_opening;
  std::size_t n_gap = 0, n_active = 0;
  for (std::size_t n = 0; n < n_nodes; ++n)
  {
    if (std::isnan(opening.at(n)))
      continue;
    ++n_gap;
    n_active += active.at(n) > 0.5 ? 1 : 0;
    gap_pressure.push_back(pressure.at(n));
    gap_opening.push_back(opening.at(n));
  }
  if (n_gap == 0)
    throw ReportError(o.results + ": " + step +
                      "/gap_opening is NaN at every node: the mesh has no gap");

  // A material whose elastic constants or expansion depend on T is evaluated at the mean
  // temperature of the last step (the uniform state's).
  const bool constant = material.elastically_constant();
  std::cout << "kiln_contact_box_report: " << o.results << " vs the uniform states of "
            << "the contact-box spec\n"
            << "  deck " << o.deck << ": E = " << sci(material.youngs_modulus(T_mean), 4)
            << " Pa, nu = " << material.poissons_ratio(T_mean)
            << ", alpha = " << sci(material.thermal_expansion(T_mean), 4) << " 1/K"
            << (constant ? "" : " (at the mean T, " + sci(T_mean, 6) + " K: they depend on T)")
            << ", T_ref = " << material.reference_temperature() << " K\n"
            << "  mesh " << geometry.mesh << ": phi = " << geometry.phi
            << ", theta = " << geometry.theta << " degrees (" << geometry.angles_from
            << "), half width " << geometry.half_width << " m, " << n_cells << " cells, " << n_nodes
            << " nodes\n"
            << width_note << "\n";

  const std::size_t pairs = n_gap / 2, pairs_active = n_active / 2;
  const bool closed = n_active == n_gap, open = n_active == 0;
  char T_text[96];
  std::snprintf(T_text, sizeof T_text, "T = %.6f K (spread %.1e K)", T_mean, T_max - T_min);
  std::cout << "contact box at t = " << time << " s: gap "
            << (closed ? "closed"
                : open ? "open"
                       : "partly closed")
            << " (" << pairs_active << " of " << pairs << " pairs in contact), " << T_text << "\n";
  if (!closed && !open)
  {
    std::cout << "  the spec's analytic solution covers only the closed and the open gap: "
                 "nothing to compare\n";
    return 0;
  }
  if (closed ? dT <= 0.0 : dT >= 0.0)
    std::cout << "  note: dT = T - T_ref = " << dT << " K; the spec's "
              << (closed ? "closed" : "open") << " state has dT " << (closed ? "> 0" : "< 0")
              << "\n";

  const ExactState exact = exact_state(closed, material, T_mean, geometry.half_width, A);
  double stress_scale = 0.0, strain_scale = 0.0;
  for (int k = 0; k < 6; ++k)
  {
    stress_scale = std::max(stress_scale, std::abs(exact.stress[k]));
    strain_scale = std::max(strain_scale, std::abs(exact.strain[k]));
  }

  std::cout << "  " << padded("quantity", 26) << padded("Kiln (min .. max over cells)", 34)
            << padded("exact", 17) << "max rel. error\n";
  std::vector<double> column(n_cells);
  for (int k = 0; k < 6; ++k)
  {
    for (std::size_t c = 0; c < n_cells; ++c)
      column[c] = stress.at(c, k);
    print_row(std::string("sigma' ") + voigt_names[k] + " [Pa]", column, exact.stress[k],
              stress_scale, "Pa");
  }
  for (int k = 0; k < 6; ++k)
  {
    for (std::size_t c = 0; c < n_cells; ++c)
      column[c] = strain.at(c, k);
    print_row(std::string("eps' ") + voigt_names[k] + " [-]", column, exact.strain[k],
              strain_scale);
  }
  print_row("contact pressure [Pa]", gap_pressure, exact.contact_pressure, stress_scale, "Pa");
  print_row("gap opening [m]", gap_opening, exact.gap_opening, 0.0, "m");
  char dT_text[48];
  std::snprintf(dT_text, sizeof dT_text, "%.6f K", dT);
  std::cout << "  (mesh frame, Voigt order, tensor shear strains; gap rows over the " << n_gap
            << " gap nodes; error:\n"
            << "   max |Kiln - exact| / largest exact component of the tensor (the stress's for "
            << "the\n"
            << "   contact pressure, > 0 in compression), absolute for the gap opening; exact\n"
            << "   state at dT = mean T - T_ref = " << dT_text
            << (constant ? "" : ", the material's E, nu and alpha at the mean T") << ")\n";
  return 0;
}
} // namespace

int main(int argc, char **argv)
{
  const std::string program = "kiln_contact_box_report";
  Options options;
  try
  {
    options = parse_command_line({argv + 1, argv + argc});
  }
  catch (const std::invalid_argument &e)
  {
    std::cerr << program << ": " << e.what() << "\n"
              << "usage: " << program << " [--phi DEG] [--theta DEG] DECK.xml RESULTS.h5\n";
    return 2;
  }
  try
  {
    return report(options);
  }
  catch (const std::exception &e) // ReportError, kiln::InputError, Teuchos' exceptions
  {
    std::cout.flush();
    std::cerr << program << ": error: " << e.what() << "\n";
    return 1;
  }
}
