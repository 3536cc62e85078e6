#include "mesh/mesh_bodies.hpp"

#include <numeric>

namespace kiln
{
namespace
{
int root(std::vector<int> &parent, int n)
{
  while (parent[n] != n)
  {
    parent[n] = parent[parent[n]]; // path halving
    n = parent[n];
  }
  return n;
}
} // namespace

MeshBodies mesh_bodies(const Mesh &mesh)
{
  std::vector<int> parent(mesh.n_nodes());
  std::iota(parent.begin(), parent.end(), 0);
  for (int c = 0; c < mesh.n_cells(); ++c)
  {
    const Span<const int> cell = mesh.cell_nodes(c);
    const int first = root(parent, cell[0]);
    for (int i = 1; i < cell.size(); ++i)
    {
      const int r = root(parent, cell[i]);
      if (r != first)
        parent[r] = first;
    }
  }
  MeshBodies bodies;
  bodies.body.assign(mesh.n_nodes(), -1);
  std::vector<int> index_of_root(mesh.n_nodes(), -1);
  for (int c = 0; c < mesh.n_cells(); ++c)
  {
    const Span<const int> cell = mesh.cell_nodes(c);
    int &index = index_of_root[root(parent, cell[0])];
    if (index < 0)
      index = bodies.count++;
    for (const int n : cell)
      bodies.body[n] = index;
  }
  return bodies;
}
} // namespace kiln
