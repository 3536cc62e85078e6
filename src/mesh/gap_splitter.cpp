#include "mesh/gap_splitter.hpp"

#include "base/errors.hpp"
#include "mesh/hex_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>

namespace kiln
{
namespace internal
{
/// Each face of the mesh with the (cell, local face) pairs that share it.
std::map<FaceKey, std::vector<std::pair<int, int>>> face_cells(const Mesh &mesh)
{
  std::map<FaceKey, std::vector<std::pair<int, int>>> faces;
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int f = 0; f < mesh.reference_cell(c).n_faces(); ++f)
      faces[mesh.face_key(c, f)].emplace_back(c, f);
  return faces;
}

/// Connected parts of the cells through faces not in `cut`, as a part index per
/// cell, the parts ranked by (lowest block id, lowest cell id).
std::vector<int> cell_parts(const Mesh &mesh,
                            const std::map<FaceKey, std::vector<std::pair<int, int>>> &faces,
                            const std::set<FaceKey> &cut)
{
  std::vector<std::vector<int>> neighbours(mesh.n_cells());
  for (const auto &[key, cells] : faces)
    if (cells.size() == 2 && cut.count(key) == 0)
    {
      neighbours[cells[0].first].push_back(cells[1].first);
      neighbours[cells[1].first].push_back(cells[0].first);
    }
  std::vector<int> part(mesh.n_cells(), -1);
  std::vector<std::pair<int, int>> part_rank; // (lowest block id, first cell) per part
  for (int seed = 0; seed < mesh.n_cells(); ++seed)
  {
    if (part[seed] >= 0)
      continue;
    const int p = static_cast<int>(part_rank.size());
    int lowest_block = mesh.block_id[seed];
    std::vector<int> stack{seed};
    part[seed] = p;
    while (!stack.empty())
    {
      const int c = stack.back();
      stack.pop_back();
      lowest_block = std::min(lowest_block, mesh.block_id[c]);
      for (const int n : neighbours[c])
        if (part[n] < 0)
        {
          part[n] = p;
          stack.push_back(n);
        }
    }
    part_rank.emplace_back(lowest_block, seed);
  }
  std::vector<int> order(part_rank.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](const int a, const int b) { return part_rank[a] < part_rank[b]; });
  std::vector<int> rank_of(order.size());
  for (std::size_t r = 0; r < order.size(); ++r)
    rank_of[order[r]] = static_cast<int>(r);
  for (int &p : part)
    p = rank_of[p];
  return part;
}
void check_not_unmerged(const Mesh &mesh, const SideSet &side_set, const std::string &where)
{
  // Coordinates compared after rounding to 1e-9 of the mesh's extent: two bodies meshed
  // apart place their coincident nodes at the same point up to round-off.
  Point lowest = mesh.coordinates.front(), highest = lowest;
  for (const Point &p : mesh.coordinates)
    for (int d = 0; d < 3; ++d)
      lowest[d] = std::min(lowest[d], p[d]), highest[d] = std::max(highest[d], p[d]);
  const double extent = std::max({highest[0] - lowest[0], highest[1] - lowest[1],
                                  highest[2] - lowest[2], std::numeric_limits<double>::min()});
  const auto rounded = [&](const Point &p)
  {
    std::array<long long, 3> key{};
    for (int d = 0; d < 3; ++d)
      key[d] = std::llround((p[d] - lowest[d]) / (1e-9 * extent));
    return key;
  };
  std::map<std::array<long long, 3>, int> side_nodes;
  for (int s = 0; s < side_set.n_sides(); ++s)
    for (const int n : mesh.face_nodes(side_set.cells[s], side_set.faces[s]))
      side_nodes.emplace(rounded(mesh.coordinates[n]), n);
  for (int n = 0; n < mesh.n_nodes(); ++n)
  {
    const auto it = side_nodes.find(rounded(mesh.coordinates[n]));
    if (it == side_nodes.end() || it->second == n)
      continue;
    const Point &p = mesh.coordinates[n];
    KILN_CHECK_INPUT(false, where,
                     "side set " << side_set.id << " has no interior face: its faces touch "
                                 << "other cells, but through nodes that are not merged (node "
                                 << it->second + 1 << " of side set " << side_set.id << " and node "
                                 << n + 1 << " are both at (" << p[0] << ", " << p[1] << ", "
                                 << p[2]
                                 << ")), so the bodies on its two sides are separate pieces of "
                                    "the mesh with no face between them to split into a gap. "
                                    "Merge the coincident nodes before exporting the mesh "
                                    "(Cubit: \"merge all\"), and keep side set "
                                 << side_set.id << " as the gap side set");
  }
}
} // namespace internal

