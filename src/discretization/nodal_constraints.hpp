#pragma once
/// Every constraint on nodal unknowns in one place, applied when a local system is added:
/// Kiln's counterpart of deal.II's AffineConstraints (distribute_local_to_global).
#include "discretization/dof_manager.hpp"
#include "discretization/local_system.hpp"
#include "mesh/mesh.hpp"

#include <Tpetra_Vector.hpp>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace kiln
{
class Assembler;

/// The constraints on the unknowns of the nodes (the DofManager's layout: T, u_x, u_y, u_z):
/// - a prescribed temperature T = g(t) at a node;
/// - prescribed displacement directions n.u = g(t) at a node (rollers, a prescribed normal
///   motion, components), up to three in the order given; a direction in the span of the
///   node's earlier ones is dropped (the first condition given applies);
/// - free axes: a direction n whose component n.u must be an unknown of its own (the gap
///   normal of contact), placed right after the node's constrained directions;
/// - held temperatures: T = T_held at every node (the temperature frozen for an equilibrium
///   solve of the displacement).
///
/// How they enter (doc/mechanics.md, "Exact constraints"). A node with displacement
/// constraints or free axes has a frame of axes q_0, q_1, q_2: its constrained directions
/// (Gram-Schmidt in the order given), its free axes, then the coordinate axes. Its unknowns are
/// û_k = q_k . u, so u = sum_k û_k t_k with t the dual basis (q_j . t_k = delta_jk), and its
/// rows are t_k . R (Galerkin: the Jacobian stays symmetric). A free axis is made orthogonal
/// to the constrained directions only, so the free axes of a node need not be perpendicular
/// (gaps that cross at an angle, doc/contact.md); the completion is orthogonal to all. Where
/// the axes are orthonormal (most frames), t = q and û = Q^T u. Every row is evaluated at
/// x~, x with each constrained unknown replaced by its prescribed value (temperature(),
/// displacement()); a constrained row is s (x_c - g_c(t)) with s a stiffness scale of the node
/// (add_rows()); distribute() removes the rows and columns of constrained unknowns from each
/// local system, so dF/dx has no entries in the constrained columns and the elimination is
/// symmetric. A held temperature keeps its columns and the state sees x; its row becomes
/// x_T - T_held.
class NodalConstraints
{
public:
  /// A prescribed value g(t) [K or m] at time t [s].
  using TimeValue = std::function<double(double)>;

  NodalConstraints(const Mesh &mesh, const DofManager &dofs);

  // --- Set-up, before close() --------------------------------------------------------------
  /// Registers the value of a condition, `name`d for messages; returns its id.
  int add_value(const std::string &name, TimeValue value);
  /// T = value(t) at `node`; a node keeps the first temperature it is given.
  void constrain_temperature(int node, int value);
  /// n.u = value(t) at `node` (n a unit vector); dropped if n lies in the span of the node's
  /// earlier directions (within 1e-6) or the node has three already.
  void constrain_direction(int node, const Point &n, int value);
  /// A constrained direction of a node: its frame axis, the direction n given and its value.
  struct Direction
  {
    Point axis;
    Point n;
    int value;
  };
  /// The node's constrained directions, in order.
  std::vector<Direction> directions(int node) const;
  /// Makes n.u at `node` an unknown of its own: the node's frame gets n, made orthogonal to
  /// its constrained directions (and with `complete` to all its axes so far, as close()
  /// completes a frame), as its next axis. Returns the slot of that unknown among the node's
  /// displacement unknowns, or -1 if the frame is full or n lies in the span of its axes so
  /// far: within 1e-6 (of its length) for a `complete` axis or one perpendicular to the
  /// others, within `min_sine` (the sine of the angle between n and that span) for one that
  /// leans to the free axes already there.
  int add_free_axis(int node, const Point &n, bool complete = false);
  /// The smallest sine of the angle between a leaning free axis and the span of the node's
  /// other axes (add_free_axis()): below it the directions are taken as dependent.
  static constexpr double min_sine = 1e-3;
  /// Before close(): axis `slot` of the node's frame so far (its constrained directions and
  /// free axes); `slot` was returned by add_free_axis().
  const Point &frame_axis_so_far(int node, int slot) const;
  /// Completes every frame with the coordinate axes and sets the scales of the constraint
  /// rows, s = c ∫|∇φ_i|^2 dΩ with c the conductivity k [W/(m K)] for a temperature and the
  /// modulus lambda + 2G [Pa] for a displacement.
  void close(double conductivity, double modulus);

  // --- Time --------------------------------------------------------------------------------
  /// The prescribed values of every constraint at t [s] for the next evaluations.
  void set_time(double t);
  /// Holds every temperature at its value in x (owned unknowns); nullptr releases it.
  void hold_temperature(const Tpetra::Vector<> *x);
  /// Whether the temperatures are held (hold_temperature() with a vector).
  bool holds_temperature() const { return holds_temperature_; }

  // --- Use ---------------------------------------------------------------------------------
  /// The name of a value (its condition).
  const std::string &value_name(const int value) const { return value_names_[value]; }
  bool has_temperature(const int node) const { return temperature_value_[node] >= 0; }
  bool has_frame(const int node) const { return frame_of_node_[node] >= 0; }
  /// The frame axes q_k of a node, û_k = q_k . u (the coordinate axes if it has no frame).
  const std::array<Point, 3> &axes(int node) const;
  /// The dual axes t_k of a node, u = sum_k û_k t_k and rows t_k . R (q_j . t_k = delta_jk;
  /// the same as axes() where those are orthonormal).
  const std::array<Point, 3> &dual_axes(int node) const;
  /// Whether the node's frame axes are orthonormal (true without a frame).
  bool orthonormal(int node) const;
  /// The number of constrained displacement directions of a node.
  int n_constrained(int node) const;
  /// The prescribed temperature of a node at t [K] (it must have one).
  double prescribed_temperature(int node, double t) const;
  /// The prescribed û_0..û_{m-1} of a node at t [m] (zero beyond its constraints).
  std::array<double, 3> prescribed_components(int node, double t) const;

  /// The physical temperature [K] of mesh node `node` from its unknowns (x at the node's
  /// first unknown): the prescribed value where constrained.
  double temperature(int node, const double *unknowns) const;
  /// The physical displacement u = sum_k û~_k t_k [m] of mesh node `node` from its unknowns, with
  /// the constrained components at their prescribed values.
  Point displacement(int node, const double *unknowns) const;

  /// Turns the displacement rows and columns of framed nodes into their frames (t_k . R,
  /// dR/du t_k), then
  /// removes the rows and columns of constrained unknowns and the rows of held ones;
  /// nodes[i] is the mesh node of local node i.
  void distribute(const std::vector<int> &nodes, LocalSystem &local) const;
  /// Adds the constraint rows of the owned nodes: s (x_c - g_c) and x_T - T_held.
  void add_rows(const Tpetra::Vector<> &x_overlap, Assembler &assembler, bool jacobian) const;

private:
  struct Frame
  {
    std::vector<Point> basis;           ///< while set up: an orthonormal basis of the axes' span
    std::vector<Point> axes;            ///< while set up: the axes so far
    std::array<Point, 3> q{};           ///< the axes, û_k = q_k . u; q[0..m) the constrained ones
    std::array<Point, 3> t{};           ///< the dual axes, u = sum_k û_k t_k
    bool orthonormal = true;            ///< q orthonormal (then t = q)
    int n_constrained = 0;              ///< m
    int n_free = 0;                     ///< free axes after the constrained ones
    std::array<int, 3> value{};         ///< the value of constraint l
    std::array<Point, 3> n{};           ///< the direction of constraint l
    std::array<double, 3> prescribed{}; ///< û_0..û_{m-1} at the set time [m]
  };
  Frame &frame_of(int node);
  std::array<double, 3> prescribed_components(const Frame &frame, double t) const;
  /// ∫|∇φ_i|^2 dΩ [m] of every node with a constraint.
  std::vector<double> stiffness_sums() const;

  const Mesh &mesh_;
  const DofManager &dofs_;
  int F_;
  int T_slot_;
  int u_slot_;
  std::vector<TimeValue> values_;
  std::vector<std::string> value_names_;
  std::vector<int> temperature_value_;         ///< per mesh node: a value id, or -1
  std::vector<double> prescribed_temperature_; ///< per mesh node, at the set time [K]
  std::vector<double> temperature_scale_;      ///< per mesh node [W/K]
  std::vector<int> frame_of_node_;             ///< per mesh node: index into frames_, or -1
  std::vector<Frame> frames_;
  std::vector<double> displacement_scale_; ///< per mesh node [N/m]
  std::vector<double> held_;               ///< per owned node [K]; empty if none held
  bool holds_temperature_ = false;
  bool closed_ = false;
};
} // namespace kiln
