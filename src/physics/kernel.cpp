#include "physics/kernel.hpp"

namespace kiln
{
std::vector<int> InterfaceKernel::nodes(const Mesh &mesh, const GapFace &face) const
{
  std::vector<int> result = mesh.face_nodes(face.cell_a, face.face_a);
  const int n = static_cast<int>(result.size());
  result.insert(result.end(), face.node_b.begin(), face.node_b.begin() + n);
  return result;
}
} // namespace kiln
