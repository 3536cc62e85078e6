// Tests app/restart_plan: a new run continues nothing; a restart reads the checkpoint's output
// steps (the gap tables' first step) and refuses a checkpoint at the end of the run; it
// continues the results of its own run (BASE.h5, or BASE.running.h5 of a run cut off, moved to
// BASE.interrupted.h5) and keeps them whole until it passes them (its own files then under
// BASE.restarted), warns when they are missing, and refuses another run's results or results
// without a run fingerprint, naming the file and the checkpoint. The steps of a new run land on
// its start, the output times and every checkpoint time; a restart's on the later ones alone.
// KILN_TEST_NP: 1 2
#include "app/restart_plan.hpp"

#include "app/checkpoint_schedule.hpp"
#include "app/output_schedule.hpp"
#include "base/parameters.hpp"
#include "mesh/box_mesh_generator.hpp"
#include "mesh/metis_partitioner.hpp"
#include "support/parameter_lists.hpp"
#include "support/results_files.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <limits>
#include <sstream>

using kiln_test::input_error_message;
using kiln_test::values;
using testing::ElementsAre;
using testing::HasSubstr;

namespace
{
constexpr double none = -std::numeric_limits<double>::infinity();

struct Fixture
{
  Teuchos::RCP<const Teuchos::Comm<int>> comm = Teuchos::DefaultComm<int>::getComm();
  std::string base = kiln_test::temporary_base(
      testing::UnitTest::GetInstance()->current_test_info()->name(), *comm);
  std::ostringstream log;
  Teuchos::RCP<Teuchos::FancyOStream> out = Teuchos::fancyOStream(Teuchos::rcpFromRef(log));

  Fixture() = default;
  Fixture(const Fixture &) = delete;
  Fixture &operator=(const Fixture &) = delete;
  ~Fixture() { kiln_test::remove_results(base, *comm); }

  kiln::RestartPlan plan(const std::string &checkpoint, const std::string &digest = "ours")
  {
    return kiln::RestartPlan(checkpoint, base, ".h5", digest, comm, out);
  }

