#pragma once
/// Transient heat conduction on the split mesh as a TransientProblem for the
/// Newton solver and the time stepper.
#include "discretization/assembler.hpp"
#include "discretization/dof_manager.hpp"
#include "discretization/nonlinear_problem.hpp"
#include "mesh/mesh.hpp"
#include "physics/heat/gap_conductance_kernel.hpp"
#include "physics/heat/heat_conduction_kernel.hpp"
#include "physics/heat/thermal_boundary_condition.hpp"
#include "physics/materials/material.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace kiln
{
/// F(T) = 0 for the nodal temperatures (DofLayout{1, false}):
/// - every owned cell adds HeatConductionKernel;
/// - every owned face of a "Heat Flux" or "Convection" condition adds its kernel;
/// - every gap face whose side-a cell is owned adds GapConductanceKernel;
/// - rows of nodes on "Temperature" side sets are replaced by s_i (T_i - T_D(t)), with
///   s_i the conduction stiffness diagonal of node i at the initial temperature [W/K],
///   so that those rows are scaled like their neighbours; the local systems' rows of
///   such nodes are dropped before they are added. Where two temperature conditions
///   share a node, the first listed applies.
/// The Jacobian is therefore not symmetric: use GMRES (the default).
class ThermalProblem final : public TransientProblem
{
public:
  /// The "Thermal" block: Initial Temperature, Gap Conductance, Boundary Conditions.
  static Teuchos::ParameterList valid_parameters();

  /// `thermal` has been validated against valid_parameters(); `where` names it in
  /// messages ("in.xml: Kiln/Thermal"). `dofs` has one unknown per node and no contact.
  ThermalProblem(const Mesh &mesh, const DofManager &dofs, const Material &material,
                 const Teuchos::ParameterList &thermal, const std::string &where);

  Teuchos::RCP<const Map> solution_map() const override { return dofs_.owned_dof_map(); }
  Teuchos::RCP<const Graph> jacobian_graph() const override { return assembler_.owned_graph(); }
  Teuchos::RCP<const Tpetra::MultiVector<double>> node_coordinates() const override
  {
    return coordinates_;
  }
  void evaluate(const Vector &x, Vector *f, Matrix *J) override;
  void set_time_derivative(double time, double a, const Vector &b) override;

  /// x = the initial temperature, with the prescribed temperatures of time t [s].
  void initial_condition(double time, Vector &x) const;
  const std::vector<ThermalBoundaryCondition> &boundary_conditions() const { return bcs_; }

private:
  struct BoundaryFace
  {
    int cell;
    int face;
    int bc; ///< index into bcs_
  };
  /// Temperature-BC nodes, and the flux and convection faces of the owned cells
  /// (owns_cell: per cell).
  void find_boundary_faces(const std::vector<char> &owns_cell, const std::string &where);
  /// Throws InputError if a condition's side set holds a face shared by two cells.
  void check_faces_on_boundary(const std::string &where) const;
  /// dirichlet_scale_ with conductivity k [W/(m K)].
  void compute_dirichlet_scales(double k);
  /// Drops the rows of constrained nodes (node_of_local[i]: the mesh node of local node i).
  void drop_constrained_rows(const std::vector<int> &node_of_local, LocalSystem &local) const;
  void add_cells(const double *T, const double *b);
  void add_boundary_faces(const double *T);
  void add_gap_faces(const double *T);
  void add_constraint_rows(const double *T);

  const Mesh &mesh_;
  const DofManager &dofs_;
  Assembler assembler_;
  HeatConductionKernel conduction_;
  GapConductanceKernel gap_;
  double initial_temperature_;
  std::vector<ThermalBoundaryCondition> bcs_;
  std::vector<BoundaryFace> boundary_faces_; ///< flux and convection faces of owned cells
  std::vector<int> dirichlet_bc_;            ///< per mesh node: index into bcs_, or -1
  std::vector<double> dirichlet_scale_;      ///< per mesh node [W/K] (0 if unconstrained)
  std::vector<int> owned_gap_faces_;
  double time_ = 0.0;
  double a_ = 0.0;
  Teuchos::RCP<Vector> x_overlap_;
  Teuchos::RCP<Vector> b_overlap_;
  Teuchos::RCP<Tpetra::MultiVector<double>> coordinates_;
};
} // namespace kiln
