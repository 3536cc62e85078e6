#include "mesh/mesh.hpp"

#include <algorithm>

namespace kiln
{
const SideSet *Mesh::find_side_set(const int id) const
{
  for (const auto &s : side_sets)
    if (s.id == id)
      return &s;
  return nullptr;
}

FaceKey Mesh::face_key(const int cell, const int face) const
{
  const ReferenceCell &rc = reference_cell(cell);
  const int n_corners = ReferenceCell::of(rc.face_type(face)).n_vertices();
  FaceKey key{-1, -1, -1, -1};
  for (int i = 0; i < n_corners; ++i)
    key[i] = face_node(cell, face, i);
  std::sort(key.begin(), key.end());
  return key;
}

std::vector<int> Mesh::face_nodes(const int c, const int face) const
{
  const std::vector<int> &local = reference_cell(c).face_nodes(face);
  std::vector<int> nodes(local.size());
  for (std::size_t i = 0; i < local.size(); ++i)
    nodes[i] = cell_node_ids[cell_offsets[c] + local[i]];
  return nodes;
}

void Mesh::add_cell(const CellType type, const int *nodes, const int block)
{
  const int n = ReferenceCell::of(type).n_nodes();
  cell_types.push_back(type);
  cell_node_ids.insert(cell_node_ids.end(), nodes, nodes + n);
  cell_offsets.push_back(static_cast<int>(cell_node_ids.size()));
  block_id.push_back(block);
}

std::vector<CellType> Mesh::types() const
{
  std::vector<CellType> result(cell_types);
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

std::vector<int> Mesh::block_ids() const
{
  std::vector<int> ids(block_id);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}
} // namespace kiln
