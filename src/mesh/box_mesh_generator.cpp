#include "mesh/box_mesh_generator.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"
#include "mesh/hex_geometry.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>

#include <limits>
#include <string>
#include <tuple>

namespace kiln
{
Teuchos::ParameterList BoxMeshGenerator::valid_parameters()
{
  Teuchos::ParameterList p("Box");
  p.set("Size", Teuchos::Array<double>(Teuchos::tuple(0.04, 0.04, 0.04)),
        "edge lengths Lx, Ly, Lz of the block in its own frame [m]",
        positive_double_array_validator(3));
  p.set("Cells", Teuchos::Array<int>(Teuchos::tuple(4, 4, 4)),
        "cells along x, y, z; the x count must be even so that x = 0 is a cell face [-]",
        positive_int_array_validator(3));
  p.set("Phi", 0.0, "rotation about the y axis, applied first [degrees]",
        double_range_validator(-360.0, 360.0));
  p.set("Theta", 0.0, "rotation about the x axis, applied second [degrees]",
        double_range_validator(-360.0, 360.0));
  p.set("Translation", Teuchos::Array<double>(Teuchos::tuple(0.0, 0.0, 0.0)),
        "translation applied after the rotation [m]", double_array_validator(3));
  return p;
}

BoxMeshGenerator::BoxMeshGenerator(const Teuchos::ParameterList &p, const std::string &where)
    : where_(where)
{
  const auto &size = p.get<Teuchos::Array<double>>("Size");
  const auto &cells = p.get<Teuchos::Array<int>>("Cells");
  const auto &shift = p.get<Teuchos::Array<double>>("Translation");
  for (int d = 0; d < 3; ++d)
  {
    size_[d] = size[d];
    cells_[d] = cells[d];
    translation_[d] = shift[d];
  }
  phi_ = p.get<double>("Phi");
  theta_ = p.get<double>("Theta");
  // Odd: suggest the even counts next to it that are valid (1 has only 2).
  const std::string even_choices =
      cells_[0] > 1 ? std::to_string(cells_[0] - 1) + " or " + std::to_string(cells_[0] + 1)
                    : std::string("2 (one cell on each side)");
  KILN_CHECK_INPUT(cells_[0] % 2 == 0, where + "/\"Cells\"",
                   "the x count is " << cells_[0]
                                     << " but must be even, so that the plane x = 0 between "
                                        "the two blocks is a cell face; use "
                                     << even_choices);
  // Nodes and cells are numbered with int: refuse counts that overflow it before the
  // generator computes them.
  const long double n_nodes =
      static_cast<long double>(cells_[0] + 1.0L) * (cells_[1] + 1.0L) * (cells_[2] + 1.0L);
  const long double n_cells =
      static_cast<long double>(cells_[0]) * static_cast<long double>(cells_[1]) * cells_[2];
  KILN_CHECK_INPUT(n_nodes <= std::numeric_limits<int>::max(), where + "/\"Cells\"",
                   "{" << cells_[0] << ", " << cells_[1] << ", " << cells_[2] << "} gives "
                       << static_cast<double>(n_cells) << " cells and "
                       << static_cast<double>(n_nodes) << " nodes, more than the "
                       << std::numeric_limits<int>::max()
                       << " a Kiln mesh can number (and far more than fits in memory): use "
                          "fewer cells");
}

long long BoxMeshGenerator::n_cells() const
{
  return static_cast<long long>(cells_[0]) * cells_[1] * cells_[2];
}

long long BoxMeshGenerator::n_nodes() const
{
  return (cells_[0] + 1LL) * (cells_[1] + 1LL) * (cells_[2] + 1LL);
}

Mesh BoxMeshGenerator::generate(const bool mid_y, const bool mid_z) const
{
  const int nx = cells_[0], ny = cells_[1], nz = cells_[2];
  KILN_CHECK_INPUT(!mid_y || ny % 2 == 0, where_ + "/\"Cells\"",
                   "has " << ny << " cells along y: side set 11 (the plane y = 0) needs an even "
                          << "number; use " << ny + 1);
  KILN_CHECK_INPUT(!mid_z || nz % 2 == 0, where_ + "/\"Cells\"",
                   "has " << nz << " cells along z: side set 12 (the plane z = 0) needs an even "
                          << "number; use " << nz + 1);
  const auto node = [&](const int i, const int j, const int k)
  { return i + (nx + 1) * (j + (ny + 1) * k); };
  const auto A = rotation_matrix(phi_, theta_);

  Mesh mesh;
  mesh.coordinates.resize(static_cast<std::size_t>(nx + 1) * (ny + 1) * (nz + 1));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
      {
        const Point x{size_[0] * (double(i) / nx - 0.5), size_[1] * (double(j) / ny - 0.5),
                      size_[2] * (double(k) / nz - 0.5)};
        Point &y = mesh.coordinates[node(i, j, k)];
        for (int d = 0; d < 3; ++d)
          y[d] = A[d][0] * x[0] + A[d][1] * x[1] + A[d][2] * x[2] + translation_[d];
      }

  // Side sets 1..6 and 10, filled while the cells are made.
  mesh.side_sets.resize(7);
  const char *const face_names[6] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
  for (int s = 0; s < 6; ++s)
  {
    mesh.side_sets[s].id = s + 1;
    mesh.side_sets[s].name = face_names[s];
  }
  mesh.side_sets[6].id = 10;
  mesh.side_sets[6].name = "gap";
  SideSet &gap = mesh.side_sets[6];
  const auto add_side = [](SideSet &set, const int cell, const int face)
  {
    set.cells.push_back(cell);
    set.faces.push_back(face);
  };
  // Local faces (Exodus order): 0 y-, 1 x+, 2 y+, 3 x-, 4 z-, 5 z+.
  std::vector<std::pair<int, int>> gap_sides_b; // block 2's sides, listed after block 1's
  for (int block = 1; block <= 2; ++block)
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = (block == 1 ? 0 : nx / 2); i < (block == 1 ? nx / 2 : nx); ++i)
        {
          const int cell = mesh.n_cells();
          mesh.add_cell(CellType::hex8,
                        {node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                         node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                         node(i, j + 1, k + 1)},
                        block);
          if (i == 0)
            add_side(mesh.side_sets[0], cell, 3);
          if (i == nx - 1)
            add_side(mesh.side_sets[1], cell, 1);
          if (j == 0)
            add_side(mesh.side_sets[2], cell, 0);
          if (j == ny - 1)
            add_side(mesh.side_sets[3], cell, 2);
          if (k == 0)
            add_side(mesh.side_sets[4], cell, 4);
          if (k == nz - 1)
            add_side(mesh.side_sets[5], cell, 5);
          if (i == nx / 2 - 1)
            add_side(gap, cell, 1);
          if (i == nx / 2)
            gap_sides_b.emplace_back(cell, 3);
        }
  for (const auto &[cell, face] : gap_sides_b)
    add_side(gap, cell, face);
  // The mid-planes y = 0 and z = 0 on request: the lower side's faces, then the upper's.
  for (const auto &[wanted, id, axis, name] :
       {std::tuple{mid_y, 11, 1, "mid_y"}, std::tuple{mid_z, 12, 2, "mid_z"}})
  {
    if (!wanted)
      continue;
    SideSet set;
    set.id = id;
    set.name = name;
    const int n = cells_[axis];
    // Local faces: y+ 2, y- 0, z+ 5, z- 4.
    const int upper_face = axis == 1 ? 2 : 5, lower_face = axis == 1 ? 0 : 4;
    for (int side = 0; side < 2; ++side)
      for (int c = 0; c < mesh.n_cells(); ++c)
      {
        const Span<const int> nodes = mesh.cell_nodes(c);
        const int index =
            axis == 1 ? nodes[0] / (nx + 1) % (ny + 1) : nodes[0] / ((nx + 1) * (ny + 1));
        if (side == 0 && index == n / 2 - 1)
          add_side(set, c, upper_face);
        if (side == 1 && index == n / 2)
          add_side(set, c, lower_face);
      }
    mesh.side_sets.push_back(std::move(set));
  }
  return mesh;
}
} // namespace kiln
