#pragma once
/// A state's figures for a time history: temperature extremes and mean, thermal energy,
/// largest displacement, contact area and force, gap opening.
#include "contact/interface_strategy.hpp"
#include "discretization/dof_manager.hpp"
#include "physics/heat/block_heat_conduction_kernel.hpp"
#include "physics/nodal_fields.hpp"

#include <limits>
#include <string>
#include <vector>

namespace kiln
{
/// The contact figures of one gap (every rank alike): as StateSummary's, over its pairs.
struct GapFigures
{
  int n_pairs = 0;           ///< pairs with an interface
  int n_active = 0;          ///< pairs in contact
  int n_loaded = 0;          ///< pairs in contact that carry a pressure (StateSummary::n_loaded)
  double contact_area = 0.0; ///< [m^2]
  double normal_force = 0.0; ///< compression > 0 [N]
  double max_opening = 0.0, min_opening = 0.0;                 ///< [m] (0 without pairs)
  double heat_flow = std::numeric_limits<double>::quiet_NaN(); ///< from side a to b [W]
};

/// The figures of one contact pair of Mechanics/Contact/Pairs (every rank alike), over its
/// rows j (the secondary side's nodes with a row).
struct PairFigures
{
  std::string name;          ///< the interface's name in the log: pair "NAME"
  int n_rows = 0;            ///< rows of the pairing
  int n_active = 0;          ///< rows in contact
  int n_loaded = 0;          ///< rows in contact that carry a pressure (StateSummary::n_loaded)
  double contact_area = 0.0; ///< sum over the rows in contact of D_jj [m^2]
  double normal_force = 0.0; ///< sum_j D_jj P_j, compression > 0 [N]
  /// The heat across the pair from the secondary to the primary side [W]
  /// (MortarGapHeat::heat_flow over its cells); NaN for a pair without Heat Transfer.
  double heat_flow = std::numeric_limits<double>::quiet_NaN();
};

/// Over the whole mesh (every rank alike).
struct StateSummary
{
  double T_min = 0.0, T_max = 0.0; ///< over the nodes [K]
  double T_mean = 0.0;             ///< volume average [K]
  /// ∫ H(T) dΩ, H = ∫ rho c dT (rho c T if constant; with the lumped capacity H interpolated
  /// from the nodes, as the capacity term takes it) [J]
  double thermal_energy = 0.0;
  double max_displacement = 0.0; ///< max over the nodes of |u| [m]
  int n_pairs = 0;               ///< gap pairs
  int n_active = 0;              ///< pairs in contact
  /// Pairs in contact whose pressure is above round-off: P > round_off_strain * (lambda + 2G)
  /// (with "Free Motions" = "Minimum Norm" the bodies may touch at a pair that carries a
  /// pressure of round-off, which may hold or not from one step to the next).
  int n_loaded = 0;
  double contact_area = 0.0;    ///< Σ A of the pairs in contact [m^2]
  double normal_force = 0.0;    ///< Σ A p of the pairs in contact, compression > 0 [N]
  double max_opening = 0.0;     ///< max over the pairs of g [m] (0 without pairs)
  double min_opening = 0.0;     ///< min over the pairs of g, negative if penetrated [m]
  double max_penetration = 0.0; ///< max over the pairs of -g, at least 0 [m]
  /// Per gap (Mesh::gap_side_sets order); the totals above are over all of them.
  std::vector<GapFigures> gaps;
  /// Per contact pair (the pairings' interfaces in Mechanics/Contact/Pairs order); not in the
  /// totals above.
  std::vector<PairFigures> pairs;
};

/// The temperature figures at `fields` (`conduction`: each cell's enthalpy H(T); nothing
/// without a temperature, which leaves them 0). Collective.
void summarize_temperature(const Mesh &mesh, const DofManager &dofs, const NodalFields &fields,
                           const BlockHeatConductionKernel &conduction, StateSummary &summary);
/// The largest displacement at `fields` (0 without a displacement). Collective.
void summarize_displacement(const DofManager &dofs, const NodalFields &fields,
                            StateSummary &summary);
/// The contact figures of the decision at `fields`' state, in all and per gap (`summary.gaps`
/// sized to the mesh's gaps), and per contact pair (`summary.pairs`). Collective.
void summarize_contact(const std::vector<const InterfaceStrategy *> &interfaces,
                       const NodalFields &fields, const Teuchos::Comm<int> &comm,
                       StateSummary &summary);
} // namespace kiln
