#include "support/two_body_mesh.hpp"

#include "mesh/box_mesh_generator.hpp"
#include "mesh/hex_geometry.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <random>

namespace kiln_test
{
namespace
{
kiln::SideSet &side_set(kiln::Mesh &mesh, const int id)
{
  for (auto &s : mesh.side_sets)
    if (s.id == id)
      return s;
  kiln::SideSet s;
  s.id = id;
  s.name = "side_" + std::to_string(id);
  mesh.side_sets.push_back(s);
  std::sort(mesh.side_sets.begin(), mesh.side_sets.end(),
            [](const kiln::SideSet &a, const kiln::SideSet &b) { return a.id < b.id; });
  return side_set(mesh, id);
}
} // namespace

void add_body(kiln::Mesh &mesh, const std::array<int, 3> &cells, const BodyMap &map,
              const int block, const int bottom, const int top)
{
  const int first = mesh.n_nodes();
  const int nx = cells[0] + 1, ny = cells[1] + 1;
  for (int k = 0; k <= cells[2]; ++k)
    for (int j = 0; j <= cells[1]; ++j)
      for (int i = 0; i <= cells[0]; ++i)
        mesh.coordinates.push_back(
            map(double(i) / cells[0], double(j) / cells[1], double(k) / cells[2]));
  const auto node = [&](const int i, const int j, const int k)
  { return first + i + nx * (j + ny * k); };
  for (int k = 0; k < cells[2]; ++k)
    for (int j = 0; j < cells[1]; ++j)
      for (int i = 0; i < cells[0]; ++i)
      {
        const int c = mesh.n_cells();
        mesh.add_cell(kiln::CellType::hex8,
                      {node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                       node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                       node(i, j + 1, k + 1)},
                      block);
        // Exodus sides 5 (nodes 0 3 2 1, zeta = 0) and 6 (4 5 6 7, zeta = 1).
        if (k == 0)
        {
          side_set(mesh, bottom).cells.push_back(c);
          side_set(mesh, bottom).faces.push_back(4);
        }
        if (k == cells[2] - 1)
        {
          side_set(mesh, top).cells.push_back(c);
          side_set(mesh, top).faces.push_back(5);
        }
      }
  mesh.parent_node.clear();
  for (int n = 0; n < mesh.n_nodes(); ++n)
    mesh.parent_node.push_back(n);
}

kiln::Mesh two_flat_bodies(const std::array<int, 2> &n1, const std::array<int, 2> &n2,
                           const double gap)
{
  kiln::Mesh mesh;
  add_body(
      mesh, {n1[0], n1[1], 1},
      [](const double x, const double y, const double z) {
        return kiln::Point{x, y, -0.2 + 0.2 * z};
      },
      1, 3, 1);
  add_body(
      mesh, {n2[0], n2[1], 1},
      [gap](const double x, const double y, const double z) {
        return kiln::Point{x, y, gap + 0.2 * z};
      },
      2, 2, 4);
  return mesh;
}

kiln::Mesh two_cylinder_shells(const std::array<int, 2> &n1, const std::array<int, 2> &n2,
                               const double gap)
{
  // (angle, z, r) is right-handed like (x, y, z); zeta runs outwards.
  const auto shell = [](const double r0, const double r1)
  {
    return [r0, r1](const double a, const double z, const double r)
    {
      const double radius = r0 + (r1 - r0) * r;
      return kiln::Point{radius * std::cos(a), radius * std::sin(a), z};
    };
  };
  kiln::Mesh mesh;
  add_body(mesh, {n1[0], n1[1], 1}, shell(1.5, 2.0), 1, 3, 1);
  add_body(mesh, {n2[0], n2[1], 1}, shell(2.0 + gap, 2.5), 2, 2, 4);
  return mesh;
}

kiln::Mesh concentric_shells(const std::array<double, 4> &radii, const std::array<int, 2> &n1,
                             const std::array<int, 2> &n2)
{
  // (angle, z, r) is right-handed like (x, y, z); zeta runs outwards.
  const auto shell = [](const double r0, const double r1)
  {
    return [r0, r1](const double a, const double z, const double r)
    {
      const double radius = r0 + (r1 - r0) * r;
      return kiln::Point{radius * std::cos(a), radius * std::sin(a), z};
    };
  };
  kiln::Mesh mesh;
  add_body(mesh, {n1[0], 1, n1[1]}, shell(radii[0], radii[1]), 1, 3, 1);
  add_body(mesh, {n2[0], 1, n2[1]}, shell(radii[2], radii[3]), 2, 2, 4);
  // The side faces on the planes: Exodus sides 1 to 4 (faces 0 to 3) of each cell.
  const int face_nodes[4][4] = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {0, 3, 7, 4}};
  // Side set 5 + plane: angle 0, angle 1 rad, z = 0 (7), z = 1 (7).
  const std::array<std::function<bool(const kiln::Point &)>, 4> on_plane = {
      [](const kiln::Point &x) { return std::abs(x[1]) < 1e-12; },
      [](const kiln::Point &x)
      { return std::abs(x[1] * std::cos(1.0) - x[0] * std::sin(1.0)) < 1e-12; },
      [](const kiln::Point &x) { return std::abs(x[2]) < 1e-12; },
      [](const kiln::Point &x) { return std::abs(x[2] - 1.0) < 1e-12; }};
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int f = 0; f < 4; ++f)
      for (int plane = 0; plane < 4; ++plane)
        if (std::all_of(std::begin(face_nodes[f]), std::end(face_nodes[f]),
                        [&](const int i)
                        { return on_plane[plane](mesh.coordinates[mesh.cell_nodes(c)[i]]); }))
        {
          side_set(mesh, 5 + std::min(plane, 2)).cells.push_back(c);
          side_set(mesh, 5 + std::min(plane, 2)).faces.push_back(f);
        }
  return mesh;
}

void perturb(kiln::Mesh &mesh, const double amplitude)
{
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> uniform(-amplitude, amplitude);
  for (kiln::Point &x : mesh.coordinates)
    for (double &v : x)
      v += uniform(random);
}

void rotate(kiln::Mesh &mesh, const double phi_degrees, const double theta_degrees)
{
  for (kiln::Point &x : mesh.coordinates)
    x = rotated(x, phi_degrees, theta_degrees);
}

kiln::Point rotated(const kiln::Point &x, const double phi_degrees, const double theta_degrees,
                    const bool inverse)
{
  const auto A = kiln::rotation_matrix(phi_degrees, theta_degrees);
  kiln::Point y{0, 0, 0};
  for (int i = 0; i < 3; ++i)
    for (int d = 0; d < 3; ++d)
      y[i] += (inverse ? A[d][i] : A[i][d]) * x[d];
  return y;
}

Teuchos::ParameterList box_halves_parameters(const double gap, const std::string &cell_type)
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  p.set("Cells", Teuchos::Array<int>(Teuchos::tuple(8, 4, 4)));
  p.set("Second Half Cells", Teuchos::Array<int>(Teuchos::tuple(5, 3, 6)));
  p.set("Gap Width", gap);
  p.set("Phi", 45.0);
  p.set("Theta", -30.0);
  p.set("Cell Type", cell_type);
  return p;
}
} // namespace kiln_test
