// Tests src/io/checkpoint.cpp: a checkpoint read back holds the state bit for bit (time, steps,
// counters, the three vectors of unknowns) on the ranks that read it; the fingerprint tells
// which of mesh, unknowns or problem blocks differ; a checkpoint of another run, a foreign
// file and a damaged one are refused with one clear message on every rank; the file appears
// only once complete.
// KILN_TEST_NP: 1 2
#include "io/checkpoint.hpp"

#include "base/errors.hpp"
#include "mesh/box_mesh_generator.hpp"
#include "mesh/gap_splitter.hpp"
#include "mesh/metis_partitioner.hpp"
#include "support/parallel.hpp"
#include "support/parameter_lists.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using testing::HasSubstr;

namespace
{
struct Fixture
{
  Teuchos::RCP<const Teuchos::Comm<int>> comm = Teuchos::DefaultComm<int>::getComm();
  kiln::Mesh mesh = []
  {
    kiln::Mesh m =
        kiln::BoxMeshGenerator(kiln::BoxMeshGenerator::valid_parameters(), "test/Box").generate();
    kiln::split_gap(m, 10, "test");
    return m;
  }();
  std::vector<int> cell_rank = kiln::partition_cells(mesh, *comm, "test");
  kiln::DofManager dofs{mesh, cell_rank, comm, kiln::DofLayout{true, true, true}};
  Teuchos::ParameterList input = []
  {
    Teuchos::ParameterList p("Kiln");
    p.set("Physics", "Thermo-Elasticity");
    for (const char *block : {"Mesh", "Material", "Thermal", "Mechanics"})
      p.sublist(block).set("Tag", std::string(block));
    return p;
  }();
  kiln::RunFingerprint fingerprint = kiln::RunFingerprint::of(mesh, dofs.layout(), input);
  std::string folder = kiln_test::shared_test_folder(MPI_COMM_WORLD, "checkpoint");

  Fixture() = default;
  Fixture(const Fixture &) = delete;
  Fixture &operator=(const Fixture &) = delete;
  ~Fixture()
  {
    comm->barrier();
    if (comm->getRank() == 0)
      std::filesystem::remove_all(folder);
  }

  /// A state whose unknowns depend on their global ids alone (the same on any ranks).
  kiln::TimeStepper::State state() const
  {
    kiln::TimeStepper::State s;
    s.time = 53.0;
    s.next_step = 1.0 / 3.0;
    s.last_step = 2.9999999999999996;
    s.step_before = 4.5;
    s.accepted = 12;
    s.attempts = 14;
    s.statistics = {12, 1, 1, 13, 133};
    const auto map = dofs.owned_dof_map();
    for (auto *x : {&s.x, &s.x_1, &s.x_2})
    {
      *x = Teuchos::rcp(new Tpetra::Vector<>(map));
      auto v = (*x)->getDataNonConst();
      for (Teuchos::ArrayRCP<double>::size_type i = 0; i < v.size(); ++i)
        v[i] = std::sin(1.0 + static_cast<double>(map->getGlobalElement(i))) * (x == &s.x ? 1 : 2);
    }
    return s;
  }
};
} // namespace

