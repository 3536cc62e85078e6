#include "mesh/reference_cell.hpp"

#include <utility>

namespace kiln
{
ReferenceCell::ReferenceCell(CellType type, std::string name, int dim, int degree, int n_vertices,
                             std::vector<Point> nodes, std::vector<std::vector<int>> faces,
                             std::vector<CellType> face_types, int xdmf_code)
    : type_(type), name_(std::move(name)), dim_(dim), degree_(degree), n_vertices_(n_vertices),
      nodes_(std::move(nodes)), faces_(std::move(faces)), face_types_(std::move(face_types)),
      xdmf_code_(xdmf_code)
{
}
} // namespace kiln
