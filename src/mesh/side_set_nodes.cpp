#include "mesh/side_set_nodes.hpp"

#include <algorithm>

namespace kiln
{
std::vector<int> side_set_nodes(const Mesh &mesh, const SideSet &set)
{
  std::vector<int> nodes;
  for (int s = 0; s < set.n_sides(); ++s)
    for (const int n : mesh.face_nodes(set.cells[s], set.faces[s]))
      nodes.push_back(n);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}
} // namespace kiln