void split_gaps(Mesh &mesh, const std::vector<int> &side_set_ids, const std::string &where)
{
  const auto faces = internal::face_cells(mesh);
  std::map<FaceKey, int> cut; // face -> its gap (index into side_set_ids)
  for (std::size_t g = 0; g < side_set_ids.size(); ++g)
  {
    const int side_set_id = side_set_ids[g];
    KILN_CHECK_INPUT(std::find(side_set_ids.begin(), side_set_ids.begin() + static_cast<long>(g),
                               side_set_id) == side_set_ids.begin() + static_cast<long>(g),
                     where, "lists side set " << side_set_id << " twice; list each gap once");
    const SideSet *side_set = mesh.find_side_set(side_set_id);
    if (side_set == nullptr)
    {
      std::string present;
      for (const auto &s : mesh.side_sets)
        present += (present.empty() ? "" : ", ") + std::to_string(s.id);
      KILN_CHECK_INPUT(false, where,
                       "side set " << side_set_id << " is not in the mesh (side sets present: "
                                   << (present.empty() ? "none" : present)
                                   << "); set it to the id of the side set that cuts the mesh, "
                                      "or to 0 for no gap");
    }
    int interior = 0;
    for (int s = 0; s < side_set->n_sides(); ++s)
    {
      const auto key = mesh.face_key(side_set->cells[s], side_set->faces[s]);
      if (faces.at(key).size() != 2)
        continue;
      ++interior;
      const auto [it, added] = cut.emplace(key, static_cast<int>(g));
      KILN_CHECK_INPUT(added || it->second == static_cast<int>(g), where,
                       "side sets " << side_set_ids[it->second] << " and " << side_set_id
                                    << " share a face (of cells " << faces.at(key)[0].first + 1
                                    << " and " << faces.at(key)[1].first + 1
                                    << "); a face belongs to one gap: remove it from one of them");
    }
    if (interior == 0)
      internal::check_not_unmerged(mesh, *side_set, where);
    KILN_CHECK_INPUT(interior > 0, where,
                     "side set " << side_set_id
                                 << " has no interior face, so it cannot split the mesh into a "
                                    "gap; name a side set between two parts of the mesh");
  }

  std::set<FaceKey> cut_faces;
  for (const auto &entry : cut)
    cut_faces.insert(entry.first);
  const std::vector<int> part = internal::cell_parts(mesh, faces, cut_faces);
  for (const auto &[key, g] : cut)
  {
    const auto &cells = faces.at(key);
    KILN_CHECK_INPUT(part[cells[0].first] != part[cells[1].first], where,
                     "side set " << side_set_ids[g] << " does not cut the mesh: cells "
                                 << cells[0].first + 1 << " and " << cells[1].first + 1
                                 << " on its two sides stay connected around its edge; a "
                                    "gap side set must separate the mesh into parts");
  }

  // The parts around each node of the cut faces.
  std::map<int, std::set<int>> node_parts;
  // Every node of the cut faces (a key lists only the corners, a triangle's with -1 first;
  // quadratic faces have mid-side nodes too).
  for (const auto &entry : cut)
  {
    const auto &side = faces.at(entry.first)[0];
    for (const int n : mesh.face_nodes(side.first, side.second))
      node_parts[n];
  }
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (const int n : mesh.cell_nodes(c))
      if (auto it = node_parts.find(n); it != node_parts.end())
        it->second.insert(part[c]);

  // Copies: the node stays with its lowest part; every other part gets a copy of its own.
  const int n_original = mesh.n_nodes();
  mesh.parent_node.resize(n_original);
  std::iota(mesh.parent_node.begin(), mesh.parent_node.end(), 0);
  std::map<std::pair<int, int>, int> copy; // (original node, part) -> its node in that part
  for (const auto &[n, parts] : node_parts)
  {
    copy[{n, *parts.begin()}] = n;
    for (auto p = std::next(parts.begin()); p != parts.end(); ++p)
    {
      copy[{n, *p}] = mesh.n_nodes();
      mesh.coordinates.push_back(mesh.coordinates[n]);
      mesh.parent_node.push_back(n);
    }
  }
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int &n : mesh.cell_nodes(c))
      if (auto it = copy.find({n, part[c]}); it != copy.end())
        n = it->second;

  // A pair per two copies that a cut face separates: its area and normal from those faces,
  // seen from side a.
  std::map<std::pair<int, int>, int> pair_index; // (node_a, node_b) -> pair
  std::vector<Point> area_vector;
  for (const auto &[key, g] : cut)
  {
    auto side_a = faces.at(key)[0], side_b = faces.at(key)[1];
    if (part[side_a.first] > part[side_b.first])
      std::swap(side_a, side_b);
    const FaceNodalAreas areas = face_nodal_areas(mesh, side_a.first, side_a.second);
    const int n_face_nodes = static_cast<int>(areas.area.size());
    GapFace gap_face{side_a.first,
                     side_a.second,
                     side_b.first,
                     side_b.second,
                     std::vector<int>(n_face_nodes, -1),
                     g};
    for (int i = 0; i < n_face_nodes; ++i)
    {
      const int a = mesh.face_node(side_a.first, side_a.second, i);
      const int b = copy.at({mesh.parent_node[a], part[side_b.first]});
      const auto [it, added] =
          pair_index.emplace(std::make_pair(a, b), static_cast<int>(mesh.gap_pairs.size()));
      if (added)
      {
        mesh.gap_pairs.push_back(GapPair{a, b, 0.0, {0.0, 0.0, 0.0}, g});
        area_vector.push_back(Point{0.0, 0.0, 0.0});
      }
      const int k = it->second;
      KILN_CHECK_INPUT(mesh.gap_pairs[k].gap == g, where,
                       "side sets " << side_set_ids[mesh.gap_pairs[k].gap] << " and "
                                    << side_set_ids[g] << " both separate the same two parts "
                                    << "of the mesh at node " << mesh.parent_node[a] + 1
                                    << "; make them one gap side set");
      gap_face.node_b[i] = b;
      mesh.gap_pairs[k].area += areas.area[i];
      for (int d = 0; d < 3; ++d)
        area_vector[k][d] += areas.area_vector[i][d];
    }
    mesh.gap_faces.push_back(gap_face);
  }
  double largest_area = 0.0;
  for (const GapPair &pair : mesh.gap_pairs)
    largest_area = std::max(largest_area, pair.area);
  for (std::size_t k = 0; k < mesh.gap_pairs.size(); ++k)
  {
    const Point &a = area_vector[k];
    const double length = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    // A pair's area is the integral of its node's shape function over the cut faces: the
    // corners of QUAD8 (HEX20) and TRI6 (TETRA10) faces integrate to a negative or zero area
    // (doc/contact.md, "Quadratic faces"), which would turn contact and the gap conductance
    // around at those pairs without a word. (A TRI6 corner's 0 comes out as round-off.)
    const GapPair &pair = mesh.gap_pairs[k];
    const Point &x = mesh.coordinates[pair.node_a];
    KILN_CHECK_INPUT(pair.area > 1e-12 * largest_area && length > 1e-12 * largest_area, where,
                     "gap side set " << side_set_ids[pair.gap] << ": the node pair at node "
                                     << mesh.parent_node[pair.node_a] + 1 << " (" << x[0] << ", "
                                     << x[1] << ", " << x[2] << ") has an area of " << pair.area
                                     << " m^2 (the integral of its shape function over the "
                                        "gap's faces), but must have a positive one: the "
                                        "corners of QUAD8 (HEX20) and TRI6 (TETRA10) faces "
                                        "integrate to a negative or zero area, so contact "
                                        "and gap conductance cannot use them. Use HEX27, "
                                        "HEX8, TETRA4, WEDGE6 or PYRAMID5 cells on the two "
                                        "sides of the gap");
    for (int d = 0; d < 3; ++d)
      mesh.gap_pairs[k].normal[d] = a[d] / length;
  }
  // In increasing (node_a, node_b) order, as pair_index is; the faces refer to nodes only.
  std::vector<GapPair> sorted;
  sorted.reserve(mesh.gap_pairs.size());
  for (const auto &entry : pair_index)
    sorted.push_back(mesh.gap_pairs[entry.second]);
  mesh.gap_pairs = std::move(sorted);
  mesh.gap_side_sets = side_set_ids;
}

void split_gap(Mesh &mesh, const int side_set_id, const std::string &where)
{
  split_gaps(mesh, {side_set_id}, where);
}
} // namespace kiln
