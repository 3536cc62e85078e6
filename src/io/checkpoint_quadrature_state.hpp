#pragma once
/// Private to src/io: the state at quadrature points in a checkpoint, the group
/// quadrature_state: the points of every cell (points_per_cell, global cell order) and one
/// dataset per component, named as the component, of every point in global cell order and point
/// order, so that a run on any number of ranks reads it back.
#include "discretization/quadrature_state.hpp"

#include <Teuchos_Comm.hpp>
#include <hdf5.h>

#include <string>
#include <utility>
#include <vector>

namespace kiln
{
namespace internal
{
/// The number of points of every cell of the mesh (`n_cells`), from every rank's owned ones,
/// on every rank. Collective.
std::vector<int> points_per_cell(const QuadratureState &qs, int n_cells,
                                 const Teuchos::Comm<int> &comm);

/// Component by component, the committed state of every point on rank 0, in global cell and
/// point order (empty elsewhere); `points` from points_per_cell(). Collective.
std::vector<std::vector<double>> gather_quadrature_state(const QuadratureState &qs,
                                                         const std::vector<int> &points,
                                                         const Teuchos::Comm<int> &comm);

/// Rank 0: the group quadrature_state of `file`, with the components `names` gathered as
/// `components` (gather_quadrature_state()).
void write_quadrature_state(hid_t file, const std::vector<std::string> &names,
                            const std::vector<int> &points,
                            const std::vector<std::vector<double>> &components);

/// An error if the components (name, values written) of the group quadrature_state of `file`
/// read back differ from what was written (nothing to check for none).
void verify_quadrature_state(
    hid_t file, const std::vector<std::pair<std::string, const std::vector<double> *>> &components);

/// What a checkpoint holds of the state at quadrature points (read_checkpoint).
struct SavedQuadratureState
{
  bool present = false;
  std::vector<std::string> names;
  std::vector<int> points; ///< per cell, global order
  std::vector<std::vector<double>> components;
};

/// The group quadrature_state of `file`, if any (a mesh of `n_cells` cells); an error if it is
/// damaged.
SavedQuadratureState read_saved_quadrature_state(hid_t file, int n_cells);

/// `saved` (read from `path`, written by Kiln `version`) into `qs` (null: the run has no state),
/// checked against it: InputErrors on every rank naming `path`. Collective.
void restore_quadrature_state(const std::string &path, const std::string &version,
                              const SavedQuadratureState &saved, QuadratureState *qs,
                              const Teuchos::Comm<int> &comm);
} // namespace internal
} // namespace kiln
