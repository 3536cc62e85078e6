// Tests app/simulation: the input tree validates the example decks, and
// Simulation::write_mesh (kiln --write-mesh) round-trips the mesh through
// Exodus II exactly.
// KILN_TEST_NP: 1 2
#include "app/simulation.hpp"
#include "io/input_reader.hpp"
#include "mesh/exodus_io.hpp"
#include "mesh/mesh_factory.hpp"
#include "support/simulation_runs.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <cstdio>

using kiln_test::inputs;

TEST(Simulation, WriteMeshRoundTrip)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string deck = inputs + "contact-box-close.xml";
  const kiln::Simulation sim(kiln::read_input(deck, *comm), deck, comm);
  const std::string path = "simulation_test_" + std::to_string(comm->getSize()) + ".exo";
  sim.write_mesh(path);
  comm->barrier();

  const kiln::Mesh read = kiln::read_exodus_mesh(path, 1.0);
  // The generated mesh, built independently of write_mesh.
  const Teuchos::ParameterList params = kiln::read_input(deck, *comm);
  Teuchos::ParameterList mesh_params = params.sublist("Mesh");
  mesh_params.validateParametersAndSetDefaults(kiln::MeshFactory::valid_parameters());
  const kiln::Mesh made = kiln::MeshFactory(mesh_params, deck).build();

  ASSERT_EQ(read.n_nodes(), 125);
  ASSERT_EQ(read.n_cells(), 64);
  for (int n = 0; n < made.n_nodes(); ++n)
    for (int d = 0; d < 3; ++d)
      EXPECT_EQ(read.coordinates[n][d], made.coordinates[n][d]);
  EXPECT_EQ(read.cell_node_ids, made.cell_node_ids);
  EXPECT_TRUE(read.cell_types == made.cell_types);
  EXPECT_EQ(read.block_id, made.block_id);
  ASSERT_EQ(read.side_sets.size(), made.side_sets.size());
  for (std::size_t s = 0; s < made.side_sets.size(); ++s)
  {
    EXPECT_EQ(read.side_sets[s].id, made.side_sets[s].id);
    EXPECT_EQ(read.side_sets[s].cells, made.side_sets[s].cells);
    EXPECT_EQ(read.side_sets[s].faces, made.side_sets[s].faces);
  }
  comm->barrier();
  if (comm->getRank() == 0)
    std::remove(path.c_str());
}

TEST(Simulation, ExampleInputsValidate)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  for (const char *name :
       {"contact-box-close.xml", "contact-box-open.xml", "contact-box-exodus.xml"})
  {
    const std::string deck = inputs + name;
    EXPECT_NO_THROW(kiln::Simulation(kiln::read_input(deck, *comm), deck, comm)) << deck;
  }
}
