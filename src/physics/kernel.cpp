#include "physics/kernel.hpp"

namespace kiln
{
std::vector<int> InterfaceKernel::nodes(const Mesh &mesh, const GapFace &face) const
{
  std::vector<int> result;
  for (int i = 0; i < 4; ++i)
    result.push_back(mesh.connectivity[face.cell_a][hex_face_nodes[face.face_a][i]]);
  result.insert(result.end(), face.node_b.begin(), face.node_b.end());
  return result;
}
} // namespace kiln
