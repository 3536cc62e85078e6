// Both kinds of gap in one run (issue 30, item 4: "the split-mesh gap of today stays, and both
// kinds can be used in one run"; doc/contact.md, "Split gaps and contact pairs in one run"):
// inputs/contact-box-nonmatching.xml (the seed's closing deck, its halves meshed apart, 4 x 4 x
// 4 cells for x < 0 and 5 x 3 x 6 for x > 0, the contact pair "cut" between the cut faces x = 0)
// on its mesh written here with two more side sets, split as gaps by Mesh/"Gap Side Sets":
// 11, the plane x = -L/4 of the half x < 0, and 21, the plane x = +L/5 of the half x > 0 (planes
// of the box frame, parallel to the pair). The box is then four bodies in a row along x: two
// split gaps (a node and its twin per pair, g0 = 0) and one mortar pair (weighted partners).
// - At 150 s the spec's closed state to 1e-9 (every cell's stress, strain and thermal strain,
//   every node's displacement and temperature, every gap node's and pair row's contact pressure
//   2.288e7 Pa), np 1 and 2; both kinds' outputs present and consistent: the split gaps' gap
//   grids /gap and /gap_21 (HDF5, XDMF, CSV tables, each table's sum of pressure x area = the
//   history's normal_force_gap11 / _gap21) and the pair's /pair_cut (check_pair_output); the
//   log names each kind ("gap pairs" of the split gaps, the pair's "secondary nodes"), and so
//   do the step lines, the summary ("gap closed at", "pair "cut" closed at") and the end-of-run
//   list of files ("gap tables", "pair tables (cut)").
// - Restarted from the checkpoint at 53 s (both kinds closed), the same state at 150 s as the
//   uninterrupted run; the restart line counts both kinds apart.
// - One split gap (x = -L/4) and the pair to 53 s: the gap's log lines name it beside the pair.
// - Split gaps that cross the pair (the planes z = 0 of either half, which meet the cut faces):
//   a node of a pair on a split gap is refused, on every rank, naming the node, the gap and the
//   pair.
// KILN_TEST_NP: 1 2
#include "app/simulation.hpp"
#include "base/errors.hpp"
#include "mesh/box_mesh_generator.hpp"
#include "mesh/exodus_io.hpp"
#include "physics/coupled_problem.hpp"
#include "support/contact_box.hpp"
#include "support/contact_box_runs.hpp"
#include "support/results_files.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

namespace
{
using namespace kiln_test;

constexpr double L = 0.04;

/// A plane of the box frame in one half: side set `id` gets every face of the cells of block
/// `block` whose corners are all at coordinate `at` along `axis`.
struct Plane
{
  int id;
  int block;
  int axis;
  double at;
};

/// The mesh of inputs/contact-box-nonmatching.xml (its Box, rotated) with the side sets of
/// `planes` added, written by rank 0 to `path` (collective). The faces are found on the same
/// box unrotated (the same numbering).
void write_mesh(const std::string &path, const std::vector<Plane> &planes)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  if (comm->getRank() == 0)
  {
    Teuchos::ParameterList box = kiln::BoxMeshGenerator::valid_parameters();
    box.set("Cells", Teuchos::Array<int>({8, 4, 4}));
    box.set("Second Half Cells", Teuchos::Array<int>({5, 3, 6}));
    const kiln::Mesh flat = kiln::BoxMeshGenerator(box, "test box").generate();
    box.set("Phi", 45.0).set("Theta", -30.0);
    kiln::Mesh mesh = kiln::BoxMeshGenerator(box, "test box").generate();
    for (const Plane &plane : planes)
    {
      kiln::SideSet set{plane.id, "plane_" + std::to_string(plane.id), {}, {}};
      for (int c = 0; c < flat.n_cells(); ++c)
      {
        if (flat.block_id[c] != plane.block)
          continue;
        const auto nodes = flat.cell_nodes(c);
        const kiln::ReferenceCell &ref = flat.reference_cell(c);
        for (int f = 0; f < ref.n_faces(); ++f)
        {
          bool on = true;
          for (const int n : ref.face_nodes(f))
            on = on && std::abs(flat.coordinates[nodes[n]][plane.axis] - plane.at) < 1e-12;
          if (on)
          {
            set.cells.push_back(c);
            set.faces.push_back(f);
          }
        }
      }
      ASSERT_FALSE(set.cells.empty()) << "side set " << plane.id;
      mesh.side_sets.push_back(set);
    }
    kiln::write_exodus_mesh(mesh, path);
  }
  comm->barrier();
}

