#pragma once
/// Puts the pieces together, deal.II-tutorial style:
///   run() { setup(); output(t0); for each step { assemble; solve; } output(t_k) }
/// (the time loop is the TimeStepper's; each step one NOX solve; what happens between the
/// steps is the RunObserver's).
#include "discretization/dof_manager.hpp"
#include "discretization/nonlinear_problem.hpp"
#include "mesh/mesh.hpp"
#include "solvers/time_stepper.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_FancyOStream.hpp>
#include <Teuchos_ParameterList.hpp>

#include <chrono>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace kiln
{
class OutputSchedule;
class RestartPlan;
class RunResults;
class NewtonSolver;
class CoupledProblem;

class Simulation
{
public:
  /// The whole valid input tree (kiln --print-parameters prints it).
  static Teuchos::ParameterList valid_parameters();

  /// `input` is the unvalidated list read from `input_path`; it is validated
  /// here. `mesh_file` overrides the input's mesh (kiln --mesh FILE).
  Simulation(const Teuchos::ParameterList &input, const std::string &input_path,
             const Teuchos::RCP<const Teuchos::Comm<int>> &comm, const std::string &mesh_file = "");
  ~Simulation();

  /// Mesh, gap split, partition, unknowns, physics, solvers (so that every input
  /// error shows here); prints the header.
  void setup();
  /// setup(), and the checks a run makes before it starts (kiln --check).
  void check();
  /// How a run ended: at its last output time, or stopped by a signal after a step (with a
  /// checkpoint to continue from).
  enum class Ending
  {
    finished,
    stopped
  };
  /// check(), then the time integration from t = 0, or from the checkpoint of
  /// set_restart(), holding the lock BASE.lock; the state written when the output schedule
  /// asks, a history row per step, checkpoints as asked, a summary at the end. A RunError
  /// leaves the last good state written (output and checkpoint), the results files finished
  /// with its message as their status, and goes on.
  Ending run();
  /// run() continues from this checkpoint (kiln --restart FILE).
  void set_restart(const std::string &checkpoint) { restart_ = checkpoint; }
  /// The mesh before the split, as Exodus II (rank 0 writes).
  void write_mesh(const std::string &path) const;

  const Mesh &mesh() const { return mesh_; }
  const std::vector<int> &cell_rank() const { return cell_rank_; }
  const DofManager &dofs() const { return *dofs_; }
  /// Kiln/Output: the results' path, format and schedule.
  const OutputSchedule &outputs() const { return *outputs_; }
  /// The solution after run(), the unknowns of the owned nodes (CoupledProblem has
  /// their physical values).
  const NonlinearProblem::Vector &solution() const { return *solution_; }
  /// The pieces setup() builds, for tests and studies that drive the time loop
  /// themselves (from an initial state of their own, say).
  CoupledProblem &problem() { return *problem_; }
  NewtonSolver &newton_solver() { return *newton_; }
  const TimeStepper &time_stepper() const { return *stepper_; }

private:
  void print_header() const;
  /// The state at t = 0: the initial condition, in equilibrium with a displacement.
  TimeStepper::State start();
  /// Solves for the displacement at t = 0 with the temperature held at its initial value.
  NewtonSolver::Result equilibrate();

  /// When the run began: the summary's wall time counts from it.
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  Teuchos::ParameterList params_;
  std::string input_path_;
  std::string input_xml_; ///< the input as given
  std::string mesh_file_;
  std::string restart_; ///< the checkpoint to continue from, or ""
  /// What run() does with the checkpoint and the files of the run it continues.
  std::unique_ptr<RestartPlan> restart_plan_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  Teuchos::RCP<Teuchos::FancyOStream> out_;
  Mesh mesh_;
  std::vector<int> cell_rank_;
  std::unique_ptr<DofManager> dofs_;
  DofLayout layout_;
  Teuchos::RCP<CoupledProblem> problem_;
  /// What the solvers see: problem_, or problem_ with Kiln/Debug's fault (FaultInjection).
  Teuchos::RCP<TransientProblem> solved_;
  std::unique_ptr<NewtonSolver> newton_;
  std::unique_ptr<TimeStepper> stepper_;
  std::unique_ptr<OutputSchedule> outputs_;
  /// The results files of run(); they close with the Simulation, after run()'s lock is
  /// released.
  std::unique_ptr<RunResults> results_;
  Teuchos::RCP<NonlinearProblem::Vector> solution_;
};
} // namespace kiln
