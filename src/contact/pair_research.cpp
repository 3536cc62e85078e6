#include "contact/pair_research.hpp"

#include "base/errors.hpp"
#include "mesh/contact_surface.hpp"

#include <algorithm>
#include <sstream>
#include <utility>

namespace kiln
{
Point row_relative_displacement(const ContactRow &row, const std::function<Point(int node)> &u)
{
  Point d = u(row.node);
  for (std::size_t k = 0; k < row.partners.size(); ++k)
  {
    const Point uk = u(row.partners[k]);
    for (int i = 0; i < 3; ++i)
      d[i] -= row.weights[k] * uk[i];
  }
  return d;
}

PairResearch::PairResearch(const Mesh &mesh, const int primary_side_set,
                           const int secondary_side_set, const MortarPairingOptions &options,
                           std::string where, std::string name,
                           std::vector<std::vector<int>> margins)
    : mesh_(mesh), options_(options), where_(std::move(where)), name_(std::move(name)),
      margins_(std::move(margins)),
      primary_(mesh, primary_side_set, where_ + "/\"Primary Side Set\""),
      secondary_(mesh, secondary_side_set, where_ + "/\"Secondary Side Set\"")
{
  for (const ContactSurface *surface : {&primary_, &secondary_})
    surface_nodes_.insert(surface_nodes_.end(), surface->nodes().begin(), surface->nodes().end());
  std::sort(surface_nodes_.begin(), surface_nodes_.end());
  surface_nodes_.erase(std::unique(surface_nodes_.begin(), surface_nodes_.end()),
                       surface_nodes_.end());
}

std::size_t PairResearch::surface_index(const int node) const
{
  const auto at = std::lower_bound(surface_nodes_.begin(), surface_nodes_.end(), node);
  KILN_ASSERT(at != surface_nodes_.end() && *at == node,
              "node " << node << " is on a surface of " << name_);
  return static_cast<std::size_t>(at - surface_nodes_.begin());
}

std::vector<std::pair<int, int>> PairResearch::links(const std::vector<ContactRow> &rows) const
{
  KILN_ASSERT(rows.size() == margins_.size(), "a margin per row of " << name_);
  std::vector<std::pair<int, int>> links;
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (const int k : margins_[i])
      links.emplace_back(rows[i].node, k);
  return links;
}

std::vector<ContactRow> PairResearch::rows_at(const std::vector<ContactRow> &current,
                                              const std::vector<Point> &u, const double time) const
{
  KILN_ASSERT(current.size() == margins_.size(), "a margin per row of " << name_);
  KILN_ASSERT(u.size() == surface_nodes_.size(), "a displacement per surface node of " << name_);
  // The rows' nodes and partners are surface nodes: u is read at these only.
  const auto u_of = [&](const int node) { return u[surface_index(node)]; };
  const MortarPairing pairing(mesh_, primary_, secondary_, options_, where_, u_of);
  const std::vector<ContactRow> &fresh = pairing.rows();
  const auto node_text = [&](const int node)
  {
    const Point &X = mesh_.coordinates[node];
    std::ostringstream text;
    text << "secondary node " << node + 1 << " (reference position (" << X[0] << ", " << X[1]
         << ", " << X[2] << ") m)";
    return text.str();
  };
  const std::string what_to_do =
      ". The pairs support sliding within the margin of primary faces linked at set-up only "
      "(doc/contact.md, \"Small sliding\"): keep the sliding along this pair within it (a "
      "smaller imposed motion or load), or raise the pair's \"Sliding Distance\" to the "
      "largest sliding expected (a larger matrix graph); a secondary surface that slides off "
      "the primary one needs a larger primary surface. The results up to the last accepted "
      "step are kept";
  const auto newly_covered = [&](const int node)
  {
    std::ostringstream message;
    message << name_ << ": at t = " << time << " s the search redone in the current "
            << "configuration finds " << node_text(node)
            << " covered by the primary surface, which it was not at set-up (the pair's rows "
               "are those of the nodes covered at set-up)"
            << what_to_do;
    throw RunError(message.str());
  };
  std::vector<ContactRow> rows;
  rows.reserve(current.size());
  std::size_t f = 0;
  for (std::size_t i = 0; i < current.size(); ++i)
  {
    const ContactRow &old = current[i];
    // Both in increasing node: a fresh row before this one is a node newly covered.
    if (f < fresh.size() && fresh[f].node < old.node)
    {
      newly_covered(fresh[f].node);
    }
    if (f >= fresh.size() || fresh[f].node != old.node)
    {
      std::ostringstream message;
      message << name_ << ": at t = " << time << " s " << node_text(old.node)
              << " has slid off the primary surface: the search redone in the current "
                 "configuration finds it no longer covered (the pair's rows are those of the "
                 "nodes covered at set-up)"
              << what_to_do;
      throw RunError(message.str());
    }
    const ContactRow &row = fresh[f++];
    const std::vector<int> &margin = margins_[i];
    for (const int k : row.partners)
      if (!std::binary_search(margin.begin(), margin.end(), k))
      {
        const Point &X = mesh_.coordinates[k];
        std::ostringstream message;
        message << name_ << ": at t = " << time << " s " << node_text(old.node)
                << " has slid beyond the small-sliding limit: the search redone in the current "
                   "configuration pairs it with primary node "
                << k + 1 << " (reference position (" << X[0] << ", " << X[1] << ", " << X[2]
                << ") m), outside the margin of primary faces linked to it at set-up (within "
                   "\"Search Distance\" plus \"Sliding Distance\" "
                << options_.sliding_distance << " m of its faces)" << what_to_do;
        throw RunError(message.str());
      }
    ContactRow next = old;
    next.partners = row.partners;
    next.weights = row.weights;
    next.area = row.area;
    const Point d_old = row_relative_displacement(old, u_of);
    const Point d_new = row_relative_displacement(next, u_of);
    next.gap0 = old.gap0 + dot(old.normal, d_old) - dot(old.normal, d_new);
    next.slip0 = d_new;
    rows.push_back(std::move(next));
  }
  if (f < fresh.size())
  {
    newly_covered(fresh[f].node);
  }
  return rows;
}
} // namespace kiln