  /// Rank 0 writes results at `path` with the run fingerprint `digest` ("": none) and output
  /// steps at `times`, as a results file has them (/steps/NNNNNN, attribute time).
  void write_results(const std::string &path, const std::string &digest,
                     const std::vector<double> &times) const
  {
    if (comm->getRank() == 0)
    {
      const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
      const hid_t scalar = H5Screate(H5S_SCALAR);
      if (!digest.empty())
      {
        const hid_t type = H5Tcopy(H5T_C_S1);
        H5Tset_size(type, digest.size());
        const hid_t a = H5Acreate2(file, "run_fingerprint", type, scalar, H5P_DEFAULT, H5P_DEFAULT);
        H5Awrite(a, type, digest.data());
        H5Aclose(a);
        H5Tclose(type);
      }
      const hid_t steps = H5Gcreate2(file, "steps", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      for (std::size_t i = 0; i < times.size(); ++i)
      {
        const std::string name = "00000" + std::to_string(i);
        const hid_t step = H5Gcreate2(steps, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        const hid_t a = H5Acreate2(step, "time", H5T_IEEE_F64LE, scalar, H5P_DEFAULT, H5P_DEFAULT);
        H5Awrite(a, H5T_NATIVE_DOUBLE, &times[i]);
        H5Aclose(a);
        H5Gclose(step);
      }
      H5Gclose(steps);
      H5Sclose(scalar);
      H5Fclose(file);
    }
    comm->barrier();
  }
};
} // namespace

TEST(RestartPlan, NewRunContinuesNothing)
{
  Fixture f;
  f.write_results(f.base + ".h5", "another run's", {10.0});
  kiln::RestartPlan plan = f.plan("");
  EXPECT_TRUE(plan.fresh());
  EXPECT_EQ(plan.earlier_results(), "") << "a new run replaces the results, whoever wrote them";
  EXPECT_EQ(plan.first_gap_step(""), 0);
  EXPECT_NO_THROW(plan.check_time_left(100.0, 100.0, "deck.xml"));
  EXPECT_TRUE(plan.ahead(5.0, 5.0)) << "a new run's checkpoint at its start time is written";
  const kiln::RestartPlan::Kept kept = plan.kept(1.0, none);
  EXPECT_FALSE(kept.aside);
  EXPECT_FALSE(kept.results);
}

TEST(RestartPlan, ReadsTheCheckpointsOutputSteps)
{
  Fixture f;
  const kiln::Mesh mesh =
      kiln::BoxMeshGenerator(kiln::BoxMeshGenerator::valid_parameters(), "test/Box").generate();
  const std::vector<int> cell_rank = kiln::partition_cells(mesh, *f.comm, "test");
  const kiln::DofManager dofs(mesh, cell_rank, f.comm, kiln::DofLayout{true, false, false});
  Teuchos::ParameterList input("Kiln");
  input.set("Physics", "Heat Conduction");
  const kiln::RunFingerprint run = kiln::RunFingerprint::of(mesh, dofs.layout(), input);
  kiln::TimeStepper::State state;
  state.time = 53.0;
  for (auto *x : {&state.x, &state.x_1, &state.x_2})
  {
    *x = Teuchos::rcp(new Tpetra::Vector<>(dofs.owned_dof_map()));
    (*x)->putScalar(300.0);
  }
  const std::string checkpoint = f.base + ".checkpoint.h5";
  kiln::write_checkpoint(
      checkpoint, state,
      {"1.2.3", "2026-11-29T00:00:00Z", "deck.xml", "<Kiln/>", 4, {}, {}, {}, {}, {}}, run,
      *f.comm);

  kiln::RestartPlan plan = f.plan(checkpoint);
  EXPECT_FALSE(plan.fresh());
  EXPECT_EQ(plan.checkpoint(), checkpoint);
  const kiln::Checkpoint c = plan.read(run, dofs.owned_dof_map(), nullptr);
  EXPECT_EQ(c.state.time, 53.0);
  EXPECT_EQ(plan.output_steps(), 4);
  EXPECT_EQ(plan.first_gap_step(""), 4) << "without results to continue the tables go on";
  EXPECT_EQ(plan.first_gap_step(f.base + ".h5"), 0) << "continued results rewrite them";
  EXPECT_FALSE(plan.ahead(53.0, 53.0)) << "the checkpoint's own time is behind a restart";
  EXPECT_TRUE(plan.ahead(53.001, 53.0));
  EXPECT_NO_THROW(plan.check_time_left(53.0, 60.0, "deck.xml"));
  EXPECT_THAT(input_error_message([&] { plan.check_time_left(53.0, 53.0, "deck.xml"); }),
              HasSubstr(checkpoint + ": the checkpoint's time, t = 53 s, is at or past the end "
                                     "of this run, the last output time 53 s: there is nothing "
                                     "left to compute, and nothing was written. To go on, add "
                                     "later times to Kiln/Output/\"Times\" of deck.xml"));
  f.log.str("");
  plan.check_replayed(4, "r.h5");
  EXPECT_EQ(f.log.str(), "");
  plan.check_replayed(3, "r.h5");
  EXPECT_EQ(f.log.str(), "warning: the checkpoint was written after 4 output steps, but r.h5 "
                         "holds 3 up to its time\n");
}

TEST(RestartPlan, OwnResultsAreContinuedAndKeptUntilPassed)
{
  Fixture f;
  f.write_results(f.base + ".h5", "ours", {0.0, 10.0, 20.0});
  kiln::RestartPlan plan = f.plan("c.h5");
  EXPECT_EQ(plan.earlier_results(), f.base + ".h5");
  EXPECT_FALSE(plan.exodus_results());
  kiln::RestartPlan::Kept kept = plan.kept(15.0, none);
  EXPECT_TRUE(kept.aside);
  EXPECT_TRUE(kept.results);
  EXPECT_EQ(kept.end, 20.0);
  kept = plan.kept(20.0, none);
  EXPECT_FALSE(kept.aside) << "passed: this run's results replace them";
  kept = plan.kept(25.0, 30.0);
  EXPECT_TRUE(kept.aside) << "the history is not passed yet";
  EXPECT_FALSE(kept.results);
  EXPECT_EQ(kept.end, 30.0);
  EXPECT_EQ(plan.aside_base(), f.base + ".restarted");
  EXPECT_EQ(plan.aside(f.base + ".h5 and " + f.base + ".xmf"),
            f.base + ".restarted.h5 and " + f.base + ".restarted.xmf");
}

TEST(RestartPlan, CutOffResultsAreMovedAside)
{
  Fixture f;
  f.write_results(f.base + ".running.h5", "ours", {0.0, 10.0});
  kiln::RestartPlan plan = f.plan("c.h5");
  EXPECT_EQ(plan.earlier_results(), f.base + ".interrupted.h5");
  EXPECT_FALSE(std::filesystem::exists(f.base + ".running.h5"));
  EXPECT_TRUE(std::filesystem::exists(f.base + ".interrupted.h5"));
  EXPECT_THAT(f.log.str(), HasSubstr("results: " + f.base +
                                     ".running.h5 of a run that was cut "
                                     "off is kept as " +
                                     f.base + ".interrupted.h5\n"));
  EXPECT_FALSE(plan.kept(5.0, none).aside) << "no complete results to keep";
}

TEST(RestartPlan, MissingResultsWarn)
{
  Fixture f;
  kiln::RestartPlan plan = f.plan("c.h5");
  EXPECT_EQ(plan.earlier_results(), "");
  EXPECT_EQ(f.log.str(), "warning: " + f.base +
                             ".h5 (the earlier run's results) is missing; the results start at "
                             "the restart\n");
}

TEST(RestartPlan, ResultsOfAnotherRunOrOfNoneAreRefused)
{
  // (the results' run fingerprint, "" for none; what the message says of them)
  const std::pair<std::string, std::string> cases[] = {
      {"theirs", ".h5: was written by another run (run fingerprint theirs) than the checkpoint "
                 "c.h5 (run fingerprint ours: its mesh, physics and initial state): the restart "
                 "would append to the results of another run, and nothing was written."},
      {"", ".h5: has no run fingerprint (the attribute run_fingerprint), so it cannot be shown "
           "to belong to the run of the checkpoint c.h5"}};
  for (const auto &[digest, message] : cases)
  {
    Fixture f;
    f.write_results(f.base + ".h5", digest, {0.0});
    kiln::RestartPlan plan = f.plan("c.h5");
    EXPECT_THAT(input_error_message([&] { plan.earlier_results(); }), HasSubstr(f.base + message));
  }
}

TEST(RestartPlan, StopTimesJoinTheOutputsAndTheCheckpointsAhead)
{
  Fixture f;
  Teuchos::ParameterList output("Output");
  output.set("Times", values({10.0, 20.0}));
  output.set("File Base", f.base);
  const kiln::OutputSchedule outputs(
      kiln::validated(output, kiln::OutputSchedule::valid_parameters(), "deck.xml", "Kiln/Output"),
      "deck.xml", *f.comm);
  Teuchos::ParameterList checkpoint("Checkpoint");
  // 10 s once more, a rounding off: one stop, not two.
  checkpoint.set("Times", values({0.0, 5.0, 10.0 * (1.0 + 1e-14), 15.0}));
  const kiln::CheckpointSchedule checkpoints(
      kiln::validated(checkpoint, kiln::CheckpointSchedule::valid_parameters(), "deck.xml",
                      "Kiln/Checkpoint"),
      f.base, "deck.xml: Kiln/Checkpoint");
  EXPECT_THAT(f.plan("").stop_times(0.0, outputs, checkpoints),
              ElementsAre(0.0, 5.0, 10.0, 15.0, 20.0))
      << "a new run stops at its start, every output time and every checkpoint time";
  EXPECT_THAT(f.plan(f.base + ".checkpoint.h5").stop_times(10.0, outputs, checkpoints),
              ElementsAre(15.0, 20.0))
      << "a restart at 10 s: its checkpoint's own time is written";
}
