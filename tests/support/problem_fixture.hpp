#pragma once
/// What the tests of the assembled problem (CoupledProblem) build before they evaluate: a
/// material with a k(T) table, generated boxes (rotated, their interior nodes moved, split at
/// a gap), and a fixture holding the mesh, its partition, the unknowns and the material, which
/// makes problems from Thermal and Mechanics lists.
#include "discretization/dof_manager.hpp"
#include "mesh/mesh.hpp"
#include "physics/coupled_problem.hpp"
#include "physics/materials/material.hpp"
#include "physics/materials/material_map.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <array>
#include <vector>

namespace kiln_test
{
/// The material of the problem tests: aluminium-like, rho = 2700 kg/m^3, c = 900 J/(kg K),
/// E = 70 GPa, nu = 0.33, alpha = 2.2e-5 /K, T_ref = 298 K, and k(T) a table through
/// (200 K, 300), (280 K, 120), (400 K, 360) W/(m K): k = 120 + 2 (T - 280) on (280, 400) K, so
/// that k'(T) counts in the Jacobian.
struct TableMaterial
{
  static constexpr double density = 2700.0, specific_heat = 900.0;
  static constexpr double youngs = 7.0e10, poisson = 0.33, alpha = 2.2e-5, T_ref = 298.0;
  /// k(T) [W/(m K)] on (280, 400) K.
  static double conductivity(const double T) { return 120.0 + 2.0 * (T - 280.0); }
  static kiln::Material make();
};

/// A generated box (BoxMeshGenerator): block-frame sizes, cells, rotation and translation.
struct BoxShape
{
  kiln::Point size;
  std::array<int, 3> cells;
  double phi = 0.0, theta = 0.0; ///< [degrees]
  kiln::Point shift{0.0, 0.0, 0.0};
  /// x += shear z and y += shear z in the block frame (before the rotation): the planes
  /// z = const stay, the planes x = const and y = const slant, so that no two of the three
  /// families are perpendicular.
  double shear = 0.0;
};

/// The box, split at side set `gap_side_set` (0: not split).
kiln::Mesh box_mesh(const BoxShape &box, int gap_side_set);

/// The frames of the owned nodes (DofManager::owned_nodes() order) of a Thermo-Elasticity
/// problem: the physical direction of each displacement unknown, zero where it is
/// constrained, read back through node_displacements(). Collective.
std::vector<std::array<kiln::Point, 3>> node_frames(kiln::CoupledProblem &problem);

/// The components û_k of a displacement u [m] in a node's frame given by node_frames() (t_k,
/// u = sum_k û_k t_k, zero vectors for constrained components, which get 0): the frame need not
/// be orthonormal (gaps that cross at an angle).
std::array<double, 3> frame_components(const std::array<kiln::Point, 3> &t, const kiln::Point &u);

/// The largest difference between J at x of a Thermo-Elasticity problem and its central
/// differences (steps 1e-3 K, 1e-9 m), relative to the largest entry of its row in its block
/// (T-T, T-u, u-T, u-u), over all ranks; expects `n_active` pairs in contact at x and at
/// every perturbed state (gtest expectations). Collective.
double jacobian_error(const struct ProblemFixture &s, kiln::CoupledProblem &problem,
                      kiln::NonlinearProblem::Vector &x, int n_active);
/// The same for a problem on the unknowns `dofs` (any mesh and partition).
double jacobian_error(const kiln::DofManager &dofs, kiln::CoupledProblem &problem,
                      kiln::NonlinearProblem::Vector &x, int n_active);

/// The box split at several of its side sets 10, 11, 12 (its mid-planes x, y, z = 0), which
/// cross.
kiln::Mesh crossed_box(const BoxShape &box, const std::vector<int> &gap_side_sets);

/// The box with its nodes off the six outer faces moved by up to `distortion` of a cell along
/// each block axis (random, the same on every rank), so that the outer faces stay plane; with
/// `plane_gap` the nodes of side set `gap_side_set` move within it only (the gap stays plane);
/// then split at `gap_side_set` (0: not split).
kiln::Mesh distorted_box(const BoxShape &box, double distortion, int gap_side_set,
                         bool plane_gap = false);

/// The MaterialMap of a user's Kiln list (its "Material" or "Materials", validated against
/// Kiln's) for the element blocks `block_ids` ("test.xml" in messages).
kiln::MaterialMap material_map(const Teuchos::ParameterList &kiln_user,
                               const std::vector<int> &block_ids);

/// Mesh, partition, unknowns and material of one test. CoupledProblem keeps references to the
/// mesh and the unknowns, so a fixture stays where it is built.
struct ProblemFixture
{
  ProblemFixture(kiln::Mesh mesh, kiln::DofLayout layout,
                 kiln::Material material = TableMaterial::make());
  ProblemFixture(const ProblemFixture &) = delete;
  ProblemFixture &operator=(const ProblemFixture &) = delete;

  /// A CoupledProblem of the fixture's unknowns with the Thermal and Mechanics lists (each
  /// validated, its defaults set); with `materials` (read at construction), a
  /// material per block, else the fixture's material for every cell.
  Teuchos::RCP<kiln::CoupledProblem>
  problem(const Teuchos::ParameterList &thermal,
          const Teuchos::ParameterList &mechanics = Teuchos::ParameterList(),
          const kiln::MaterialMap *materials = nullptr) const;
  /// 1 for the nodes of the faces of side set `id`.
  std::vector<char> nodes_of_side_set(int id) const;
  /// A twin node made by the gap split.
  bool is_twin(const int node) const { return mesh.parent_node[node] != node; }

  Teuchos::RCP<const Teuchos::Comm<int>> comm = Teuchos::DefaultComm<int>::getComm();
  kiln::Mesh mesh;
  std::vector<int> cell_rank;
  kiln::DofManager dofs;
  kiln::Material material;
};
} // namespace kiln_test
