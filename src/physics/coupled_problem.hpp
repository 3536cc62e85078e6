#pragma once
/// Heat conduction and quasi-static thermo-elasticity on the split mesh, in one residual
/// and one Jacobian, as a TransientProblem for the Newton solver and the time stepper.
#include "discretization/assembler.hpp"
#include "discretization/dof_manager.hpp"
#include "discretization/nonlinear_problem.hpp"
#include "mesh/mesh.hpp"
#include "physics/active_set_history.hpp"
#include "physics/boundary_input.hpp"
#include "physics/heat/contact_conductance_kernel.hpp"
#include "physics/heat/gap_conductance_kernel.hpp"
#include "physics/heat/heat_conduction_kernel.hpp"
#include "physics/heat/thermal_boundary_condition.hpp"
#include "physics/materials/material.hpp"
#include "physics/mechanics/elasticity_kernel.hpp"
#include "physics/mechanics/mechanical_boundary_condition.hpp"

#include <Teuchos_FancyOStream.hpp>
#include <Teuchos_ParameterList.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace kiln
{
/// F(x) = 0 for the unknowns of the DofManager's layout: temperature, displacement or both
/// (4 per node: T, then u_x, u_y, u_z).
///
/// Terms (each kernel's header gives its weak form and Jacobian):
/// - every owned cell: HeatConductionKernel (rows T) and ElasticityKernel (rows u, with the
///   thermal-expansion block dR_u/dT), body force rho g + f;
/// - owned faces of "Heat Flux", "Convection", "Traction" and "Pressure" conditions;
/// - gap faces whose side-a cell is owned: GapConductanceKernel;
/// - frictionless contact across the gap (Mechanics/Contact, doc/contact.md): per node pair
///   (a, b) with normal n (from a to b) and area A, the gap g = n.(u_b - u_a) and the
///   pressure p satisfy g >= 0, p >= 0, p g = 0, with the force -p A n on a and p A n on b.
///   The pressure is condensed: n.u is an unknown of each gap node (its frame has n after
///   its constraints); P = (R_b - R_a)/(2A) of the assembled normal rows without contact is
///   the pressure that balances the pair, and C(P, g) = P - max(0, P - c g) ("Min") or
///   Fischer-Burmeister decides. An open pair (P - c g <= 0) keeps its rows (p = 0); a
///   closed one has rows R_a + R_b (no p) and A c g. The Jacobian is the exact generalized
///   derivative of this F, row by row.
///
/// Exact constraints (temperature on "Temperature" side sets; u.n or u_c on "Normal
/// Displacement" and "Displacement" side sets, including edges and corners where several
/// meet):
/// - A node with displacement constraints has a frame Q = [q_0 q_1 q_2] (orthonormal, by
///   Gram-Schmidt of the constrained directions in input order, then the axes); its
///   unknowns in x are û = Q^T u, and û_0..û_{m-1} are the m constrained components. Rows
///   are rotated alike (Q^T R), so the Jacobian stays symmetric where the physics is.
/// - The residual of the other rows is evaluated at x~, x with every constrained unknown
///   replaced by its prescribed value; a constrained row is s (x_c - g_c(t)) with s a
///   stiffness scale of the node (k or lambda + 2G times ∫|∇φ|^2). So dF/dx has no
///   entries in the constrained columns either: it is the exact Jacobian of this F, and the
///   elimination is symmetric (CG works on elasticity). Where two conditions constrain the
///   same direction (or a temperature) at a node, the first listed applies.
class CoupledProblem final : public TransientProblem
{
public:
  /// The "Mechanics" block: Body Force, Gravity, Boundary Conditions.
  static Teuchos::ParameterList valid_mechanics_parameters();
  /// The "Contact" sublist of "Mechanics".
  static Teuchos::ParameterList valid_contact_parameters();
  /// The "Thermal" block: Initial Temperature, Gap Conductance, Boundary Conditions.
  static Teuchos::ParameterList valid_thermal_parameters();

  /// `thermal` and `mechanics` have been validated against the lists above; each is read if
  /// the layout has its field. `where` names the root in messages ("in.xml: Kiln").
  CoupledProblem(const Mesh &mesh, const DofManager &dofs, const Material &material,
                 const Teuchos::ParameterList &thermal, const Teuchos::ParameterList &mechanics,
                 const std::string &where);

  Teuchos::RCP<const Map> solution_map() const override { return dofs_.owned_dof_map(); }
  Teuchos::RCP<const Graph> jacobian_graph() const override { return assembler_.owned_graph(); }
  Teuchos::RCP<const Tpetra::MultiVector<double>> node_coordinates() const override
  {
    return coordinates_;
  }
  Teuchos::RCP<const Tpetra::MultiVector<double>> near_null_space() const override
  {
    return near_null_space_;
  }
  Teuchos::RCP<const Vector> unknown_scale() const override { return unknown_scale_; }
  Teuchos::RCP<const Vector> time_error_mask() const override { return time_error_mask_; }
  void evaluate(const Vector &x, Vector *f, Matrix *J) override;
  void set_time_derivative(double time, double a, const Vector &b) override;
  void step_accepted(double time) override;

  /// Log lines (active-set changes, the gap closing or opening) go to `out`.
  void set_log(Teuchos::RCP<Teuchos::FancyOStream> out) { out_ = std::move(out); }
  /// With a state x, holds every temperature at its value in x (rows s (T - T_x)) for an
  /// equilibrium solve of the displacement at fixed temperature; with nullptr, releases it.
  void freeze_temperature(const Vector *x);

  /// Contact per mesh node, on every rank (collective): the normal traction across the gap
  /// (-p, negative in compression) [Pa] and 1/0 for pairs in contact; NaN off the gap.
  struct ContactOutput
  {
    std::vector<double> traction;
    std::vector<double> active;
  };
  ContactOutput contact_output(const Vector &x);
  /// Pairs in contact at the last evaluation (global, collective), and of all pairs.
  int n_active_pairs() const;
  int n_pairs() const { return static_cast<int>(pairs_.size()); }
  bool has_contact() const { return !pairs_.empty(); }

  /// x = the initial state at time t [s]: the initial temperature, zero displacement, and
  /// the prescribed values of that time.
  void initial_condition(double time, Vector &x) const;

  /// Physical values of the owned nodes (DofManager::owned_nodes() order) from x, with the
  /// prescribed values of the last set time where constrained.
  std::vector<double> node_temperatures(const Vector &x);
  std::vector<Point> node_displacements(const Vector &x);
  /// Volume averages over each owned cell (owned_cells() order).
  std::vector<ElasticityKernel::CellAverages> cell_averages(const Vector &x);

  const std::vector<ThermalBoundaryCondition> &boundary_conditions() const { return bcs_; }
  const std::vector<MechanicalBoundaryCondition> &mechanical_boundary_conditions() const
  {
    return mechanical_bcs_;
  }
  /// The unknowns' scale c: the solver sees x̂ = x / c and rows c F (doc/mechanics.md).
  double displacement_scale() const { return displacement_scale_; }

private:
  struct BoundaryFace
  {
    int cell;
    int face;
    int bc; ///< index into bcs_ or mechanical_bcs_
  };
  /// A node's displacement frame and its constraints n_l . u = g_l(t), l < n_constrained.
  struct NodeFrame
  {
    std::array<Point, 3> q{}; ///< orthonormal axes; q[0..m) span the constrained directions
    int n_constrained = 0;    ///< m
    std::array<int, 3> bc{};  ///< the condition of constraint l (index into mechanical_bcs_)
    std::array<Point, 3> n{}; ///< the direction of constraint l
    std::array<double, 3> prescribed{}; ///< û_0..û_{m-1} at the last set time [m]
  };

  void setup_thermal(const Material &material, const Teuchos::ParameterList &thermal,
                     const std::vector<char> &owns_cell, const InteriorFaceCheck &interior,
                     const std::string &where);
  void setup_mechanics(const Material &material, const Teuchos::ParameterList &mechanics,
                       const std::vector<char> &owns_cell, const InteriorFaceCheck &interior,
                       const std::string &where);
  void setup_solver_data(const Material &material);
  /// Normal-displacement and component constraints of every mesh node.
  void build_frames();
  /// ∫|∇φ_i|^2 dΩ of every constrained node [m].
  std::vector<double> stiffness_sums() const;
  /// The prescribed values of every constraint at time t.
  void update_prescribed(double time);
  /// û_0..û_{m-1} of a frame's constraints at time t [m].
  std::array<double, 3> prescribed_components(const NodeFrame &frame, double time) const;

  /// T, Tdot and u of every overlap node from x_overlap_ (x~: constrained unknowns replaced).
  void build_state();
  void add_cells();
  void add_boundary_faces();
  void add_gap_faces();
  void add_constraint_rows();

  /// Rotates the displacement rows and columns of framed nodes, combines the rows of pairs
  /// in contact (in the Jacobian pass), zeroes the rows and columns of constrained unknowns
  /// of `local` (changed; nodes[i]: the mesh node of local node i), then adds it. With
  /// contact, a copy extended by the missing twins of its gap nodes is used instead.
  void add_local(const std::vector<int> &nodes, LocalSystem &local);
  /// add_local() once the system holds every twin it needs.
  void transform_and_add(const std::vector<int> &nodes, LocalSystem &local);
  void setup_contact(const Teuchos::ParameterList &contact, const std::string &where);
  /// From the assembled rows f (no contact): each pair's P, state and the contact rows of
  /// f; the frozen temperature rows.
  void update_contact(Vector &f);
  /// The parts of the contact (and frozen temperature) rows that are not element sums.
  void add_contact_jacobian(Matrix &J);
  /// Logs and counts a change of the active set at a Jacobian evaluation; detects cycles.
  void track_active_set();

  const Mesh &mesh_;
  const DofManager &dofs_;
  Assembler assembler_;
  int F_;
  int T_slot_;
  int u_slot_;
  std::vector<int> overlap_index_; ///< per mesh node: position in overlap_nodes(), or -1

  // Heat conduction.
  std::optional<HeatConductionKernel> conduction_;
  GapConductanceKernel gap_{0.0};
  std::optional<ContactConductanceKernel> contact_conductance_; ///< "Contact Dependent" model
  double initial_temperature_ = 0.0;
  std::vector<ThermalBoundaryCondition> bcs_;
  std::vector<BoundaryFace> boundary_faces_;   ///< flux and convection faces of owned cells
  std::vector<int> dirichlet_bc_;              ///< per mesh node: index into bcs_, or -1
  std::vector<double> temperature_scale_;      ///< per mesh node [W/K] (0 if unconstrained)
  std::vector<double> prescribed_temperature_; ///< per mesh node, last set time [K]
  std::vector<int> owned_gap_faces_;

  // Mechanics.
  std::optional<ElasticityKernel> elasticity_;
  Point body_force_{};
  std::vector<MechanicalBoundaryCondition> mechanical_bcs_;
  std::vector<BoundaryFace> load_faces_; ///< traction and pressure faces of owned cells
  std::vector<int> frame_of_node_;       ///< per mesh node: index into frames_, or -1
  std::vector<NodeFrame> frames_;
  std::vector<double> displacement_row_scale_; ///< per mesh node [N/m] (0 if unframed)

  // Contact.
  struct ContactPair
  {
    int a = -1, b = -1; ///< mesh nodes
    double area = 0.0;  ///< A [m^2]
    double c = 0.0;     ///< complementarity constant [Pa/m]
    int slot_a = 0;     ///< the slot of n.u among the node's û (after its constraints)
    int slot_b = 0;
  };
  std::vector<ContactPair> pairs_;
  enum class ContactMode : char
  {
    open,
    closed,
    fischer_burmeister
  };
  std::vector<ContactMode> contact_mode_; ///< per pair (those in the overlap), this evaluation
  std::vector<double> contact_dP_;        ///< Fischer-Burmeister: dC/dP per pair
  std::vector<double> contact_dg_;        ///< Fischer-Burmeister: dC/d(c g) per pair
  bool combine_rows_ = false;             ///< add_local() combines the rows of pairs
  Teuchos::RCP<Vector> f_overlap_;
  std::vector<int> pair_of_node_;   ///< per mesh node: index into pairs_, or -1
  std::vector<int> owned_pairs_;    ///< pairs whose node b this rank owns
  bool fischer_burmeister_ = false; ///< the input's choice
  bool cycle_fallback_ = false;     ///< Fischer-Burmeister after a cycle, this solve
  std::vector<char> active_;        ///< per pair (owned_pairs_), at the last evaluation
  std::vector<double> pressure_;    ///< P per pair (owned_pairs_) at the last evaluation
  ActiveSetHistory history_;        ///< active sets at this solve's Jacobians
  std::vector<char> last_jacobian_active_;
  int jacobians_ = 0;       ///< Jacobian evaluations since set_time_derivative
  int accepted_active_ = 0; ///< pairs in contact after the last accepted step
  Teuchos::RCP<Vector> f_work_;
  std::vector<double> frozen_temperature_; ///< per owned node; empty when not frozen
  Teuchos::RCP<Teuchos::FancyOStream> out_;
  double modulus_ = 0.0; ///< lambda + 2G [Pa]

  double time_ = 0.0;
  double a_ = 0.0;
  double displacement_scale_ = 1.0;
  Teuchos::RCP<Vector> x_overlap_;
  Teuchos::RCP<Vector> b_overlap_;
  std::vector<double> T_state_, T_dot_state_; ///< per overlap node
  std::vector<Point> u_state_;                ///< per overlap node
  Teuchos::RCP<Tpetra::MultiVector<double>> coordinates_;
  Teuchos::RCP<Tpetra::MultiVector<double>> near_null_space_;
  Teuchos::RCP<Vector> unknown_scale_;
  Teuchos::RCP<Vector> time_error_mask_;
};
} // namespace kiln
