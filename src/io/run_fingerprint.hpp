#pragma once
/// What identifies a run: a checkpoint continues only its own run, and results are appended to
/// only by their own run.
#include "discretization/dof_manager.hpp"
#include "mesh/mesh.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <utility>
#include <vector>

namespace kiln
{
/// What a checkpoint must match to continue a run: the mesh (its sizes and a hash of its
/// coordinates, cells, blocks and gap), the unknowns (the layout) and the blocks of the input
/// that define the problem (Physics, Mesh, Material, Materials, Thermal, Mechanics). The time
/// stepping, solver, output and checkpoint blocks may change on a restart.
struct RunFingerprint
{
  int n_nodes = 0;
  int n_cells = 0;
  int n_pairs = 0;
  int gap_side_set = 0;
  std::string mesh_hash; ///< 16 hex digits
  std::string layout;    ///< e.g. "temperature displacement contact"
  /// (block path, the block as validated, in XML), in input order.
  std::vector<std::pair<std::string, std::string>> physics;

  /// The fingerprint of a run: its split mesh, layout and validated input ("Kiln").
  static RunFingerprint of(const Mesh &mesh, const DofLayout &layout,
                           const Teuchos::ParameterList &validated_input);
  /// What differs between this run and a checkpoint's `saved` one, or "" if nothing.
  std::string difference(const RunFingerprint &saved) const;
  /// All of it in 16 hex digits, for files that only need to know whether two runs are the
  /// same (the results' attribute run_fingerprint).
  std::string digest() const;
};
} // namespace kiln
