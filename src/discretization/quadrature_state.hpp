#pragma once
/// State at quadrature points (issue 31, style.md §9; deal.II's CellDataStorage, MOOSE's old
/// and current material properties): what a constitutive model with state (plastic strain,
/// ...) keeps at each quadrature point of each cell from one time step to the next.
#include <string>
#include <vector>

namespace kiln
{
/// n_state() doubles at each quadrature point of each cell this rank owns, in two copies:
/// `old`, the state at t_n as last committed (an accepted step), which a model reads, and
/// `current`, the state at t_{n+1} it writes while Newton iterates. commit() (a step is
/// accepted) copies current to old; restore() (a step is rejected or retried) copies old to
/// current. The cells are this rank's owned cells, in DofManager::owned_cells() order (their
/// local index); each has its own number of points (0: a cell whose model has no state, or
/// a cell type of another quadrature), so the storage is the owned points alone, never the
/// whole mesh. The components have names (ConstitutiveModel::state_names()), by which a
/// checkpoint writes and reads them back (io/checkpoint).
class QuadratureState
{
public:
  /// `names`: the components (n_state() = names.size(), distinct); `cells`: the global index
  /// of each owned cell (DofManager::owned_cells()); `n_points`: the points of each (>= 0,
  /// as many as `cells`). Every value starts at 0 in both copies.
  QuadratureState(std::vector<std::string> names, std::vector<int> cells,
                  const std::vector<int> &n_points);

  int n_state() const { return static_cast<int>(names_.size()); }
  const std::vector<std::string> &names() const { return names_; }
  /// Owned cells (local indices 0 .. n_cells() - 1) and their global indices.
  int n_cells() const { return static_cast<int>(cells_.size()); }
  const std::vector<int> &cells() const { return cells_; }
  /// Points of the owned cell `cell_local`, and of all owned cells.
  int n_points(const int cell_local) const
  {
    return offsets_[cell_local + 1] - offsets_[cell_local];
  }
  int n_points() const { return offsets_.back(); }

  /// The n_state() values at point q of the owned cell `cell_local`, committed (t_n) and
  /// being computed (t_{n+1}).
  const double *old(const int cell_local, const int q) const
  {
    return old_.data() + index(cell_local, q);
  }
  double *current(const int cell_local, const int q)
  {
    return current_.data() + index(cell_local, q);
  }
  const double *current(const int cell_local, const int q) const
  {
    return current_.data() + index(cell_local, q);
  }

  /// An accepted step: old = current.
  void commit() { old_ = current_; }
  /// A rejected or retried step: current = old.
  void restore() { current_ = old_; }

  /// Component k (0 <= k < n_state()) of every owned point of the committed state, cell by
  /// cell (owned order) and point by point: what a checkpoint writes.
  std::vector<double> old_component(int k) const;
  /// Sets component k of every owned point, in the order of old_component(), in both copies
  /// (a restart).
  void set_component(int k, const std::vector<double> &values);

private:
  std::size_t index(const int cell_local, const int q) const
  {
    return static_cast<std::size_t>(offsets_[cell_local] + q) * names_.size();
  }

  std::vector<std::string> names_;
  std::vector<int> cells_;
  std::vector<int> offsets_; ///< per owned cell, its first point (CSR; n_cells() + 1)
  std::vector<double> old_;
  std::vector<double> current_;
};
} // namespace kiln
