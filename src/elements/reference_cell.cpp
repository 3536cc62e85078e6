#include "elements/reference_cell.hpp"

#include <algorithm>
#include <cctype>
#include <string>
#include <utility>

namespace kiln
{
ReferenceCell::ReferenceCell(CellType type, std::string name, int dim, int degree, int n_vertices,
                             std::vector<Point> nodes, std::vector<std::vector<int>> faces,
                             std::vector<CellType> face_types, int xdmf_code,
                             std::vector<int> xdmf_order)
    : type_(type), name_(std::move(name)), dim_(dim), degree_(degree), n_vertices_(n_vertices),
      nodes_(std::move(nodes)), faces_(std::move(faces)), face_types_(std::move(face_types)),
      xdmf_code_(xdmf_code), xdmf_order_(std::move(xdmf_order))
{
}

namespace
{
/// The element family of an Exodus type name: upper case, the node count dropped, aliases
/// mapped to the ReferenceCell names' families ("HEXAHEDRON" -> "HEX", "TET" -> "TETRA").
std::string exodus_family(std::string name)
{
  std::transform(name.begin(), name.end(), name.begin(),
                 [](const unsigned char c) { return static_cast<char>(std::toupper(c)); });
  while (!name.empty() && std::isdigit(static_cast<unsigned char>(name.back())))
    name.pop_back();
  if (name == "HEXAHEDRON")
    return "HEX";
  if (name == "TET" || name == "TETRAHEDRON")
    return "TETRA";
  if (name == "PYRA")
    return "PYRAMID";
  return name;
}
} // namespace

std::optional<CellType> exodus_cell_type(const std::string &name, const int n_nodes_per_element)
{
  const std::string family = exodus_family(name);
  for (const CellType type : ReferenceCell::volume_types())
  {
    const ReferenceCell &cell = ReferenceCell::of(type);
    if (exodus_family(cell.name()) == family && cell.n_nodes() == n_nodes_per_element)
      return type;
  }
  return std::nullopt;
}

std::string supported_volume_types()
{
  std::string list;
  for (const CellType type : ReferenceCell::volume_types())
    list += (list.empty() ? "" : ", ") + ReferenceCell::of(type).name();
  return list;
}

} // namespace kiln