/// inputs/contact-box-nonmatching.xml on the mesh file `mesh` with the split gaps `gaps`, its
/// results at `base` at `times` (contact_box_deck's tolerances).
Teuchos::ParameterList deck(const std::string &mesh, const std::vector<int> &gaps,
                            const std::string &base, const std::vector<double> &times)
{
  Teuchos::ParameterList input =
      contact_box_deck("contact-box-nonmatching.xml", MeshKind::generated, base, times);
  input.remove("Mesh");
  Teuchos::ParameterList &m = input.sublist("Mesh");
  m.set("Type", "Exodus");
  m.set("Gap Side Sets", Teuchos::Array<int>(gaps.begin(), gaps.end()));
  m.sublist("Exodus").set("File", mesh).set("Coordinate Scale", 1.0);
  input.sublist("Mechanics").set("Free Motions", "Minimum Norm");
  return input;
}

std::string text_of(const std::string &path)
{
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// The split gap `name` ("gap", "gap_21") of the run at `base` at output step 3 (150 s):
/// its HDF5 surface and XDMF grid are there, its CSV table has every pair closed with the
/// pressure `pressure` to 1e-9, and its pressures times areas sum to the history's
/// normal_force_<column>, its areas to contact_area_<column> (the gap's area, L^2).
void check_split_gap_output(const std::string &base, const std::string &name,
                            const std::string &column, const double pressure)
{
  SCOPED_TRACE("the output of the split gap " + name);
  const std::string h5 = base + ".h5";
  EXPECT_FALSE(read_dataset(h5, "/" + name + "/coordinates").empty());
  EXPECT_EQ(read_dataset(h5, "/" + name + "/steps/000003/contact_pressure").size() > 0, true);
  EXPECT_NE(text_of(base + ".xmf").find("<Grid Name=\"" + name + "_000003\""), std::string::npos);
  const std::string csv = base + "." + name + "-000003.csv";
  const std::vector<double> P = csv_column(csv, "contact_pressure");
  const std::vector<double> area = csv_column(csv, "area");
  const std::vector<double> active = csv_column(csv, "contact_active");
  ASSERT_FALSE(P.empty()) << csv;
  ASSERT_EQ(area.size(), P.size());
  double force = 0.0, total = 0.0;
  for (std::size_t k = 0; k < P.size(); ++k)
  {
    EXPECT_NEAR(P[k], pressure, 1e-9 * pressure) << csv << ": row " << k;
    EXPECT_EQ(active[k], 1.0) << csv << ": row " << k;
    force += P[k] * area[k];
    total += area[k];
  }
  EXPECT_NEAR(total, L * L, 1e-12 * L * L);
  const double history_force = read_dataset(h5, "/history/normal_force_" + column).back();
  const double history_area = read_dataset(h5, "/history/contact_area_" + column).back();
  EXPECT_NEAR(history_force, force, 1e-12 * force);
  EXPECT_NEAR(history_area, L * L, 1e-12 * L * L);
  EXPECT_NEAR(history_force, pressure * L * L, 1e-9 * pressure * L * L);
}

/// Runs `input` with its log captured (rank 0's; "" on the others).
std::string run_logged(kiln::Simulation &sim)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  if (comm->getRank() == 0)
    testing::internal::CaptureStdout();
  sim.run();
  return comm->getRank() == 0 ? testing::internal::GetCapturedStdout() : std::string();
}

bool has(const std::string &log, const std::string &line)
{
  return log.find(line) != std::string::npos;
}
} // namespace

