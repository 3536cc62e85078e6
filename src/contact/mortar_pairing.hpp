#pragma once
/// The mortar pairing of a contact pair between separately meshed bodies (issue 30;
/// doc/contact.md, "Separately meshed bodies (issue 30): design"): the rows (ContactRow) that a
/// kind condenses into, one per secondary surface node that the primary surface covers.
/// Per secondary node j, with the dual basis on the covered part of each of its faces
/// (MortarFaceIntegrals) and the primary faces within reach (FaceSearch):
///   D_jj  = sum over j's faces of ∫ psi_j N_j        (the row's area)
///   w_jk  = M_jk / D_jj, M_jk = ∫ psi_j N^m_k         (partners k: primary mesh nodes; sum 1)
///   g0_j  = g~_j / D_jj, g~_j = ∫ psi_j n . (x_s - x_m) (the weighted gap; > 0 open)
///   n_j   = minus the secondary surface's outward nodal normal (from the primary side to the
///           secondary side)
/// A node with D_jj <= multiplier_fraction() of ∫ N_j over its faces gets no row (the primary
/// covers too little of it for its multiplier to be sound). On flat surfaces g0_j = n_j . (X_j -
/// sum_k w_jk X_k).
///
/// In the reference configuration X at set-up, and in X + u when the search is redone during a
/// run (PairResearch, doc/contact.md "Small sliding"): each row's slip_limit is
/// `search_update_fraction` times the smallest diameter of its node's secondary faces, checked
/// after every accepted step (slid_beyond_limit). The mesh is replicated, so every rank computes
/// the rows of the whole secondary surface, in the same order (deterministic: the same rows on
/// every rank and for every number of ranks). When the mesh is distributed, a rank will integrate
/// the secondary faces of its owned cells and sum D, M and g~ of a node whose faces lie on two
/// ranks to its owner (an Export with ADD), as the design says.
#include "contact/contact_row.hpp"
#include "mesh/contact_surface.hpp"
#include "mesh/mesh.hpp"

#include <functional>
#include <string>
#include <vector>

namespace kiln
{
/// The options of a pair (Mechanics/Contact/Pairs, contact_pairs.hpp).
struct MortarPairingOptions
{
  /// The reach of the search [m]: primary faces whose boxes are within it of a secondary
  /// face's are integrated against it; 0: the secondary surface's largest face diameter.
  double search_distance = 0.0;
  /// The largest interpenetration of the reference configuration accepted, g0_j >= -this [m].
  double penetration_tolerance = 1e-9;
  /// The small-sliding limit as a fraction of the size of a secondary node's faces, in (0, 1]
  /// [-]: ContactRow::slip_limit (doc/contact.md, "Small sliding").
  double search_update_fraction = 0.25;
  /// How far the pair may slide in all [m]: the margin of each row's partner links (margins())
  /// reaches the primary faces within search_distance + this of its node's faces; the search
  /// redone during a run finds partners within it, or the run ends (PairResearch). 0: the
  /// margin is the faces the search finds (with the default reach, a ring of faces around the
  /// overlap).
  double sliding_distance = 0.0;
};

class MortarPairing
{
public:
  /// The rows of the pair of side sets `primary_side_set` and `secondary_side_set` of `mesh`.
  /// `where` names the pair in messages ("in.xml: Mechanics/Contact/Pairs/\"Pellet\"").
  /// Throws InputError naming `where` if the two side sets are one (check_distinct_side_sets),
  /// a side set is absent, empty, inside the mesh or has quadratic faces (ContactSurface), the
  /// surfaces do not face each other (check_surfaces_face_each_other), a secondary node
  /// starts inside the primary body by more than the penetration tolerance, or the primary
  /// covers no secondary node.
  MortarPairing(const Mesh &mesh, int primary_side_set, int secondary_side_set,
                const MortarPairingOptions &options, const std::string &where);
  /// The same in the current configuration X + u, `displacement` giving u [m] at a mesh node
  /// of the two surfaces (it is asked for theirs only: the search redone during a run,
  /// PairResearch, holds u on the surfaces, never per mesh node): the rows' normals are the
  /// current configuration's, their slip limits are computed alike; the interpenetration of
  /// the state is not checked (it is the solver's) and no margins are computed.
  MortarPairing(const Mesh &mesh, int primary_side_set, int secondary_side_set,
                const MortarPairingOptions &options, const std::string &where,
                const std::function<Point(int node)> &displacement);
  /// The same on the surfaces `primary` and `secondary` as built by ContactSurface (in X, with
  /// the checks made when they were; PairResearch keeps those of set-up): a search redone does
  /// not rebuild them from the mesh (ContactSurface's checks pass over every cell of it).
  MortarPairing(const Mesh &mesh, const ContactSurface &primary, const ContactSurface &secondary,
                const MortarPairingOptions &options, const std::string &where,
                const std::function<Point(int node)> &displacement);

  /// One row per covered secondary node, in increasing mesh node id; partners in increasing
  /// mesh node id.
  const std::vector<ContactRow> &rows() const { return rows_; }
  /// Per row (in rows() order), the primary mesh nodes its node j is linked to at set-up,
  /// increasing: the nodes of the primary faces facing j's faces whose boxes are within
  /// search_distance() + the option's sliding_distance of theirs (a superset of the row's
  /// partners). Empty for a pairing in a displaced configuration.
  const std::vector<std::vector<int>> &margins() const { return margins_; }
  /// The reach the search used [m] (the option, or its default).
  double search_distance() const { return search_distance_; }

  /// The least D_jj / ∫ N_j of a row [-] (doc/contact.md, "Dual basis on the covered part":
  /// the gap stays within 1e-13 of exact above it).
  static constexpr double multiplier_fraction() { return 1e-6; }

private:
  void pair(const Mesh &mesh, ContactSurface primary, ContactSurface secondary,
            const MortarPairingOptions &options, const std::string &where,
            const std::function<Point(int node)> *displacement);

  std::vector<ContactRow> rows_;
  std::vector<std::vector<int>> margins_;
  double search_distance_ = 0.0;
};
} // namespace kiln