TEST(Checkpoint, ReadBackBitForBit)
{
  Fixture f;
  const kiln::TimeStepper::State s = f.state();
  const double rank = f.comm->getRank();
  kiln::CheckpointInfo info{"1.2.3", "2026-11-23T00:00:00Z", "deck.xml", "<Kiln/>", 3, {},
                            {},      {1, 0.5, 0.25, rank}};
  for (std::size_t k = 0; k < f.mesh.gap_pairs.size(); ++k)
  {
    info.active.push_back(k % 2);
    info.traction.push_back(-1e6 * k);
  }
  const std::string path = f.folder + "/c.h5";
  kiln::write_checkpoint(path, s, info, f.fingerprint, *f.comm);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  const kiln::Checkpoint c =
      kiln::read_checkpoint(path, f.fingerprint, f.dofs.owned_dof_map(), *f.comm);
  EXPECT_EQ(c.state.time, s.time);
  EXPECT_EQ(c.state.next_step, s.next_step);
  EXPECT_EQ(c.state.last_step, s.last_step);
  EXPECT_EQ(c.state.step_before, s.step_before);
  EXPECT_EQ(c.state.accepted, 12);
  EXPECT_EQ(c.state.attempts, 14);
  EXPECT_EQ(c.state.statistics.linear_iterations, 133);
  EXPECT_EQ(c.info.output_steps, 3);
  EXPECT_EQ(c.info.input_xml, "<Kiln/>");
  EXPECT_EQ(c.info.active, info.active);
  EXPECT_EQ(c.info.traction, info.traction);
  EXPECT_EQ(c.info.preconditioner_origin, info.preconditioner_origin);
  EXPECT_EQ(c.fingerprint.difference(f.fingerprint), "");
  const auto a = s.x->getData(), b = c.state.x->getData();
  EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin()));
  const auto a2 = s.x_2->getData(), b2 = c.state.x_2->getData();
  EXPECT_TRUE(std::equal(a2.begin(), a2.end(), b2.begin()));
}

TEST(Checkpoint, FingerprintNamesWhatDiffers)
{
  Fixture f;
  kiln::Mesh moved = f.mesh;
  moved.coordinates[7][1] = std::nextafter(moved.coordinates[7][1], 1.0);
  EXPECT_THAT(kiln::RunFingerprint::of(moved, f.dofs.layout(), f.input).difference(f.fingerprint),
              HasSubstr("the mesh differs: it has the checkpoint's sizes but other coordinates"));
  EXPECT_THAT(kiln::RunFingerprint::of(f.mesh, kiln::DofLayout{true, false, false}, f.input)
                  .difference(f.fingerprint),
              HasSubstr("the unknowns differ: the checkpoint has temperature displacement "
                        "contact, this input temperature"));
  Teuchos::ParameterList other = f.input;
  other.sublist("Thermal").set("Tag", std::string("hotter"));
  EXPECT_THAT(kiln::RunFingerprint::of(f.mesh, f.dofs.layout(), other).difference(f.fingerprint),
              HasSubstr("Kiln/Thermal differs from the checkpoint's"));
}

TEST(Checkpoint, ForeignDamagedAndOtherRunsAreRefusedOnEveryRank)
{
  Fixture f;
  const std::string path = f.folder + "/good.h5";
  kiln::write_checkpoint(path, f.state(), {"1", "now", "deck.xml", "", 0, {}, {}, {}},
                         f.fingerprint, *f.comm);
  if (f.comm->getRank() == 0)
  {
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(f.folder + "/cut.h5", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    std::ofstream(f.folder + "/text.h5") << "not a checkpoint\n";
  }
  f.comm->barrier();
  const auto map = f.dofs.owned_dof_map();
  const auto message = [&](const std::string &file, const kiln::RunFingerprint &run) {
    return kiln_test::input_error_message([&] { kiln::read_checkpoint(file, run, map, *f.comm); });
  };
  EXPECT_THAT(message(f.folder + "/cut.h5", f.fingerprint),
              HasSubstr("cannot read the checkpoint"));
  EXPECT_THAT(message(f.folder + "/text.h5", f.fingerprint),
              HasSubstr("text.h5: cannot read the checkpoint: not an HDF5 file, or a damaged "
                        "(truncated) one"));
  EXPECT_THAT(message(f.folder + "/none.h5", f.fingerprint), HasSubstr("no such file"));
  Teuchos::ParameterList other = f.input;
  other.set("Physics", "Heat Conduction");
  EXPECT_THAT(message(path, kiln::RunFingerprint::of(f.mesh, f.dofs.layout(), other)),
              HasSubstr("cannot continue this run from the checkpoint: Kiln/\"Physics\" differs"));
  f.comm->barrier(); // every rank got here: none hung
}
