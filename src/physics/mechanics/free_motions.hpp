#pragma once
/// The rigid motions the mechanical conditions leave free, body by body (doc/mechanics.md,
/// "Free motions").
#include "contact/interface_strategy.hpp"
#include "discretization/dof_manager.hpp"
#include "discretization/nodal_constraints.hpp"
#include "mesh/mesh.hpp"
#include "physics/mechanics/free_motion_finder.hpp"

#include <Tpetra_MultiVector.hpp>

#include <string>
#include <vector>

namespace kiln
{
/// The free rigid motions of the displacement: the bodies are the mesh's connected parts after
/// the gap split (mesh_bodies()); each constrained displacement direction of a node
/// (NodalConstraints::directions(): rollers, prescribed normal motions, components) holds its
/// body along it, and each gap pair holds the two bodies together along the directions its
/// interface kind holds (InterfaceStrategy::held_directions(): the normal for contact, which
/// is frictionless; every direction for a bonded gap). Tractions, pressures and body forces
/// hold nothing. Each rank adds the constraints of its owned nodes (and its share of the
/// pairs); the sums are reduced over the ranks (FreeMotionFinder). Collective.
class FreeMotions
{
public:
  using HeldDirection = InterfaceStrategy::HeldDirection;
  /// `constraints` is closed. `held`: this rank's share of the directions the gap pairs can
  /// hold (none without an interface).
  FreeMotions(const Mesh &mesh, const DofManager &dofs, const NodalConstraints &constraints,
              const std::vector<HeldDirection> &held);

  bool empty() const { return motions_.empty(); }
  int size() const { return static_cast<int>(motions_.size()); }
  /// Each motion in words ("translation along z").
  std::vector<std::string> names() const;
  /// What is free, body by body: "body 1 of 2 (element block 1, the cells between (0, 0, 0)
  /// and (1, 1, 1)): translation along z; ...".
  std::string description() const { return description(motions_); }

  /// With an interface: the free motions, as description() gives them, when only `held`
  /// holds (this rank's share, each pair on one rank: those in contact), or "" if they leave
  /// no more free than all the pairs do (the set-up's motions). An open gap can leave a body
  /// that only contact holds free. Collective.
  std::string more_free_with(const std::vector<HeldDirection> &held) const;
  /// The free motions (a basis) when only `held` holds (this rank's share). Collective.
  std::vector<RigidMotion> motions_with(const std::vector<HeldDirection> &held) const;
  /// How much a motion opens or closes the pair of `h` along its direction d,
  /// |d.(r_b(x) - r_a(x))|, relative to the motion's largest displacement of a body,
  /// max_b (|a_b| + |w_b| L_b) [-]: 0 if the pair cannot hold it.
  double opening_rate(const RigidMotion &motion, const HeldDirection &h) const;
  /// The motions in the unknowns of the DofManager's layout, one column each: T = 0 and
  /// û = Q^T r(x) at each owned node (the nodal frames of `constraints`), with r of unit
  /// translation or unit rotation: so that v.F is the net force [N] along a free translation
  /// and the net moment [N m] about a free axis.
  Teuchos::RCP<Tpetra::MultiVector<double>> basis() const { return basis(motions_); }
  /// The same for any motions of the bodies.
  Teuchos::RCP<Tpetra::MultiVector<double>> basis(const std::vector<RigidMotion> &motions) const;
  /// d.(r_b(x) - r_a(x)) for the pair of `h` (d its direction, x its nodes' position): how
  /// much a motion opens the pair [m per unit of the motion].
  double opening_along(const RigidMotion &motion, const HeldDirection &h) const;

private:
  std::string description(const std::vector<RigidMotion> &motions) const;

  const Mesh &mesh_;
  const DofManager &dofs_;
  const NodalConstraints &constraints_;
  std::vector<int> body_;            ///< per mesh node, its body or -1
  std::vector<std::string> summary_; ///< per body: blocks and extent
  FreeMotionFinder conditions_;      ///< the displacement conditions' rows only
  FreeMotionFinder finder_;          ///< and the gap's with contact
  std::vector<RigidMotion> motions_;
};
} // namespace kiln
