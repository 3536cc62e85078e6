#include "discretization/nodal_constraints.hpp"

#include "base/errors.hpp"
#include "discretization/assembler.hpp"
#include "discretization/element_values.hpp"
#include "mesh/hex_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace kiln
{
namespace
{
/// The dual basis of q: t_k with q_j . t_k = delta_jk (t_0 = q_1 x q_2 / det, and cyclic).
std::array<Point, 3> dual_basis(const std::array<Point, 3> &q)
{
  std::array<Point, 3> t{};
  for (int k = 0; k < 3; ++k)
  {
    const Point &a = q[(k + 1) % 3], &b = q[(k + 2) % 3];
    t[k] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }
  const double det = dot(q[0], t[0]);
  for (Point &v : t)
    for (double &x : v)
      x /= det;
  return t;
}
} // namespace

NodalConstraints::NodalConstraints(const Mesh &mesh, const DofManager &dofs)
    : mesh_(mesh), dofs_(dofs), F_(dofs.n_node_fields()), T_slot_(dofs.layout().slot(Field::T)),
      u_slot_(dofs.layout().slot(Field::ux)), temperature_value_(mesh.n_nodes(), -1),
      prescribed_temperature_(mesh.n_nodes(), 0.0), temperature_scale_(mesh.n_nodes(), 0.0),
      frame_of_node_(mesh.n_nodes(), -1), displacement_scale_(mesh.n_nodes(), 0.0)
{
}

int NodalConstraints::add_value(const std::string &name, TimeValue value)
{
  values_.push_back(std::move(value));
  value_names_.push_back(name);
  return static_cast<int>(values_.size()) - 1;
}

void NodalConstraints::constrain_temperature(const int node, const int value)
{
  KILN_ASSERT(!closed_ && T_slot_ >= 0, "constrain_temperature() after close() or without T");
  if (temperature_value_[node] < 0)
    temperature_value_[node] = value;
}

NodalConstraints::Frame &NodalConstraints::frame_of(const int node)
{
  if (frame_of_node_[node] < 0)
  {
    frame_of_node_[node] = static_cast<int>(frames_.size());
    frames_.emplace_back();
  }
  return frames_[frame_of_node_[node]];
}

void NodalConstraints::constrain_direction(const int node, const Point &n, const int value)
{
  KILN_ASSERT(!closed_ && u_slot_ >= 0, "constrain_direction() after close() or without u");
  Frame &frame = frame_of(node);
  KILN_ASSERT(frame.n_free == 0, "a constraint added after a free axis at node " << node);
  if (frame.basis.size() < 3 && append_orthonormal(frame.basis, n))
  {
    frame.axes.push_back(frame.basis.back());
    frame.value[frame.n_constrained] = value;
    frame.n[frame.n_constrained] = n;
    ++frame.n_constrained;
  }
}

std::vector<NodalConstraints::Direction> NodalConstraints::directions(const int node) const
{
  std::vector<Direction> result;
  if (frame_of_node_[node] < 0)
    return result;
  const Frame &frame = frames_[frame_of_node_[node]];
  for (int l = 0; l < frame.n_constrained; ++l)
    result.push_back({closed_ ? frame.q[l] : frame.basis[l], frame.n[l], frame.value[l]});
  return result;
}

int NodalConstraints::add_free_axis(const int node, const Point &n, const bool complete)
{
  KILN_ASSERT(!closed_ && u_slot_ >= 0, "add_free_axis() after close() or without u");
  Frame &frame = frame_of(node);
  std::vector<Point> basis = frame.basis;
  if (basis.size() >= 3 || !append_orthonormal(basis, n))
    return -1;
  // n made orthogonal to all the axes so far (as before the frames could lean) ...
  Point axis = basis.back();
  if (!complete)
  {
    // ... or to the constrained directions only, where n leans to the free axes there: the
    // frame is then not orthonormal (doc/contact.md, "Gaps that cross").
    std::vector<Point> held(frame.basis.begin(), frame.basis.begin() + frame.n_constrained);
    if (!append_orthonormal(held, n))
      return -1;
    const Point &free = held.back();
    // axis is the part of `free` off the span of the other axes: their dot is the sine of the
    // angle between `free` and that span.
    const double sine = dot(axis, free);
    if (sine < 1.0 - 1e-12)
    {
      if (sine < min_sine)
        return -1;
      axis = free;
      frame.orthonormal = false;
    }
  }
  frame.basis = std::move(basis);
  frame.axes.push_back(axis);
  ++frame.n_free;
  return static_cast<int>(frame.axes.size()) - 1;
}

const Point &NodalConstraints::frame_axis_so_far(const int node, const int slot) const
{
  KILN_ASSERT(!closed_ && has_frame(node), "frame_axis_so_far() after close() or without a frame");
  return frames_[frame_of_node_[node]].axes.at(slot);
}

void NodalConstraints::close(const double conductivity, const double modulus)
{
  for (Frame &frame : frames_)
  {
    for (int d = 0; d < 3 && frame.basis.size() < 3; ++d)
    {
      Point e{};
      e[d] = 1.0;
      if (append_orthonormal(frame.basis, e))
        frame.axes.push_back(frame.basis.back());
    }
    std::copy(frame.axes.begin(), frame.axes.end(), frame.q.begin());
    // Released, not cleared: clear() keeps their capacity, two heap blocks per frame for the
    // whole run (about 0.7 MB at the box's 20^3, its rollers and gap nodes).
    std::vector<Point>().swap(frame.basis);
    std::vector<Point>().swap(frame.axes);
    frame.t = frame.orthonormal ? frame.q : dual_basis(frame.q);
  }
  closed_ = true;
  const std::vector<double> sums = stiffness_sums();
  for (int n = 0; n < mesh_.n_nodes(); ++n)
  {
    if (has_temperature(n))
      temperature_scale_[n] = conductivity * sums[n];
    if (has_frame(n))
      displacement_scale_[n] = modulus * sums[n];
  }
}

std::vector<double> NodalConstraints::stiffness_sums() const
{
  std::vector<double> sum(mesh_.n_nodes(), 0.0);
  ElementValues fe;
  const auto constrained = [&](const int n) { return has_temperature(n) || has_frame(n); };
  for (int c = 0; c < mesh_.n_cells(); ++c)
  {
    const Span<const int> nodes = mesh_.cell_nodes(c);
    if (std::none_of(nodes.begin(), nodes.end(), constrained))
      continue;
    fe.reinit(mesh_, c);
    for (int i = 0; i < nodes.size(); ++i)
      if (constrained(nodes[i]))
        for (int q = 0; q < fe.n_qpoints(); ++q)
          sum[nodes[i]] += dot(fe.grad(i, q), fe.grad(i, q)) * fe.JxW(q);
  }
  return sum;
}

void NodalConstraints::set_time(const double t)
{
  for (int n = 0; n < mesh_.n_nodes(); ++n)
    if (has_temperature(n))
      prescribed_temperature_[n] = values_[temperature_value_[n]](t);
  for (Frame &frame : frames_)
    frame.prescribed = prescribed_components(frame, t);
}

void NodalConstraints::hold_temperature(const Tpetra::Vector<> *x)
{
  held_.clear();
  holds_temperature_ = x != nullptr && T_slot_ >= 0;
  if (!holds_temperature_)
    return;
  const auto values = x->getData();
  for (std::size_t i = 0; i < dofs_.owned_nodes().size(); ++i)
    held_.push_back(values[F_ * i + T_slot_]);
}

const std::array<Point, 3> &NodalConstraints::axes(const int node) const
{
  static const std::array<Point, 3> identity = {Point{1, 0, 0}, Point{0, 1, 0}, Point{0, 0, 1}};
  return has_frame(node) ? frames_[frame_of_node_[node]].q : identity;
}

const std::array<Point, 3> &NodalConstraints::dual_axes(const int node) const
{
  return has_frame(node) ? frames_[frame_of_node_[node]].t : axes(node);
}

bool NodalConstraints::orthonormal(const int node) const
{
  return !has_frame(node) || frames_[frame_of_node_[node]].orthonormal;
}

int NodalConstraints::n_constrained(const int node) const
{
  return has_frame(node) ? frames_[frame_of_node_[node]].n_constrained : 0;
}

double NodalConstraints::prescribed_temperature(const int node, const double t) const
{
  return values_[temperature_value_[node]](t);
}

std::array<double, 3> NodalConstraints::prescribed_components(const int node, const double t) const
{
  return has_frame(node) ? prescribed_components(frames_[frame_of_node_[node]], t)
                         : std::array<double, 3>{};
}

std::array<double, 3> NodalConstraints::prescribed_components(const Frame &frame,
                                                              const double t) const
{
  // n_l . u = g_l with u = sum_k û_k t_k, where t_k = q_k for the constrained axes k < m (they
  // are orthonormal and orthogonal to the others) and n_l . t_k = 0 for k > l: forward
  // substitution.
  KILN_ASSERT(closed_, "prescribed values before close()");
  const auto &q = frame.q;
  std::array<double, 3> u_hat{};
  for (int l = 0; l < frame.n_constrained; ++l)
  {
    double g = values_[frame.value[l]](t);
    for (int k = 0; k < l; ++k)
      g -= dot(frame.n[l], q[k]) * u_hat[k];
    u_hat[l] = g / dot(frame.n[l], q[l]);
  }
  return u_hat;
}

double NodalConstraints::temperature(const int node, const double *unknowns) const
{
  return has_temperature(node) ? prescribed_temperature_[node] : unknowns[T_slot_];
}

Point NodalConstraints::displacement(const int node, const double *unknowns) const
{
  Point u_hat{unknowns[u_slot_], unknowns[u_slot_ + 1], unknowns[u_slot_ + 2]};
  if (!has_frame(node))
    return u_hat;
  const Frame &frame = frames_[frame_of_node_[node]];
  for (int k = 0; k < frame.n_constrained; ++k)
    u_hat[k] = frame.prescribed[k];
  Point u{};
  for (int d = 0; d < 3; ++d)
    u[d] = frame.t[0][d] * u_hat[0] + frame.t[1][d] * u_hat[1] + frame.t[2][d] * u_hat[2];
  return u;
}

void NodalConstraints::distribute(const std::vector<int> &nodes, LocalSystem &local) const
{
  const int n_local = local.n_nodes();
  const bool jacobian = local.has_jacobian();
  if (u_slot_ >= 0)
    for (int i = 0; i < n_local; ++i)
    {
      if (!has_frame(nodes[i]))
        continue;
      const auto &q = frames_[frame_of_node_[nodes[i]]].t;
      // Rows: R̂_k = t_k . R; columns: dR/dû_k = dR/du . t_k (t = q where orthonormal).
      Point r{};
      for (int k = 0; k < 3; ++k)
        for (int d = 0; d < 3; ++d)
          r[k] += q[k][d] * local.residual(u_slot_ + d, i);
      for (int k = 0; k < 3; ++k)
        local.residual(u_slot_ + k, i) = r[k];
      if (!jacobian)
        continue;
      for (int j = 0; j < n_local; ++j)
        for (int fj = 0; fj < F_; ++fj)
        {
          Point row{};
          for (int k = 0; k < 3; ++k)
            for (int d = 0; d < 3; ++d)
              row[k] += q[k][d] * local.jacobian(u_slot_ + d, i, fj, j);
          for (int k = 0; k < 3; ++k)
            local.jacobian(u_slot_ + k, i, fj, j) = row[k];
        }
      for (int j = 0; j < n_local; ++j)
        for (int fj = 0; fj < F_; ++fj)
        {
          Point column{};
          for (int k = 0; k < 3; ++k)
            for (int d = 0; d < 3; ++d)
              column[k] += local.jacobian(fj, j, u_slot_ + d, i) * q[k][d];
          for (int k = 0; k < 3; ++k)
            local.jacobian(fj, j, u_slot_ + k, i) = column[k];
        }
    }
  const auto eliminate = [&](const int field, const int i, const bool column)
  {
    local.residual(field, i) = 0.0;
    if (!jacobian)
      return;
    for (int j = 0; j < n_local; ++j)
      for (int fj = 0; fj < F_; ++fj)
      {
        local.jacobian(field, i, fj, j) = 0.0;
        if (column)
          local.jacobian(fj, j, field, i) = 0.0;
      }
  };
  for (int i = 0; i < n_local; ++i)
  {
    if (T_slot_ >= 0 && (has_temperature(nodes[i]) || !held_.empty()))
      eliminate(T_slot_, i, has_temperature(nodes[i]));
    for (int k = 0; k < n_constrained(nodes[i]); ++k)
      eliminate(u_slot_ + k, i, true);
  }
}

void NodalConstraints::add_rows(const Tpetra::Vector<> &x_overlap, Assembler &assembler,
                                const bool jacobian) const
{
  const auto x = x_overlap.getData();
  LocalSystem local(1, 1, jacobian);
  const auto add_row = [&](const LO lid, const double scale, const double value)
  {
    local.clear();
    local.residual(0, 0) = scale * (x[lid] - value);
    if (jacobian)
      local.jacobian(0, 0, 0, 0) = scale;
    assembler.add({lid}, local);
  };
  const auto &owned_nodes = dofs_.owned_nodes();
  for (std::size_t i = 0; i < owned_nodes.size(); ++i)
  {
    const int n = owned_nodes[i];
    if (T_slot_ >= 0 && !held_.empty())
      add_row(assembler.lid(dofs_.dof(n, Field::T)), 1.0, held_[i]);
    else if (T_slot_ >= 0 && has_temperature(n))
      add_row(assembler.lid(dofs_.dof(n, Field::T)), temperature_scale_[n],
              prescribed_temperature_[n]);
    if (!has_frame(n))
      continue;
    const Frame &frame = frames_[frame_of_node_[n]];
    for (int k = 0; k < frame.n_constrained; ++k)
      add_row(assembler.lid(dofs_.node_dof(n, u_slot_ + k)), displacement_scale_[n],
              frame.prescribed[k]);
  }
}
} // namespace kiln
