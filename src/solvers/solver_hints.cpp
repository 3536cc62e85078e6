#include "solvers/solver_hints.hpp"

#include "mesh/mesh_bodies.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace kiln
{
SolverHints::SolverHints(const Mesh &mesh, const DofManager &dofs,
                         const NodalConstraints &constraints, const double conductivity,
                         const double modulus, const double thermal_expansion)
{
  const int F = dofs.n_node_fields();
  const int T_slot = dofs.layout().slot(Field::T);
  const int u_slot = dofs.layout().slot(Field::ux);
  // Symmetric scaling: with both fields, displacements by sqrt(k / (lambda + 2G)), so that
  // the diagonal of the force rows (~ (lambda + 2G) h) becomes that of the heat rows (~ k h).
  if (T_slot >= 0 && u_slot >= 0)
    displacement_scale_ = std::sqrt(conductivity / modulus);

  const auto owned_map = dofs.owned_dof_map();
  const auto &owned_nodes = dofs.owned_nodes();
  coordinates_ = Teuchos::rcp(new MultiVector(dofs.owned_node_map(), 3));
  Point centre{}, lowest = mesh.coordinates.front(), highest = lowest;
  for (const Point &x : mesh.coordinates)
    for (int d = 0; d < 3; ++d)
    {
      centre[d] += x[d] / mesh.n_nodes();
      lowest[d] = std::min(lowest[d], x[d]);
      highest[d] = std::max(highest[d], x[d]);
    }
  // MueLu's coordinates: body k moved by k times ten diagonals along x, so that its distance
  // Laplacian sees no coupling across a gap that separates bodies.
  const MeshBodies bodies = mesh_bodies(mesh);
  const Point extent{highest[0] - lowest[0], highest[1] - lowest[1], highest[2] - lowest[2]};
  const double body_spacing = 10.0 * std::sqrt(dot(extent, extent));
  const int n_modes = (T_slot >= 0 ? 1 : 0) + (u_slot >= 0 ? 6 : 0);
  near_null_space_ = Teuchos::rcp(new MultiVector(owned_map, n_modes));
  unknown_scale_ = Teuchos::rcp(new Vector(owned_map));
  time_error_mask_ = Teuchos::rcp(new Vector(owned_map));
  for (std::size_t i = 0; i < owned_nodes.size(); ++i)
  {
    const int n = owned_nodes[i];
    const Point &x = mesh.coordinates[n];
    for (int d = 0; d < 3; ++d)
      coordinates_->replaceLocalValue(static_cast<LO>(i), d, x[d]);
    coordinates_->sumIntoLocalValue(static_cast<LO>(i), 0,
                                    std::max(bodies.body[n], 0) * body_spacing);
    const LO row = static_cast<LO>(F * i);
    int mode = 0;
    if (T_slot >= 0)
    {
      near_null_space_->replaceLocalValue(row + T_slot, mode++, 1.0);
      unknown_scale_->replaceLocalValue(row + T_slot, 1.0);
      time_error_mask_->replaceLocalValue(row + T_slot, 1.0);
    }
    if (u_slot >= 0)
    {
      // Rigid-body modes in the node's unknowns (û_k = q_k . u where it has a frame, q its
      // axes: NodalConstraints::axes(), orthonormal or not).
      const Point r{x[0] - centre[0], x[1] - centre[1], x[2] - centre[2]};
      const std::array<Point, 6> modes = {Point{1, 0, 0},        Point{0, 1, 0},
                                          Point{0, 0, 1},        Point{0, -r[2], r[1]},
                                          Point{r[2], 0, -r[0]}, Point{-r[1], r[0], 0}};
      const bool framed = constraints.has_frame(n);
      const auto &q = constraints.axes(n);
      // The temperature mode moves the node by its free thermal expansion: with T and u
      // solved together, J (1, 0) is the thermal force of a uniform heating, as large as the
      // force rows' coupling to T, while J (1, alpha (x - centre)) vanishes in the rows of an
      // unheld homogeneous body. With (1, 0), smoothed aggregation of the whole system failed
      // where the coupling is strong (the shells of verification_pair_shells_closing).
      if (T_slot >= 0)
      {
        const Point expansion{thermal_expansion * r[0], thermal_expansion * r[1],
                              thermal_expansion * r[2]};
        for (int k = 0; k < 3; ++k)
          near_null_space_->replaceLocalValue(row + u_slot + k, 0,
                                              framed ? dot(q[k], expansion) : expansion[k]);
      }
      for (const Point &u : modes)
      {
        for (int k = 0; k < 3; ++k)
          near_null_space_->replaceLocalValue(row + u_slot + k, mode, framed ? dot(q[k], u) : u[k]);
        ++mode;
      }
      for (int k = 0; k < 3; ++k)
        unknown_scale_->replaceLocalValue(row + u_slot + k, displacement_scale_);
    }
  }
}
} // namespace kiln
