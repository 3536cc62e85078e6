#include "elements/reference_cell.hpp"

#include "base/errors.hpp"

#include <algorithm>
#include <cctype>
#include <string>
#include <utility>

namespace kiln
{
namespace
{
/// The types Kiln has a table for (the others follow with their element files).
std::vector<ReferenceCell> make_cells()
{
  std::vector<ReferenceCell> cells;
  cells.emplace_back(
      CellType::hex8, "HEX8", 3, 1, 8,
      std::vector<Point>{{-1, -1, -1},
                         {1, -1, -1},
                         {1, 1, -1},
                         {-1, 1, -1},
                         {-1, -1, 1},
                         {1, -1, 1},
                         {1, 1, 1},
                         {-1, 1, 1}},
      std::vector<std::vector<int>>{
          {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}},
      std::vector<CellType>(6, CellType::quad4), 9);
  cells.emplace_back(CellType::quad4, "QUAD4", 2, 1, 4,
                     std::vector<Point>{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}},
                     std::vector<std::vector<int>>{}, std::vector<CellType>{}, 5);
  return cells;
}

const std::vector<ReferenceCell> &cells()
{
  static const std::vector<ReferenceCell> table = make_cells();
  return table;
}
} // namespace

ReferenceCell::ReferenceCell(const CellType type, std::string name, const int dim, const int degree,
                             const int n_vertices, std::vector<Point> nodes,
                             std::vector<std::vector<int>> faces, std::vector<CellType> face_types,
                             const int xdmf_code, std::vector<int> xdmf_order)
    : type_(type), name_(std::move(name)), dim_(dim), degree_(degree), n_vertices_(n_vertices),
      nodes_(std::move(nodes)), faces_(std::move(faces)), face_types_(std::move(face_types)),
      xdmf_code_(xdmf_code), xdmf_order_(std::move(xdmf_order))
{
}

const ReferenceCell &ReferenceCell::of(const CellType type)
{
  // Looked up per cell in the assembly: an array indexed by the type, not a search.
  static const std::vector<const ReferenceCell *> by_type = []
  {
    std::vector<const ReferenceCell *> table;
    for (const ReferenceCell &cell : cells())
    {
      const auto index = static_cast<std::size_t>(cell.type());
      table.resize(std::max(table.size(), index + 1), nullptr);
      table[index] = &cell;
    }
    return table;
  }();
  const auto index = static_cast<std::size_t>(type);
  if (index >= by_type.size() || by_type[index] == nullptr)
    throw InternalError("no reference cell for element type " + std::to_string(index));
  return *by_type[index];
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

const std::vector<CellType> &ReferenceCell::volume_types()
{
  static const std::vector<CellType> types = []
  {
    std::vector<CellType> result;
    for (const ReferenceCell &cell : cells())
      if (cell.dim() == 3)
        result.push_back(cell.type());
    return result;
  }();
  return types;
}
} // namespace kiln
