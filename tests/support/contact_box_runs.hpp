#pragma once
/// Whole runs of the contact box (../shared/spec/contact-box.md) in the verification tests: a
/// deck of inputs/ with tight tolerances on the generated or the Cubit mesh, its run, and the
/// checks of an output step against a uniform state of the spec (every node's temperature and
/// displacement, every cell's stress, strain and thermal strain, every gap node's pressure and
/// opening) or against a closed or open gap.
#include "mesh/mesh.hpp"
#include "support/contact_box.hpp"

#include <Teuchos_ParameterList.hpp>

#include <limits>
#include <string>
#include <vector>

namespace kiln_test
{
enum class MeshKind
{
  generated, ///< the deck's own Box
  cubit      ///< ../shared/meshes/rotated-cube.exo
};

std::string mesh_name(MeshKind mesh);

/// inputs/<deck> (or the deck at the path `deck`, if it has a '/') with its results at `base` at
/// the given output times, on the mesh asked for;
/// Newton to 1e-12 relative and 1e-11 absolute, GMRES to 1e-13, steps of at most 2 s.
Teuchos::ParameterList contact_box_deck(const std::string &deck, MeshKind mesh,
                                        const std::string &base, const std::vector<double> &times);

/// What a run leaves for the checks (the output file is closed when it returns).
struct Run
{
  kiln::Mesh mesh;
  std::size_t n_gap_pairs = 0;
  /// Rows of the contact pairs (Mechanics/Contact/Pairs): a node each in the output.
  std::size_t n_pair_rows = 0;
  double seconds = 0.0;
};

/// Runs a deck (collective), prints its run time, expects a split gap (with `split_gap`; the
/// halves meshed apart have none).
Run run(const Teuchos::ParameterList &input, const std::string &label, bool split_gap = true);

/// One output step of BASE.h5 (rank 0 reads it).
struct OutputStep
{
  double time = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> temperature, displacement, stress, strain, thermal_strain;
  std::vector<double> gap_opening, contact_pressure, contact_active;
};

OutputStep read_output_step(const std::string &h5, int step);

inline constexpr double closed_opening_tolerance = 1e-12; // [m]

/// Output step `step` (at `time`): every gap pair in contact (closed) or open. In contact:
/// contact_active 1, |gap_opening| < 1e-12 m, a positive (compressive) contact pressure; open:
/// contact_active 0, gap_opening > 0, pressure 0.
void check_gap(const std::string &label, const std::string &h5, int step, double time, bool closed,
               const Run &r);

/// The tolerances of check_uniform_state.
struct StateTolerance
{
  double relative;    ///< tensors, displacement, contact pressure and opening (see below)
  double zero_stress; ///< [Pa] stress components whose exact value is 0
  double zero_strain; ///< strain and thermal strain components whose exact value is 0
  double temperature; ///< [K] every node's |T - T_exact|
};

/// Output step `step` (at `time`) is the uniform state `exact` at temperature T: every node's
/// temperature to tolerance.temperature, every cell's stress, strain and thermal strain to
/// tolerance.relative of the tensor's largest component (zero_stress, zero_strain where 0),
/// every node's displacement to `relative` of the largest, and at every gap node the state of
/// the gap (contact_active 1, |gap_opening| < 1e-12 m and the traction to `relative` when
/// closed; contact active 0, the opening to `relative` and traction 0 when open).
void check_uniform_state(const std::string &label, const std::string &h5, int step, double time,
                         double T, const UniformState &exact, bool closed,
                         const StateTolerance &tolerance, const Run &r);
/// The same with `rel` for tensors, displacement and gap, zero_stress_tolerance and
/// zero_strain_tolerance where 0, and the temperature to 1e-9 of |T - T_ref| (the spec's).
void check_uniform_state(const std::string &label, const std::string &h5, int step, double time,
                         double T, const UniformState &exact, bool closed, double rel,
                         const Run &r);

/// The output of the contact pair "cut" (issue 30, item 5) in the results at `base` of a run of
/// the closing box meshed apart to 0, 50, 53, 150 s: its secondary surface /pair_cut (HDF5, the
/// XDMF grid, the CSV table) at 0 s open (g > 0, P = 0, not in contact) and at 150 s closed (P =
/// `pressure` to 1e-9, g 0 to round-off, in contact) at every node with a row; the history's
/// normal_force_cut and contact_area_cut: 0 at 0 s, P x 0.04^2 and 0.04^2 m^2 at 150 s to 1e-9.
/// Without `open_at_start`, nothing is checked at 0 s (where bodies held by nothing else along
/// the pair's normal touch at the minimum-norm solution, doc/contact.md).
void check_pair_output(const std::string &label, const std::string &base, double pressure,
                       bool open_at_start = true);

/// inputs/<deck> (a closing deck: contact-box-close.xml or the same box on other cells) to
/// 150 s with contact_box_deck's tolerances on the mesh asked for: the open-gap state at 0 s
/// (288 K), every pair open at 50 s, every pair closed at 53 s, the closed-gap state at 150 s
/// (308 K), the uniform states to 1e-9.
void check_closing_box(const std::string &deck, MeshKind mesh);
} // namespace kiln_test
