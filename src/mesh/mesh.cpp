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
  FaceKey key;
  for (int i = 0; i < 4; ++i)
    key[i] = connectivity[cell][hex_face_nodes[face][i]];
  std::sort(key.begin(), key.end());
  return key;
}

std::vector<int> Mesh::block_ids() const
{
  std::vector<int> ids(block_id);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}
} // namespace kiln
