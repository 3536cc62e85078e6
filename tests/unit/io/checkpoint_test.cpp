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
#include "support/accumulating_state_model.hpp"
#include "support/parallel.hpp"
#include "support/parameter_lists.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numeric>

using testing::AllOf;
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
                            {},      {1, 0.5, 0.25, rank},   {},         {}};
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
  // Named materials (issue 31) are part of the problem too.
  Teuchos::ParameterList steel = f.input;
  steel.sublist("Materials").sublist("steel").set("Density", 7900.0);
  EXPECT_THAT(kiln::RunFingerprint::of(f.mesh, f.dofs.layout(), steel).difference(f.fingerprint),
              HasSubstr("Kiln/Materials differs from the checkpoint's"));
}

TEST(Checkpoint, ForeignDamagedAndOtherRunsAreRefusedOnEveryRank)
{
  Fixture f;
  const std::string path = f.folder + "/good.h5";
  kiln::write_checkpoint(path, f.state(), {"1", "now", "deck.xml", "", 0, {}, {}, {}, {}, {}},
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

namespace
{
/// A copy of `good` at `path` (rank 0), changed by `change` on the opened file.
void damaged_copy(const std::string &good, const std::string &path,
                  const std::function<void(hid_t)> &change)
{
  std::filesystem::copy_file(good, path, std::filesystem::copy_options::overwrite_existing);
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  change(file);
  ASSERT_GE(H5Fclose(file), 0);
}

void set_attribute(const hid_t file, const char *name, const double value)
{
  const hid_t group = H5Gopen2(file, "state", H5P_DEFAULT);
  const hid_t a = H5Aopen(group, name, H5P_DEFAULT);
  ASSERT_GE(a, 0);
  const hid_t type = H5Aget_type(a);
  const int as_int = static_cast<int>(value);
  const herr_t status = H5Tget_class(type) == H5T_FLOAT ? H5Awrite(a, H5T_NATIVE_DOUBLE, &value)
                                                        : H5Awrite(a, H5T_NATIVE_INT, &as_int);
  if (status < 0)
    H5Eprint2(H5E_DEFAULT, stderr);
  EXPECT_GE(status, 0) << name;
  H5Tclose(type);
  H5Aclose(a);
  H5Gclose(group);
}
} // namespace

TEST(Checkpoint, DamagedStateOrScalarsAreRefused)
{
  Fixture f;
  const std::string good = f.folder + "/good.h5";
  const std::size_t n_pairs = static_cast<std::size_t>(f.fingerprint.n_pairs);
  kiln::write_checkpoint(good, f.state(),
                         {"1",
                          "now",
                          "deck.xml",
                          "",
                          0,
                          std::vector<int>(n_pairs, 1),
                          std::vector<double>(n_pairs, 2.5e6),
                          {},
                          {},
                          {}},
                         f.fingerprint, *f.comm);
  const double nan = std::nan("");
  if (f.comm->getRank() == 0)
  {
    // One bit of the stored state flipped (the Fletcher32 checksum sees it).
    haddr_t offset = HADDR_UNDEF;
    damaged_copy(good, f.folder + "/flipped.h5",
                 [&](const hid_t file)
                 {
                   // The dataset is one chunk (Fletcher32 needs a chunked layout).
                   const hid_t d = H5Dopen2(file, "state/x_1", H5P_DEFAULT);
                   const hid_t space = H5Dget_space(d);
                   hsize_t chunk_offset[2] = {0, 0}, size = 0;
                   unsigned mask = 0;
                   H5Dget_chunk_info(d, space, 0, chunk_offset, &mask, &offset, &size);
                   H5Sclose(space);
                   H5Dclose(d);
                 });
    ASSERT_NE(offset, HADDR_UNDEF);
    {
      std::fstream io(f.folder + "/flipped.h5", std::ios::in | std::ios::out | std::ios::binary);
      const auto at = static_cast<std::streamoff>(offset + 20);
      char byte = 0;
      io.seekg(at);
      io.read(&byte, 1);
      byte = static_cast<char>(byte ^ 0x04);
      io.seekp(at);
      io.write(&byte, 1);
      ASSERT_TRUE(io.good());
    }
    // A NaN written through HDF5 (the checksum is then right).
    damaged_copy(good, f.folder + "/nan.h5",
                 [&](const hid_t file)
                 {
                   const hid_t d = H5Dopen2(file, "state/x", H5P_DEFAULT);
                   const hid_t space = H5Dget_space(d);
                   std::vector<double> x(
                       static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
                   H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, x.data());
                   x[7] = nan;
                   H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, x.data());
                   H5Sclose(space);
                   H5Dclose(d);
                 });
    damaged_copy(good, f.folder + "/time_nan.h5",
                 [&](const hid_t file) { set_attribute(file, "time", nan); });
    damaged_copy(good, f.folder + "/time_huge.h5",
                 [](const hid_t file) { set_attribute(file, "time", 1e300); });
    damaged_copy(good, f.folder + "/negative_step.h5",
                 [](const hid_t file) { set_attribute(file, "last_step", -1.0); });
    damaged_copy(good, f.folder + "/negative_steps.h5",
                 [](const hid_t file) { set_attribute(file, "steps", -4.0); });
  }
  f.comm->barrier();
  const auto map = f.dofs.owned_dof_map();
  const auto message = [&](const std::string &name)
  {
    return kiln_test::input_error_message(
        [&] { kiln::read_checkpoint(f.folder + "/" + name, f.fingerprint, map, *f.comm); });
  };
  EXPECT_THAT(message("flipped.h5"),
              AllOf(HasSubstr("flipped.h5: cannot read the checkpoint: dataset x_1"),
                    HasSubstr("Fletcher32")));
  EXPECT_THAT(message("nan.h5"),
              HasSubstr("nan.h5: cannot read the checkpoint: its state (state/x, x_1 or x_2) "
                        "holds values that are not finite numbers"));
  EXPECT_THAT(message("time_nan.h5"), HasSubstr("its attribute state/time = nan is out of range"));
  EXPECT_THAT(message("time_huge.h5"),
              HasSubstr("its attribute state/time = 1e+300 is out of range (a finite number in "
                        "[0, 1e+15] s is expected): a damaged checkpoint"));
  EXPECT_THAT(message("negative_step.h5"), HasSubstr("its attribute state/last_step = -1"));
  EXPECT_THAT(message("negative_steps.h5"),
              HasSubstr("its attribute state/steps = -4 is negative"));
  EXPECT_NO_THROW(kiln::read_checkpoint(good, f.fingerprint, map, *f.comm));
  f.comm->barrier();
}

TEST(Checkpoint, NonFiniteStateIsNotWritten)
{
  Fixture f;
  kiln::TimeStepper::State s = f.state();
  if (f.comm->getRank() == f.comm->getSize() - 1 && s.x->getLocalLength() > 0)
    s.x->getDataNonConst()[0] = std::nan("");
  const std::string path = f.folder + "/nan_state.h5";
  try
  {
    kiln::write_checkpoint(path, s, {"1", "now", "deck.xml", "", 0, {}, {}, {}, {}, {}},
                           f.fingerprint, *f.comm);
    ADD_FAILURE() << "a NaN state was written";
  }
  catch (const kiln::RunError &e)
  {
    EXPECT_THAT(e.what(), HasSubstr("nan_state.h5: the state at t = 53 s holds values that are "
                                    "not finite numbers (NaN or Inf); it is not written"));
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  f.comm->barrier();
}

TEST(Checkpoint, UnwritableFolderIsAWriteError)
{
  Fixture f;
  try
  {
    kiln::write_checkpoint(f.folder + "/no/such/folder/c.h5", f.state(),
                           {"1", "now", "deck.xml", "", 0, {}, {}, {}, {}, {}}, f.fingerprint,
                           *f.comm);
    ADD_FAILURE() << "no error";
  }
  catch (const kiln::WriteError &e)
  {
    EXPECT_THAT(e.what(), HasSubstr("c.h5: cannot write the checkpoint: cannot create the file "
                                    "(No such file or directory); nothing was put in its place"));
  }
  f.comm->barrier();
}

namespace
{
/// A state at the quadrature points of `owned` (global cells) whose values depend on the cell
/// and the point alone: cell c has 1 + c % 3 points, every fifth none (a stateless model).
kiln::QuadratureState cell_state(const std::vector<int> &owned,
                                 const std::vector<std::string> &names = {"eqps", "back_stress_xx"},
                                 const bool values = true)
{
  std::vector<int> points;
  for (const int c : owned)
    points.push_back(c % 5 == 0 ? 0 : 1 + c % 3);
  kiln::QuadratureState s(names, owned, points);
  if (values)
    for (int c = 0; c < s.n_cells(); ++c)
      for (int q = 0; q < s.n_points(c); ++q)
        for (int k = 0; k < s.n_state(); ++k)
          s.current(c, q)[k] = std::sin(1.0 + owned[c]) * (k + 1) + 0.25 * q;
  s.commit();
  return s;
}

/// The cells of the mesh all on one rank, and its unknowns there.
struct OneRank
{
  OneRank(const kiln::Mesh &mesh, const Teuchos::RCP<const Teuchos::Comm<int>> &one)
      : comm(one),
        dofs(mesh, std::vector<int>(mesh.n_cells(), 0), one, kiln::DofLayout{true, true, true})
  {
  }
  Teuchos::RCP<const Teuchos::Comm<int>> comm;
  kiln::DofManager dofs;
};

/// A checkpoint's info with the contact state of the mesh's gap pairs (all open).
kiln::CheckpointInfo plain_info(const kiln::Mesh &mesh)
{
  kiln::CheckpointInfo info{"1", "now", "deck.xml", "", 0, {}, {}, {}, {}, {}};
  info.active.assign(mesh.gap_pairs.size(), 0);
  info.traction.assign(mesh.gap_pairs.size(), 0.0);
  return info;
}
} // namespace

TEST(Checkpoint, QuadratureStateReadBackBitForBit)
{
  Fixture f;
  const kiln::QuadratureState written = cell_state(f.dofs.owned_cells());
  const std::string path = f.folder + "/state.h5";
  kiln::write_checkpoint(path, f.state(), plain_info(f.mesh), f.fingerprint, *f.comm, &written);
  kiln::QuadratureState read = cell_state(f.dofs.owned_cells(), {"eqps", "back_stress_xx"}, false);
  ASSERT_FALSE(kiln_test::same_bits(read, written));
  kiln::read_checkpoint(path, f.fingerprint, f.dofs.owned_dof_map(), *f.comm, &read);
  EXPECT_TRUE(kiln_test::same_bits(read, written));
  // Components are read by name, not by position.
  kiln::QuadratureState swapped =
      cell_state(f.dofs.owned_cells(), {"back_stress_xx", "eqps"}, false);
  kiln::read_checkpoint(path, f.fingerprint, f.dofs.owned_dof_map(), *f.comm, &swapped);
  EXPECT_EQ(swapped.old_component(0), written.old_component(1));
  EXPECT_EQ(swapped.old_component(1), written.old_component(0));
}

TEST(Checkpoint, QuadratureStateReadOnAnotherNumberOfRanks)
{
  // Written on every rank, read on rank 0 alone; written on rank 0 alone, read on every rank.
  Fixture f;
  const Teuchos::RCP<const Teuchos::Comm<int>> one = f.comm->split(f.comm->getRank(), 0);
  const std::string many_ranks = f.folder + "/many.h5", one_rank = f.folder + "/one.h5";
  const kiln::QuadratureState on_every_rank = cell_state(f.dofs.owned_cells());
  kiln::write_checkpoint(many_ranks, f.state(), plain_info(f.mesh), f.fingerprint, *f.comm,
                         &on_every_rank);
  if (f.comm->getRank() == 0)
  {
    const OneRank r(f.mesh, one);
    std::vector<int> all(f.mesh.n_cells());
    std::iota(all.begin(), all.end(), 0);
    kiln::QuadratureState read = cell_state(all, {"eqps", "back_stress_xx"}, false);
    kiln::read_checkpoint(many_ranks, f.fingerprint, r.dofs.owned_dof_map(), *one, &read);
    EXPECT_TRUE(kiln_test::same_bits(read, cell_state(all)));

    // The state of the same values, written by one rank.
    kiln::TimeStepper::State s;
    s.x = Teuchos::rcp(new Tpetra::Vector<>(r.dofs.owned_dof_map()));
    s.x_1 = Teuchos::rcp(new Tpetra::Vector<>(r.dofs.owned_dof_map()));
    s.x_2 = Teuchos::rcp(new Tpetra::Vector<>(r.dofs.owned_dof_map()));
    const kiln::QuadratureState on_one_rank = cell_state(all);
    kiln::write_checkpoint(one_rank, s, plain_info(f.mesh), f.fingerprint, *one, &on_one_rank);
  }
  f.comm->barrier();
  kiln::QuadratureState read = cell_state(f.dofs.owned_cells(), {"eqps", "back_stress_xx"}, false);
  kiln::read_checkpoint(one_rank, f.fingerprint, f.dofs.owned_dof_map(), *f.comm, &read);
  EXPECT_TRUE(kiln_test::same_bits(read, on_every_rank));
}

TEST(Checkpoint, QuadratureStateThatDiffersIsAnInputErrorOnEveryRank)
{
  Fixture f;
  const auto &owned = f.dofs.owned_cells();
  const std::string with = f.folder + "/with.h5", without = f.folder + "/without.h5";
  const kiln::QuadratureState written = cell_state(owned);
  kiln::write_checkpoint(with, f.state(), plain_info(f.mesh), f.fingerprint, *f.comm, &written);
  kiln::write_checkpoint(without, f.state(), plain_info(f.mesh), f.fingerprint, *f.comm);
  const auto message = [&](const std::string &file, kiln::QuadratureState *state)
  {
    return kiln_test::input_error_message(
        [&]
        { kiln::read_checkpoint(file, f.fingerprint, f.dofs.owned_dof_map(), *f.comm, state); });
  };
  kiln::QuadratureState needed = cell_state(owned);
  EXPECT_THAT(message(without, &needed),
              AllOf(HasSubstr(without + ": the checkpoint holds no state at the quadrature "
                                        "points, which this run's constitutive models need "
                                        "(components eqps, back_stress_xx)"),
                    HasSubstr("start this run anew (without --restart)")));
  EXPECT_THAT(message(with, nullptr),
              HasSubstr(with + ": the checkpoint holds state at the quadrature points "
                               "(components eqps, back_stress_xx) that this run's constitutive "
                               "models do not declare"));
  kiln::QuadratureState fewer = cell_state(owned, {"eqps"});
  EXPECT_THAT(message(with, &fewer),
              HasSubstr("has the components back_stress_xx that this run's constitutive models "
                        "do not declare"));
  kiln::QuadratureState more = cell_state(owned, {"eqps", "back_stress_xx", "hardening"});
  EXPECT_THAT(message(with, &more),
              HasSubstr("lacks the components hardening that this run's constitutive models need"));
  // Eight points in every cell (another element or quadrature).
  kiln::QuadratureState eight({"eqps", "back_stress_xx"}, owned, std::vector<int>(owned.size(), 8));
  EXPECT_THAT(message(with, &eight),
              AllOf(HasSubstr("quadrature points with state in the checkpoint and 8 in this run"),
                    HasSubstr("cell ")));
  // Without state on either side, nothing changes.
  EXPECT_NO_THROW(kiln::read_checkpoint(without, f.fingerprint, f.dofs.owned_dof_map(), *f.comm));
}
