#pragma once
/// What the linear solvers are told about a problem beyond its matrix: node coordinates, the
/// near-null space, the scale of the unknowns, which unknowns have a time derivative.
#include "discretization/dof_manager.hpp"
#include "discretization/nodal_constraints.hpp"
#include "mesh/mesh.hpp"

#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

namespace kiln
{
/// For the unknowns of a DofManager's layout (doc/mechanics.md, "Scaling"; doc/solvers.md):
/// - coordinates: of the owned nodes, for MueLu's aggregation (its distance Laplacian), with
///   the mesh's k-th body (mesh_bodies(): the two halves of a box cut by its gap) moved by k
///   times ten diagonals of the mesh's bounding box along x, so that no aggregate crosses a
///   gap that separates bodies: with the pairs in contact, the rows of the pair couple the
///   two sides as strongly as a body's own rows, and aggregates across the gap cannot
///   represent the sliding of one side on the other (doc/solvers.md);
/// - near-null space: the constant temperature with the free thermal expansion it causes
///   (u = alpha (x - centre) per kelvin, where both fields are solved: a uniform heating of an
///   unheld body leaves no force, so (1, alpha (x - centre)) is J's near-null vector, not (1,
///   0); doc/solvers.md, "Strong thermal coupling") and the six rigid-body modes
///   (translations, rotations about the mesh centre), in the nodes' frame unknowns;
/// - unknown scale c: 1 for T, sqrt(k / (lambda + 2G)) for u when both fields are solved
///   (so that the diagonals of the force and heat rows match), 1 otherwise;
/// - time-error mask: 1 for the temperature (which has a time derivative), 0 for the
///   quasi-static displacement.
class SolverHints
{
public:
  using MultiVector = Tpetra::MultiVector<double>;
  using Vector = Tpetra::Vector<>;

  /// `constraints` is closed (its frames rotate the rigid-body modes); k [W/(m K)] and
  /// lambda + 2G [Pa] give the scale; alpha [1/K] the temperature mode's expansion.
  SolverHints(const Mesh &mesh, const DofManager &dofs, const NodalConstraints &constraints,
              double conductivity, double modulus, double thermal_expansion);

  Teuchos::RCP<const MultiVector> coordinates() const { return coordinates_; }
  Teuchos::RCP<const MultiVector> near_null_space() const { return near_null_space_; }
  Teuchos::RCP<const Vector> unknown_scale() const { return unknown_scale_; }
  Teuchos::RCP<const Vector> time_error_mask() const { return time_error_mask_; }
  /// The scale c of the displacement unknowns.
  double displacement_scale() const { return displacement_scale_; }

private:
  double displacement_scale_ = 1.0;
  Teuchos::RCP<MultiVector> coordinates_;
  Teuchos::RCP<MultiVector> near_null_space_;
  Teuchos::RCP<Vector> unknown_scale_;
  Teuchos::RCP<Vector> time_error_mask_;
};
} // namespace kiln
