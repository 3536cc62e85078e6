#pragma once
/// Checkpoints: everything a run needs to continue exactly, in one HDF5 file
/// (doc/user-guide.md, "Checkpoints and restart").
#include "discretization/dof_manager.hpp"
#include "discretization/quadrature_state.hpp"
#include "io/run_fingerprint.hpp"
#include "solvers/time_stepper.hpp"

#include <Teuchos_Comm.hpp>

#include <string>
#include <vector>

namespace kiln
{
/// A checkpoint's content besides the time-integration state.
struct CheckpointInfo
{
  std::string kiln_version;
  std::string created;    ///< UTC, ISO 8601
  std::string input_path; ///< the input it ran with
  std::string input_xml;  ///< that input, as given
  int output_steps = 0;   ///< output steps up to its time (one due at its time included)
  /// Per gap pair (Mesh::gap_pairs order): 1 in contact, and the normal traction [Pa].
  std::vector<int> active;
  std::vector<double> traction;
  /// This rank's NewtonSolver::preconditioner_origin() (written for every rank; read back
  /// only on as many ranks, else empty).
  std::vector<double> preconditioner_origin;
  /// The rows of the contact pairs between bodies meshed apart as their last search left
  /// them (CoupledProblem::pair_rows_state()); empty without pairings.
  std::vector<double> pair_rows;
  /// The displacement of the surfaces of the pairs with a heat term at their last search, so
  /// that a restart rebuilds their heat cells (CoupledProblem::pair_heat_state()); empty
  /// without such pairs (or in a checkpoint of an older Kiln).
  std::vector<double> pair_heat_u;
};

/// Writes `state` (on the owned map of the unknowns), `info` and `fingerprint` to `path`:
/// rank 0 writes `path`.tmp and renames it when complete, so a crash never leaves a
/// truncated checkpoint in place of a good one. Throws InputError (on every rank) naming
/// the path if it cannot be written. Collective.
/// With `quadrature_state` (null on every rank or on none), its committed state goes into the
/// group quadrature_state: the points of every cell (points_per_cell, global cell order) and
/// one dataset per component, named as the component, of every point in global cell order
/// and point order, so that a run on any number of ranks reads it back.
void write_checkpoint(const std::string &path, const TimeStepper::State &state,
                      const CheckpointInfo &info, const RunFingerprint &fingerprint,
                      const Teuchos::Comm<int> &comm,
                      const QuadratureState *quadrature_state = nullptr);

/// A checkpoint read back.
struct Checkpoint
{
  TimeStepper::State state; ///< x, x_1, x_2 on the map given to read_checkpoint
  CheckpointInfo info;
  RunFingerprint fingerprint;
};

/// Reads a checkpoint of a run with the fingerprint `run`; the unknowns land on `map` (any
/// number of ranks). Throws InputError naming `path` for a missing, damaged (truncated) or
/// foreign file, another format version, or a checkpoint of another run (what differs, from
/// RunFingerprint::difference). Collective.
/// The state at quadrature points lands in `quadrature_state` (both copies; null on every rank
/// or on none: a run whose models have no state), by component name. An InputError naming
/// `path` if the checkpoint has none and the run needs it, lacks a component the run needs, has
/// one the run's models do not declare (a run never drops state it cannot continue exactly),
/// or gives a cell another number of points than this run.
Checkpoint read_checkpoint(const std::string &path, const RunFingerprint &run,
                           const Teuchos::RCP<const Map> &map, const Teuchos::Comm<int> &comm,
                           QuadratureState *quadrature_state = nullptr);

/// The version of the checkpoint format this Kiln writes and reads.
inline constexpr int checkpoint_format_version = 1;
} // namespace kiln
