#pragma once
/// The local residual and Jacobian of one cell, face or gap-face pair:
/// n_nodes local nodes with n_fields unknowns each; local index
/// node * n_fields + field. Kernels add into it; the Assembler scatters it.
/// A system built for the residual alone has no Jacobian: kernels ask has_jacobian()
/// and skip its terms.
#include <algorithm>
#include <vector>

namespace kiln
{
class LocalSystem
{
public:
  LocalSystem(const int n_nodes, const int n_fields, const bool with_jacobian = true)
      : n_nodes_(n_nodes), n_fields_(n_fields), residual_(n_nodes * n_fields, 0.0),
        jacobian_(with_jacobian ? residual_.size() * residual_.size() : 0, 0.0),
        has_jacobian_(with_jacobian)
  {
  }
  void clear()
  {
    std::fill(residual_.begin(), residual_.end(), 0.0);
    std::fill(jacobian_.begin(), jacobian_.end(), 0.0);
  }
  /// Clears it for `n_nodes` nodes (a cell of another type: the buffers keep their capacity).
  void reset(const int n_nodes)
  {
    if (n_nodes != n_nodes_)
    {
      n_nodes_ = n_nodes;
      residual_.resize(static_cast<std::size_t>(n_nodes) * n_fields_);
      if (has_jacobian_)
        jacobian_.resize(residual_.size() * residual_.size());
    }
    clear();
  }
  int n_nodes() const { return n_nodes_; }
  int n_fields() const { return n_fields_; }
  int size() const { return static_cast<int>(residual_.size()); }
  int index(const int field, const int node) const { return node * n_fields_ + field; }
  /// Whether the system holds a Jacobian (false: the residual alone is wanted).
  bool has_jacobian() const { return has_jacobian_; }

  double &residual(const int field, const int i) { return residual_[index(field, i)]; }
  double &jacobian(const int field_i, const int i, const int field_j, const int j)
  {
    return jacobian_[index(field_i, i) * size() + index(field_j, j)];
  }
  const std::vector<double> &residual_values() const { return residual_; }
  std::vector<double> &residual_values() { return residual_; }
  /// Row-major, size() x size(); empty without a Jacobian.
  const std::vector<double> &jacobian_values() const { return jacobian_; }
  std::vector<double> &jacobian_values() { return jacobian_; }

private:
  int n_nodes_;
  int n_fields_;
  std::vector<double> residual_;
  std::vector<double> jacobian_;
  bool has_jacobian_;
};
} // namespace kiln
