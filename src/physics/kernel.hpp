#pragma once
/// The interfaces of the kernels. A kernel turns the state of one cell, boundary face or gap
/// face into local residual and Jacobian terms; its class comment states the weak form and
/// the Jacobian. It never touches Tpetra, MPI or the mesh: CoupledProblem gathers the state,
/// asks every kernel of a kind for the same LocalSystem and distributes the result. A system
/// without a Jacobian (LocalSystem::has_jacobian) asks for the residual alone.
#include "discretization/element_values.hpp"
#include "discretization/face_values.hpp"
#include "discretization/local_system.hpp"
#include "mesh/mesh.hpp"

#include <array>
#include <vector>

namespace kiln
{
/// Where a node's unknowns are in a LocalSystem: field slot T_slot (temperature) and u_slot ..
/// u_slot + 2 (displacement); -1 for a field the layout lacks.
struct FieldSlots
{
  int T = -1;
  int u = -1;
};

/// The past nodal temperatures of a cell that Tdot is made of, Tdot = a T + Σ_k weights[k]
/// T_past[k] (TransientProblem::set_time_history: x_n, and x_{n-1} with BDF2), one value per
/// cell node; n = 0 in a steady solve or where no kernel asked for them
/// (NodalFields::keep_history). A kernel that differentiates a nonlinear function of T in
/// time (the enthalpy) takes dH/dt = a H(T) + Σ_k weights[k] H(T_past[k]).
/// T_old: the temperatures of the last accepted state (t_n; NodalFields::set_accepted), one
/// per cell node, for the constitutive models' PointInput::temperature_old; null before an
/// accepted state or without a kernel that reads it.
struct TemperatureHistory
{
  int n = 0;
  std::array<double, 2> weights{};        ///< [1/s]
  std::array<const double *, 2> T_past{}; ///< [K], n_shape() values each
  const double *T_old = nullptr;          ///< [K], n_shape() values
};

/// One cell: its shape functions and the nodal fields (constrained unknowns at their
/// prescribed values), one local node per node of the cell, in its type's order.
struct CellState
{
  const ElementValues &fe;
  Span<const double> T;     ///< [K] (T_ref without a temperature)
  Span<const double> T_dot; ///< [K/s]
  Span<const Point> u;      ///< [m] (0 without a displacement)
  double dTdot_dT;          ///< a in Tdot = a T + b [1/s]
  double time;              ///< [s]
  FieldSlots slots;
  int cell = -1;       ///< its global index (mesh.block_id[cell]: its material's block)
  int cell_local = -1; ///< its index among the owned cells (QuadratureState's)
  TemperatureHistory history{};
};

class CellKernel
{
public:
  virtual ~CellKernel() = default;
  virtual void evaluate(const CellState &state, LocalSystem &local) const = 0;
  /// Whether the Jacobian of evaluate() depends on neither the state (T, u) nor the time,
  /// only (linearly) on the time-derivative coefficient a: then an unchanged Jacobian and
  /// its preconditioner are reused (doc/solvers.md). Default false, the safe answer: a new
  /// kernel whose Jacobian is constant says so by overriding it.
  virtual bool constant_jacobian() const { return false; }
};

/// One boundary face: one local node per face node, in ReferenceCell::face_nodes order.
struct FaceState
{
  const FaceValues &fv;
  Span<const double> T; ///< [K]
  Span<const Point> u;  ///< [m]
  double time;          ///< [s]
  FieldSlots slots;
};

class FaceKernel
{
public:
  virtual ~FaceKernel() = default;
  virtual void evaluate(const FaceState &state, LocalSystem &local) const = 0;
  /// As CellKernel::constant_jacobian().
  virtual bool constant_jacobian() const { return false; }
};

/// One gap face: the side-a face, its two cells and the local nodes the kernel asked for
/// (InterfaceKernel::nodes: the side-a face nodes, their twins, then any others).
struct InterfaceState
{
  const FaceValues &fv;         ///< the side-a face
  const ElementValues &fe_a;    ///< the side-a cell (set only if the kernel needs_cells())
  const ElementValues &fe_b;    ///< the side-b cell (likewise)
  Span<const int> cell_a;       ///< the local node of each node of cell a
  Span<const int> cell_b;       ///< likewise for cell b (-1 if absent)
  const std::vector<double> &T; ///< per local node [K]
  const std::vector<Point> &u;  ///< per local node [m]
  double time;                  ///< [s]
  FieldSlots slots;
  /// The global indices of cells a and b (mesh.block_id: their materials); -1 if not set.
  std::array<int, 2> cells{-1, -1};
};

class InterfaceKernel
{
public:
  virtual ~InterfaceKernel() = default;
  /// The nodes of the terms on a gap face: its side-a nodes (face_nodes order), their twins,
  /// then any other nodes the terms depend on.
  virtual std::vector<int> nodes(const Mesh &mesh, const GapFace &face) const;
  /// Whether evaluate() reads the cells' shape functions (InterfaceState::fe_a, fe_b).
  virtual bool needs_cells() const { return false; }
  /// Whether its temperature rows depend on the displacement (then the Jacobian's graph
  /// holds the T-u blocks: Couplings). Default true, the safe answer.
  virtual bool depends_on_displacement() const { return true; }
  virtual void evaluate(const InterfaceState &state, LocalSystem &local) const = 0;
  /// As CellKernel::constant_jacobian().
  virtual bool constant_jacobian() const { return false; }
};
} // namespace kiln
