#pragma once
/// The nodes of a side set.
#include "mesh/mesh.hpp"

#include <vector>

namespace kiln
{
/// The mesh nodes of the faces of `set`, increasing, each once.
std::vector<int> side_set_nodes(const Mesh &mesh, const SideSet &set);
} // namespace kiln
