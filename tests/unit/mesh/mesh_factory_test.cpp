// Tests src/mesh/mesh_factory.cpp on Exodus files: a file Kiln wrote (in metres) read with a
// Coordinate Scale other than 1 is an InputError naming the parameter and the file, whether
// it comes from the input or from kiln --mesh; with scale 1 it is read unchanged, and a Cubit
// file (no Kiln record) is scaled as asked; counts() gives the cells and nodes of the mesh
// (after the gap split) without building it.
// KILN_TEST_NP: 1
#include "mesh/mesh_factory.hpp"

#include "base/errors.hpp"
#include "mesh/box_mesh_generator.hpp"
#include "mesh/exodus_io.hpp"
#include "mesh/gap_splitter.hpp"
#include "support/parameter_lists.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <unistd.h>

namespace
{
using testing::HasSubstr;

const std::string where = "in.xml: Kiln/Mesh";

Teuchos::ParameterList exodus_params(const std::string &file, const double scale)
{
  Teuchos::ParameterList p = kiln::MeshFactory::valid_parameters();
  p.set("Type", "Exodus");
  p.sublist("Exodus").set("File", file);
  p.sublist("Exodus").set("Coordinate Scale", scale);
  return p;
}

/// The default box written by Kiln into a file removed at scope end.
class WrittenBox
{
public:
  WrittenBox() : path_("kiln-mesh-factory-test-" + std::to_string(::getpid()) + ".exo")
  {
    mesh_ =
        kiln::BoxMeshGenerator(kiln::BoxMeshGenerator::valid_parameters(), "test/Box").generate();
    kiln::write_exodus_mesh(mesh_, path_, {10});
  }
  ~WrittenBox() { std::remove(path_.c_str()); }
  WrittenBox(const WrittenBox &) = delete;
  WrittenBox &operator=(const WrittenBox &) = delete;
  const std::string &path() const { return path_; }
  const kiln::Mesh &mesh() const { return mesh_; }

private:
  std::string path_;
  kiln::Mesh mesh_;
};

std::string build_error(const Teuchos::ParameterList &params, const std::string &mesh_file = "")
{
  return kiln_test::input_error_message([&]
                                        { kiln::MeshFactory(params, where, mesh_file).build(); });
}
} // namespace

TEST(MeshFactory, KilnMeshWithCoordinateScaleIsAnInputError)
{
  const WrittenBox box;
  const std::string message = build_error(exodus_params(box.path(), 0.01));
  EXPECT_THAT(message, HasSubstr(where + "/Exodus/\"Coordinate Scale\": is 0.01, but"));
  EXPECT_THAT(message, HasSubstr("\"" + box.path() + "\" was written by Kiln"));
  EXPECT_THAT(message, HasSubstr("in metres already"));
  EXPECT_THAT(message, HasSubstr("Set \"Coordinate Scale\" to 1 for this file"));
}

TEST(MeshFactory, KilnMeshGivenByMeshOptionWithTheDecksScaleIsAnInputError)
{
  // kiln --mesh written.exo with a deck made for a Cubit mesh in cm (the example deck).
  const WrittenBox box;
  const std::string message =
      build_error(exodus_params("../shared/meshes/rotated-cube.exo", 0.01), box.path());
  EXPECT_THAT(message, HasSubstr("\"Coordinate Scale\""));
  EXPECT_THAT(message, HasSubstr(box.path()));
}

TEST(MeshFactory, KilnMeshWithScaleOneIsReadUnchanged)
{
  const WrittenBox box;
  const kiln::Mesh mesh = kiln::MeshFactory(exodus_params(box.path(), 1.0), where).build();
  EXPECT_EQ(mesh.coordinates, box.mesh().coordinates);
  EXPECT_EQ(mesh.cell_node_ids, box.mesh().cell_node_ids);
  EXPECT_TRUE(mesh.cell_types == box.mesh().cell_types);
}

TEST(MeshFactory, CubitMeshIsScaled)
{
  const std::string cubit = std::string(KILN_SHARED_DIR) + "/meshes/aligned-cube.exo";
  const kiln::Mesh in_cm = kiln::MeshFactory(exodus_params(cubit, 1.0), where).build();
  const kiln::Mesh in_m = kiln::MeshFactory(exodus_params(cubit, 0.01), where).build();
  ASSERT_EQ(in_m.n_nodes(), in_cm.n_nodes());
  for (int n = 0; n < in_m.n_nodes(); ++n)
    for (int d = 0; d < 3; ++d)
      EXPECT_DOUBLE_EQ(in_m.coordinates[n][d], 0.01 * in_cm.coordinates[n][d]);
}

TEST(MeshFactory, CountsAreThoseOfTheMeshWithoutBuildingIt)
{
  // A box with its gap split: the nodes of the plane x = 0 get twins.
  Teuchos::ParameterList box = kiln::MeshFactory::valid_parameters();
  box.sublist("Box").set("Cells", kiln_test::ids({4, 2, 6}));
  const kiln::MeshFactory factory(box, where);
  const kiln::MeshFactory::Counts counts = factory.counts();
  kiln::Mesh mesh = factory.build();
  EXPECT_EQ(counts.cells, mesh.n_cells());
  split_gaps(mesh, factory.gap_side_sets(), where);
  EXPECT_EQ(counts.nodes, mesh.n_nodes());
  EXPECT_EQ(counts.source, where + "/Box/\"Cells\" = {4, 2, 6}");
  // An Exodus file's counts come from its header.
  const std::string cubit = std::string(KILN_SHARED_DIR) + "/meshes/rotated-cube.exo";
  const kiln::MeshFactory::Counts file =
      kiln::MeshFactory(exodus_params(cubit, 0.01), where).counts();
  EXPECT_EQ(file.cells, 64);
  EXPECT_EQ(file.nodes, 125);
  EXPECT_EQ(file.source, "the mesh file " + cubit);
  // A box that cannot be numbered is refused here already.
  box.sublist("Box").set("Cells", kiln_test::ids({2000, 2000, 2000}));
  EXPECT_THAT(kiln_test::input_error_message([&] { kiln::MeshFactory(box, where).counts(); }),
              HasSubstr("a Kiln mesh can number"));
}
