// Tests the state at quadrature points through the time loop (issue 31, item 4): a
// CoupledProblem holding a QuadratureState of the test model AccumulatingStateModel, driven
// by StateDrivingProblem (the model evaluated at every point in every residual evaluation, as
// a kernel will), stepped by the TimeStepper with one attempt failed on purpose: the state
// counts exactly the accepted steps (committed on acceptance, restored on the rejection); a
// run continued from a checkpoint written at t = 4 s holds at t = 8 s the same unknowns and
// the same state, bit for bit, as the run that never stopped. A problem without a stateful
// model keeps no state.
// KILN_TEST_NP: 1 2
#include "io/checkpoint.hpp"
#include "physics/coupled_problem.hpp"
#include "physics/quadrature_state_setup.hpp"
#include "solvers/newton_solver.hpp"
#include "solvers/time_stepper.hpp"
#include "support/accumulating_state_model.hpp"
#include "support/parallel.hpp"
#include "support/parameter_lists.hpp"
#include "support/problem_fixture.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <functional>
#include <memory>

namespace
{
using namespace kiln_test;
using kiln::TimeStepper;
using Vector = kiln::NonlinearProblem::Vector;

/// A box heated on one end (side set 1: 300 -> 320 K over 10 s), temperature only.
struct Fixture : ProblemFixture
{
  Fixture()
      : ProblemFixture(box_mesh({{0.04, 0.02, 0.02}, {4, 2, 2}, 30.0, -20.0}, 0),
                       kiln::DofLayout{true, false, false})
  {
  }
  ~Fixture()
  {
    comm->barrier();
    if (comm->getRank() == 0)
      std::filesystem::remove_all(folder);
  }
  Teuchos::ParameterList thermal() const
  {
    Teuchos::ParameterList p;
    p.set("Initial Temperature", 300.0);
    Teuchos::ParameterList &bc = p.sublist("Boundary Conditions").sublist("hot end");
    bc.set("Type", "Temperature");
    bc.set("Side Sets", Teuchos::Array<int>(Teuchos::tuple(1)));
    bc.set("Temperature", smooth_step(300.0, 320.0, 0.0, 10.0));
    return p;
  }
  /// What a checkpoint must match: this mesh and layout, a fixed input.
  kiln::RunFingerprint fingerprint() const
  {
    Teuchos::ParameterList input("Kiln");
    input.set("Physics", "Heat Conduction");
    for (const char *block : {"Mesh", "Material", "Thermal", "Mechanics"})
      input.sublist(block).set("Tag", std::string(block));
    return kiln::RunFingerprint::of(mesh, dofs.layout(), input);
  }
  std::string folder = shared_test_folder(MPI_COMM_WORLD, "quadrature_state_continuation");
  AccumulatingStateModel model;
};

/// A problem with the state of `model` (none in every fifth cell, 1 + c % 3 points in cell c:
/// not 8 for all), driven by it; its Newton solver and the time stepper.
struct SteppedRun
{
  SteppedRun(const Fixture &f, const int fail_attempt)
  {
    problem = f.problem(f.thermal());
    problem->set_quadrature_state(kiln::make_quadrature_state(
        {&f.model}, f.dofs.owned_cells(),
        [&f](const int cell) -> const kiln::ConstitutiveModel *
        { return cell % 5 == 0 ? nullptr : &f.model; },
        [](const int cell) { return 1 + cell % 3; }, "test"));
    driven = Teuchos::rcp(
        new StateDrivingProblem(problem, f.model, *problem->quadrature_state(), fail_attempt));
    auto quiet = Teuchos::getFancyOStream(Teuchos::rcp(new Teuchos::oblackholestream));
    Teuchos::ParameterList solver;
    solver.set("Absolute Tolerance", 1e-8);
    solver.set("Relative Tolerance", 1e-12);
    newton = std::make_unique<kiln::NewtonSolver>(solver, driven, quiet);
    Teuchos::ParameterList p = TimeStepper::valid_parameters();
    p.set("Initial Step", 0.5);
    p.set("Maximum Step", 1.5);
    stepper = std::make_unique<TimeStepper>(p, "test.xml: Kiln/Time Stepping", quiet);
  }
  Teuchos::RCP<kiln::CoupledProblem> problem;
  Teuchos::RCP<StateDrivingProblem> driven;
  std::unique_ptr<kiln::NewtonSolver> newton;
  std::unique_ptr<TimeStepper> stepper;
};

/// Calls `at` at every stop time.
struct AtStops final : TimeStepper::Observer
{
  explicit AtStops(std::function<void(const TimeStepper::State &)> f) : at(std::move(f)) {}
  void stop_time(const TimeStepper::State &state) override { at(state); }
  std::function<void(const TimeStepper::State &)> at;
};

} // namespace

