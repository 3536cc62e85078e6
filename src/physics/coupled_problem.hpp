#pragma once
/// Heat conduction and quasi-static thermo-elasticity on the split mesh, in one residual
/// and one Jacobian, as a TransientProblem for the Newton solver and the time stepper.
#include "discretization/assembler.hpp"
#include "discretization/dof_manager.hpp"
#include "discretization/nonlinear_problem.hpp"
#include "mesh/mesh.hpp"
#include "physics/boundary_input.hpp"
#include "physics/heat/gap_conductance_kernel.hpp"
#include "physics/heat/heat_conduction_kernel.hpp"
#include "physics/heat/thermal_boundary_condition.hpp"
#include "physics/materials/material.hpp"
#include "physics/mechanics/elasticity_kernel.hpp"
#include "physics/mechanics/mechanical_boundary_condition.hpp"

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
/// - gap faces whose side-a cell is owned: GapConductanceKernel. The gap is open: the two
///   halves are separate bodies for the mechanics (no contact yet).
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
  /// Rotates the displacement rows and columns of framed nodes, then zeroes the rows and
  /// columns of constrained unknowns (nodes[i]: the mesh node of local node i).
  void finalize(const std::vector<int> &nodes, LocalSystem &local) const;
  void add_cells();
  void add_boundary_faces();
  void add_gap_faces();
  void add_constraint_rows();

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