TEST(ContactBoxSplitAndPair, ClosedStateWithSplitGapsAndAPairRestarted)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = temporary_base("split_and_pair", *comm);
  const std::string mesh = base + ".mesh.exo";
  // x = -L/4 in the half x < 0 (4 cells along x: a cell face) and x = +L/5 in the half x > 0
  // (5 cells along x).
  write_mesh(mesh, {{11, 1, 0, -L / 4}, {21, 2, 0, L / 5}});
  const std::string label = "the nonmatching box with split gaps 11 and 21";
  const std::vector<double> times = {0.0, 50.0, 53.0, 150.0};
  const kiln_test::Run r = run(deck(mesh, {11, 21}, base, times), label, true);
  // The mesh: 64 + 90 cells; the gaps' pairs: 5 x 5 nodes on x = -L/4, 4 x 7 on x = L/5.
  EXPECT_EQ(r.mesh.n_cells(), 64 + 90);
  EXPECT_EQ(r.n_gap_pairs, 25u + 28u);
  EXPECT_EQ(r.n_pair_rows, 28u);
  const double pressure = spec_closed_gap_state(308.0).contact_pressure;
  if (comm->getRank() == 0)
  {
    const std::string h5 = base + ".h5";
    // To 1e-9 of each tensor's largest component, the components that are 0 included (the
    // stress there to 1e-9 x 2.288e7 Pa: the heat crosses two gaps and the pair, and the
    // temperature's lag behind 308 K, 5e-9 K, leaves them at 2e-3 Pa).
    const UniformState closed = spec_closed_gap_state(308.0);
    check_uniform_state(label, h5, 3, 150.0, 308.0, closed, true,
                        {1e-9, 1e-9 * pressure, zero_strain_tolerance, 1e-9 * 10.0}, r);
    // At 0 s (288 K) the bodies between the gaps are held along x by nothing but the gaps and
    // the pair, which open: Free Motions = Minimum Norm puts them where they touch.
    check_pair_output(label, base, pressure, false);
    check_split_gap_output(base, "gap", "gap11", pressure);
    check_split_gap_output(base, "gap_21", "gap21", pressure);
  }

  // Restarted at 53 s (every gap and the pair closed): the same state at 150 s.
  const std::string part = temporary_base("split_and_pair_part", *comm);
  {
    Teuchos::ParameterList first = deck(mesh, {11, 21}, part, {0.0, 50.0, 53.0});
    first.sublist("Checkpoint").set("At End", true);
    kiln::Simulation sim(first, label, comm);
    const std::string log = run_logged(sim);
    if (comm->getRank() == 0)
    {
      // Each kind named as it is (the split gaps' node pairs, the pair's secondary nodes).
      EXPECT_TRUE(has(log, "contact (pair \"cut\") at t = ")) << log;
      EXPECT_TRUE(has(log, "28 of 28 secondary nodes in contact (was ")) << log;
      EXPECT_TRUE(has(log, ": the pair has closed\n")) << log;
      EXPECT_TRUE(has(log, "of 25 gap pairs in contact")) << log;
      EXPECT_TRUE(has(log, "of 28 gap pairs in contact")) << log;
      // The step lines and the summary: the split gaps' node pairs and the pair's nodes.
      EXPECT_TRUE(has(log, "53/53 pairs in contact, 28/28 contact-pair nodes in contact")) << log;
      EXPECT_TRUE(has(log, "\ngap closed at: 53 s\ngap opened at: never\n")) << log;
      // The pair closes at 53 s. Before, Minimum Norm holds the bodies touching at a node
      // with a pressure of round-off size (1e-6 Pa at most), so that node may leave and re-enter
      // contact at times that depend on round-off (Newton's start, the solver): the step lines
      // count it, the summary's events do not (ContactEvents): it never carried a load.
      EXPECT_TRUE(has(log, "\npair \"cut\" closed at: 53 s\npair \"cut\" opened at: never\n"))
          << log;
      // Nor do the log's lines call them openings (the split gaps touch in the same way).
      EXPECT_FALSE(has(log, "has opened")) << log;
      EXPECT_TRUE(has(log, "gap tables: " + part + ".gap-000000.csv to ")) << log;
      EXPECT_TRUE(has(log, "gap tables (2): " + part + ".gap_21-000000.csv to ")) << log;
      EXPECT_TRUE(has(log, "pair tables (cut): " + part + ".pair_cut-000000.csv to ")) << log;
    }
  }
  {
    Teuchos::ParameterList second = deck(mesh, {11, 21}, part, times);
    kiln::Simulation sim(second, label, comm);
    sim.set_restart(part + ".checkpoint.h5");
    const std::string log = run_logged(sim);
    if (comm->getRank() == 0)
    {
      EXPECT_TRUE(has(log, "; 53 of 53 gap pairs and 28 of 28 contact-pair nodes in contact\n"))
          << log;
    }
  }
  if (comm->getRank() == 0)
  {
    double t = 0.0, t_restarted = 0.0;
    const std::vector<double> u = read_last_step(base + ".h5", "displacement", t);
    const std::vector<double> v = read_last_step(part + ".h5", "displacement", t_restarted);
    EXPECT_EQ(t, 150.0);
    EXPECT_EQ(t_restarted, 150.0);
    ASSERT_EQ(u.size(), v.size());
    double scale = 0.0, difference = 0.0;
    for (std::size_t k = 0; k < u.size(); ++k)
    {
      scale = std::max(scale, std::abs(u[k]));
      difference = std::max(difference, std::abs(u[k] - v[k]));
    }
    EXPECT_LE(difference, 1e-9 * scale) << "the restarted run's displacement at 150 s";
    std::cout << label << ": restarted at 53 s, max |u - u_restarted| at 150 s = " << difference
              << " m (max |u| " << scale << " m)\n";
  }
  remove_results(part, *comm);
  remove_results(base, *comm);
}