TEST(QuadratureStateContinuation, CommittedOncePerAcceptedStepAndContinuedBitForBit)
{
  Fixture f;
  const kiln::RunFingerprint fingerprint = f.fingerprint();
  const std::string path = f.folder + "/at4.h5";

  // The run that never stops, its third attempt failed on purpose; a checkpoint at t = 4 s.
  SteppedRun a(f, 3);
  Vector x0(a.problem->solution_map());
  a.problem->initial_condition(0.0, x0);
  TimeStepper::State state = a.stepper->initial_state(0.0, x0);
  int accepted_at_4 = 0;
  AtStops checkpoint(
      [&](const TimeStepper::State &s)
      {
        if (s.time != 4.0)
          return;
        accepted_at_4 = s.accepted;
        kiln::CheckpointInfo info{"1", "now", "deck.xml", "", 0, {}, {}, {}, {}, {}};
        info.preconditioner_origin = a.newton->preconditioner_origin();
        kiln::write_checkpoint(path, s, info, fingerprint, *f.comm, a.problem->quadrature_state());
      });
  ASSERT_TRUE(a.stepper->run(*a.driven, *a.newton, state, {4.0, 8.0}, checkpoint));
  EXPECT_EQ(a.driven->rejections(), 1);
  EXPECT_EQ(state.statistics.newton_failures, 1);
  EXPECT_GT(accepted_at_4, 2);
  EXPECT_GT(state.accepted, accepted_at_4);

  // The state counts the accepted steps exactly (in both copies), and sums over them.
  const kiln::QuadratureState &qs = *a.problem->quadrature_state();
  ASSERT_GT(qs.n_points(), 0);
  for (int c = 0; c < qs.n_cells(); ++c)
  {
    EXPECT_EQ(qs.n_points(c), qs.cells()[c] % 5 == 0 ? 0 : 1 + qs.cells()[c] % 3);
    for (int q = 0; q < qs.n_points(c); ++q)
    {
      EXPECT_EQ(qs.old(c, q)[0], state.accepted);
      EXPECT_EQ(qs.current(c, q)[0], state.accepted);
      EXPECT_NEAR(qs.old(c, q)[1], state.accepted * (1e-3 * (qs.cells()[c] + 1) + 1e-4 * q), 1e-12);
      // 1 + sum of T dt with 300 K <= T <= 320 K over 8 s.
      EXPECT_GT(qs.old(c, q)[2], 1.0 + 300.0 * 8.0 * (1.0 - 1e-12));
      EXPECT_LT(qs.old(c, q)[2], 1.0 + 320.0 * 8.0);
    }
  }

  // The run continued from the checkpoint, from a fresh initial state.
  SteppedRun b(f, 0);
  EXPECT_FALSE(same_bits(*b.problem->quadrature_state(), qs));
  kiln::Checkpoint c = kiln::read_checkpoint(path, fingerprint, b.problem->solution_map(), *f.comm,
                                             b.problem->quadrature_state());
  EXPECT_EQ(c.state.accepted, accepted_at_4);
  const kiln::QuadratureState &restored = *b.problem->quadrature_state();
  for (int cell = 0; cell < restored.n_cells(); ++cell)
    for (int q = 0; q < restored.n_points(cell); ++q)
      EXPECT_EQ(restored.old(cell, q)[0], accepted_at_4);
  b.problem->resume(c.state.time, *c.state.x);
  b.newton->restore_preconditioner_origin(std::move(c.info.preconditioner_origin));
  b.driven->set_accepted(c.state.time, c.state.x->normInf());
  AtStops nothing([](const TimeStepper::State &) {});
  ASSERT_TRUE(b.stepper->run(*b.driven, *b.newton, c.state, {8.0}, nothing));

  EXPECT_EQ(c.state.accepted, state.accepted);
  EXPECT_EQ(c.state.time, state.time);
  const auto xa = state.x->getData(), xb = c.state.x->getData();
  EXPECT_EQ(std::memcmp(xa.getRawPtr(), xb.getRawPtr(), sizeof(double) * xa.size()), 0);
  EXPECT_TRUE(same_bits(restored, qs));
}

TEST(QuadratureStateContinuation, NoStatefulModelKeepsNothing)
{
  Fixture f;
  const auto problem = f.problem(f.thermal());
  EXPECT_EQ(problem->quadrature_state(), nullptr);
}
