// Tests src/mesh/reference_cells.cpp against the Exodus library itself: for every volume type
// a one-element file with a side set of all its sides, read back by
// ex_get_side_set_node_list(), whose per-side node lists (corners and mid-side nodes and
// HEX27's face centres, in the library's own order) must equal ReferenceCell::face_nodes.
// KILN_TEST_NP: 1
#include "elements/reference_cell.hpp"

#include <exodusII.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
using kiln::CellType;
using kiln::ReferenceCell;

class ExodusSides : public ::testing::TestWithParam<CellType>
{
};

TEST_P(ExodusSides, FaceNodesAreTheExodusLibrarysSideNodes)
{
  const ReferenceCell &cell = ReferenceCell::of(GetParam());
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("kiln_sides_" + cell.name() + "_" + std::to_string(getpid()) + ".exo"))
                               .string();
  const int n = cell.n_nodes(), n_sides = cell.n_faces();
  int comp_ws = 8, io_ws = 8;
  int exo = ex_create(path.c_str(), EX_CLOBBER, &comp_ws, &io_ws);
  ASSERT_GE(exo, 0) << path;
  ASSERT_GE(ex_put_init(exo, "sides", 3, n, 1, 1, 0, 1), 0);
  std::vector<double> x(n), y(n), z(n);
  for (int i = 0; i < n; ++i)
  {
    x[i] = cell.node(i)[0];
    y[i] = cell.node(i)[1];
    z[i] = cell.node(i)[2];
  }
  ASSERT_GE(ex_put_coord(exo, x.data(), y.data(), z.data()), 0);
  ASSERT_GE(ex_put_block(exo, EX_ELEM_BLOCK, 1, cell.name().c_str(), 1, n, 0, 0, 0), 0);
  std::vector<int> conn(n);
  for (int i = 0; i < n; ++i)
    conn[i] = i + 1;
  ASSERT_GE(ex_put_conn(exo, EX_ELEM_BLOCK, 1, conn.data(), nullptr, nullptr), 0);
  std::vector<int> elements(n_sides, 1), sides(n_sides);
  for (int s = 0; s < n_sides; ++s)
    sides[s] = s + 1;
  ASSERT_GE(ex_put_set_param(exo, EX_SIDE_SET, 1, n_sides, 0), 0);
  ASSERT_GE(ex_put_set(exo, EX_SIDE_SET, 1, elements.data(), sides.data()), 0);
  ASSERT_GE(ex_close(exo), 0);

  float version = 0;
  exo = ex_open(path.c_str(), EX_READ, &comp_ws, &io_ws, &version);
  ASSERT_GE(exo, 0);
  std::vector<int> counts(n_sides), nodes(n_sides * 9);
  ASSERT_GE(ex_get_side_set_node_list(exo, 1, counts.data(), nodes.data()), 0);
  ex_close(exo);
  std::remove(path.c_str());

  int offset = 0;
  for (int s = 0; s < n_sides; ++s)
  {
    std::vector<int> exodus(nodes.begin() + offset, nodes.begin() + offset + counts[s]);
    for (int &node : exodus)
      --node;
    offset += counts[s];
    EXPECT_EQ(exodus, cell.face_nodes(s)) << cell.name() << " side " << s + 1;
  }
}

INSTANTIATE_TEST_SUITE_P(VolumeTypes, ExodusSides,
                         ::testing::ValuesIn(ReferenceCell::volume_types()),
                         [](const ::testing::TestParamInfo<CellType> &type_info)
                         { return ReferenceCell::of(type_info.param).name(); });
} // namespace