TEST(ContactBoxSplitAndPair, OneSplitGapIsNamedBesideThePair)
{
  // One split gap (x = -L/4) and the pair, to 53 s: the gap's lines name it, as with several.
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = temporary_base("one_split_and_pair", *comm);
  const std::string mesh = base + ".mesh.exo";
  write_mesh(mesh, {{11, 1, 0, -L / 4}});
  kiln::Simulation sim(deck(mesh, {11}, base, {0.0, 53.0}), "one split gap and the pair", comm);
  const std::string log = run_logged(sim);
  if (comm->getRank() == 0)
  {
    EXPECT_TRUE(has(log, "contact (gap side set 11) at t = 53 s: 25 of 25 gap pairs in contact"))
        << log;
    EXPECT_TRUE(has(log, "contact (pair \"cut\") at t = 53 s: 28 of 28 secondary nodes")) << log;
    EXPECT_FALSE(has(log, "\ncontact at t = ")) << log;
  }
  remove_results(base, *comm);
}

TEST(ContactBoxSplitAndPair, SplitGapCrossingThePairIsRefused)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = temporary_base("split_crossing_pair", *comm);
  const std::string mesh = base + ".mesh.exo";
  // The planes z = 0 of the half x < 0 (12: its nodes on x = 0 are the pair's primary nodes,
  // the partners of its rows) and of the half x > 0 (22: the pair's secondary nodes, its rows).
  write_mesh(mesh, {{12, 1, 2, 0.0}, {22, 2, 2, 0.0}});
  for (const int gap : {12, 22})
  {
    SCOPED_TRACE("split gap " + std::to_string(gap));
    try
    {
      kiln::Simulation sim(deck(mesh, {gap}, base, {0.0, 150.0}), "crossing", comm);
      sim.setup();
      ADD_FAILURE() << "no error for the split gap " << gap << " crossing the pair";
    }
    catch (const kiln::InputError &e)
    {
      const std::string message = e.what();
      if (comm->getRank() == 0)
        std::cout << "split gap " << gap << " crossing the pair, refused: " << message << "\n";
      EXPECT_TRUE(has(message, "Mechanics/Contact")) << message;
      EXPECT_TRUE(has(message, "and on pair \"cut\"")) << message;
      EXPECT_TRUE(has(message, "cannot be on another pair or gap")) << message;
    }
  }
  remove_results(base, *comm);
}
