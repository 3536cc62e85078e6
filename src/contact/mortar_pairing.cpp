#include "contact/mortar_pairing.hpp"

#include "base/errors.hpp"
#include "contact/face_search.hpp"
#include "contact/mortar_face_integrals.hpp"
#include "contact/pair_checks.hpp"
#include "mesh/contact_surface.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

namespace kiln
{
namespace
{
/// Face f's corners' positions, in the face's order.
std::vector<Point> face_positions(const ContactSurface &surface, const int f)
{
  std::vector<Point> x;
  for (const int n : surface.face_nodes(f))
    x.push_back(surface.positions()[n]);
  return x;
}

/// What the secondary node j gathers from its faces.
struct NodeSums
{
  double D = 0.0;
  double gap = 0.0;
  std::map<int, double> M; ///< by primary surface node
};
} // namespace

MortarPairing::MortarPairing(const Mesh &mesh, const int primary_side_set,
                             const int secondary_side_set, const MortarPairingOptions &options,
                             const std::string &where)
{
  check_distinct_side_sets(primary_side_set, secondary_side_set, where);
  // The primary side set's errors first.
  ContactSurface primary(mesh, primary_side_set, where + "/\"Primary Side Set\"");
  ContactSurface secondary(mesh, secondary_side_set, where + "/\"Secondary Side Set\"");
  pair(mesh, std::move(primary), std::move(secondary), options, where, nullptr);
}

MortarPairing::MortarPairing(const Mesh &mesh, const int primary_side_set,
                             const int secondary_side_set, const MortarPairingOptions &options,
                             const std::string &where,
                             const std::function<Point(int node)> &displacement)
{
  check_distinct_side_sets(primary_side_set, secondary_side_set, where);
  // The primary side set's errors first.
  ContactSurface primary(mesh, primary_side_set, where + "/\"Primary Side Set\"");
  ContactSurface secondary(mesh, secondary_side_set, where + "/\"Secondary Side Set\"");
  pair(mesh, std::move(primary), std::move(secondary), options, where, &displacement);
}

MortarPairing::MortarPairing(const Mesh &mesh, const ContactSurface &primary,
                             const ContactSurface &secondary, const MortarPairingOptions &options,
                             const std::string &where,
                             const std::function<Point(int node)> &displacement)
{
  check_distinct_side_sets(primary.side_set_id(), secondary.side_set_id(), where);
  pair(mesh, primary, secondary, options, where, &displacement);
}

void MortarPairing::pair(const Mesh &mesh, ContactSurface primary, ContactSurface secondary,
                         const MortarPairingOptions &options, const std::string &where,
                         const std::function<Point(int node)> *displacement)
{
  const int primary_side_set = primary.side_set_id();
  const int secondary_side_set = secondary.side_set_id();
  if (displacement != nullptr)
    for (ContactSurface *surface : {&primary, &secondary})
    {
      std::vector<Point> u;
      u.reserve(surface->nodes().size());
      for (const int n : surface->nodes())
        u.push_back((*displacement)(n));
      surface->set_displacement(u);
    }
  search_distance_ =
      options.search_distance > 0 ? options.search_distance : secondary.max_face_diameter();
  check_surfaces_face_each_other(primary, secondary, search_distance_, where);

  const FaceSearch search(primary);
  std::vector<std::vector<Point>> primary_x(primary.n_faces());
  for (int p = 0; p < primary.n_faces(); ++p)
    primary_x[p] = face_positions(primary, p);
  std::vector<NodeSums> sums(secondary.n_nodes());
  // The margins: per secondary node, the primary surface nodes of the faces facing its faces
  // within the reach plus the sliding distance (at set-up only; without a sliding distance,
  // the faces of the search below).
  std::vector<std::vector<int>> margin(displacement == nullptr ? secondary.n_nodes() : 0);
  const auto add_margin = [&](const int s, const int p)
  {
    for (const int n : secondary.face_nodes(s))
      for (const int k : primary.face_nodes(p))
        margin[n].push_back(k);
  };
  if (displacement == nullptr && options.sliding_distance > 0.0)
    for (int s = 0; s < secondary.n_faces(); ++s)
      for (const int p :
           search.candidates(secondary.face_box(s), search_distance_ + options.sliding_distance))
        if (dot(secondary.face_area_vector(s), primary.face_area_vector(p)) < 0.0)
          add_margin(s, p);
  // The size of each secondary node's faces: the smallest diameter among them.
  std::vector<double> face_size(secondary.n_nodes(), secondary.max_face_diameter());
  for (int s = 0; s < secondary.n_faces(); ++s)
    for (const int n : secondary.face_nodes(s))
      face_size[n] = std::min(face_size[n], secondary.face_diameter(s));
  for (int s = 0; s < secondary.n_faces(); ++s)
  {
    // The candidates that face it: a primary face looking the same way (the far side of a
    // thin body) is not the other side of the gap.
    std::vector<int> faces;
    std::vector<MortarFace> primaries;
    for (const int p : search.candidates(secondary.face_box(s), search_distance_))
      if (dot(secondary.face_area_vector(s), primary.face_area_vector(p)) < 0.0)
      {
        faces.push_back(p);
        primaries.push_back({primary.face_type(p), primary_x[p]});
        if (displacement == nullptr && !(options.sliding_distance > 0.0))
          add_margin(s, p);
      }
    if (faces.empty())
      continue;
    const std::vector<Point> x = face_positions(secondary, s);
    const MortarFaceIntegrals integrals({secondary.face_type(s), x}, primaries);
    if (!integrals.covered())
      continue;
    const Span<const int> nodes = secondary.face_nodes(s);
    for (int i = 0; i < integrals.n_shape(); ++i)
    {
      NodeSums &sum = sums[nodes[i]];
      sum.D += integrals.D(i, i);
      sum.gap += integrals.weighted_gap(i);
      for (std::size_t p = 0; p < faces.size(); ++p)
      {
        const Span<const int> primary_nodes = primary.face_nodes(faces[p]);
        for (int k = 0; k < primary_nodes.size(); ++k)
        {
          const double M = integrals.M(i, static_cast<int>(p), k);
          if (M != 0.0)
            sum.M[primary_nodes[k]] += M;
        }
      }
    }
  }

  for (int j = 0; j < secondary.n_nodes(); ++j)
  {
    const NodeSums &sum = sums[j];
    if (!(sum.D > multiplier_fraction() * secondary.nodal_area(j)))
      continue;
    ContactRow row;
    row.node = secondary.nodes()[j];
    const Point &outward = secondary.normal(j);
    row.normal = {-outward[0], -outward[1], -outward[2]};
    row.area = sum.D;
    row.gap0 = sum.gap / sum.D;
    row.face_size = face_size[j];
    row.slip_limit = options.search_update_fraction * face_size[j];
    // sum.M is in increasing primary surface node, so in increasing mesh node.
    for (const auto &[k, M] : sum.M)
    {
      row.partners.push_back(primary.nodes()[k]);
      row.weights.push_back(M / sum.D);
    }
    if (displacement == nullptr)
    {
      std::vector<int> &linked = margin[j];
      std::sort(linked.begin(), linked.end());
      linked.erase(std::unique(linked.begin(), linked.end()), linked.end());
      std::vector<int> nodes;
      nodes.reserve(linked.size());
      for (const int k : linked)
        nodes.push_back(primary.nodes()[k]);
      margins_.push_back(std::move(nodes));
    }
    KILN_CHECK_INPUT(displacement != nullptr || row.gap0 >= -options.penetration_tolerance, where,
                     "the bodies interpenetrate: secondary node "
                         << row.node + 1 << " (side set " << secondary_side_set << ") at ("
                         << mesh.coordinates[row.node][0] << ", " << mesh.coordinates[row.node][1]
                         << ", " << mesh.coordinates[row.node][2] << ") m lies " << -row.gap0
                         << " m inside the primary body (side set " << primary_side_set
                         << "), more than \"Penetration Tolerance\" "
                         << options.penetration_tolerance
                         << " m; move the bodies apart in the mesh so that they at most touch, "
                            "or raise \"Penetration Tolerance\" if the overlap is the facets' "
                            "sag on curved surfaces");
    rows_.push_back(std::move(row));
  }
  KILN_CHECK_INPUT(!rows_.empty(), where,
                   "no node of the secondary side set "
                       << secondary_side_set << " is covered by the primary side set "
                       << primary_side_set << " (their faces within the search distance "
                       << search_distance_
                       << " m do not overlap along the secondary's normals); check that the two "
                          "side sets lie across the gap from each other, or raise \"Search "
                          "Distance\"");
}
} // namespace kiln
