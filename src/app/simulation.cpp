#include "app/simulation.hpp"

#include "app/checkpoint_schedule.hpp"
#include "app/contact_pairs_setup.hpp"
#include "app/memory_estimate.hpp"
#include "app/output_schedule.hpp"
#include "app/progress_report.hpp"
#include "app/restart_plan.hpp"
#include "app/results_lock.hpp"
#include "app/run_observer.hpp"
#include "app/run_results.hpp"
#include "base/errors.hpp"
#include "base/log.hpp"
#include "base/parameters.hpp"
#include "base/stop_request.hpp"
#include "io/checkpoint.hpp"
#include "io/history_csv.hpp"
#include "io/results_replay.hpp"
#include "mesh/exodus_io.hpp"
#include "mesh/gap_splitter.hpp"
#include "mesh/mesh_factory.hpp"
#include "mesh/metis_partitioner.hpp"
#include "physics/coupled_problem.hpp"
#include "physics/materials/material_map.hpp"
#include "solvers/fault_injection.hpp"
#include "solvers/newton_solver.hpp"
#include "solvers/time_stepper.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <kiln/version.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <numeric>
#include <sstream>

namespace kiln
{

Teuchos::ParameterList Simulation::valid_parameters()
{
  Teuchos::ParameterList p("Kiln");
  p.set("Problem Name", "", "a title printed in the log [-]");
  p.set("Physics", "Heat Conduction",
        "the fields solved for: \"Heat Conduction\" (temperature; block Thermal), "
        "\"Thermo-Elasticity\" (temperature and displacement in one Newton solve; blocks "
        "Thermal and Mechanics) or \"Elasticity\" (displacement at T = Reference "
        "Temperature; block Mechanics)",
        choice_validator({"Heat Conduction", "Thermo-Elasticity", "Elasticity"}));
  p.sublist(
       "Mesh", false,
       "the mesh: a generated box or an Exodus II file, the gap, the partition; see doc/mesh.md")
      .setParameters(MeshFactory::valid_parameters());
  p.sublist("Material", false,
            "material properties, one material for every element block; or give Materials; see "
            "doc/materials.md")
      .setParameters(Material::valid_parameters());
  set_named_sublists(p, "Materials",
                     "materials by name, each with the element \"Blocks\" it fills (every block "
                     "in exactly one); instead of Material; see doc/materials.md",
                     MaterialMap::valid_named_parameters());
  p.sublist("Thermal", false,
            "heat conduction: initial state, boundary conditions, gap conductance; see "
            "doc/heat.md")
      .setParameters(ThermalPhysics::valid_parameters());
  p.sublist("Mechanics", false,
            "quasi-static small-strain thermo-elasticity: body force, boundary conditions; see "
            "doc/mechanics.md")
      .setParameters(MechanicalPhysics::valid_parameters());
  p.sublist("Time Stepping", false,
            "implicit time integration with adaptive steps; see doc/heat.md")
      .setParameters(TimeStepper::valid_parameters());
  p.sublist("Solver", false, "Newton (NOX) and linear solver (Belos, MueLu); see doc/solvers.md")
      .setParameters(NewtonSolver::valid_parameters());
  p.sublist("Output", false,
            "results: the files (HDF5 + XDMF and/or Exodus, a time history, gap tables) and "
            "when the state is written; see doc/output-format.md")
      .setParameters(OutputSchedule::valid_parameters());
  p.sublist("Checkpoint", false,
            "checkpoints to continue a run from (kiln INPUT.xml --restart FILE); see "
            "doc/user-guide.md")
      .setParameters(CheckpointSchedule::valid_parameters());
  p.sublist("Debug", false,
            "testing aids: faults injected on purpose, never for real runs; see doc/user-guide.md "
            "(Faults)")
      .setParameters(FaultInjection::valid_parameters());
  return p;
}

Simulation::Simulation(const Teuchos::ParameterList &input, const std::string &input_path,
                       const Teuchos::RCP<const Teuchos::Comm<int>> &comm,
                       const std::string &mesh_file)
    : params_(validated(input, valid_parameters(), input_path, "Kiln")), input_path_(input_path),
      mesh_file_(mesh_file), comm_(comm), out_(rank0_stream(*comm))
{
  std::ostringstream xml;
  Teuchos::writeParameterListToXmlOStream(input, xml);
  input_xml_ = xml.str();
  outputs_ = std::make_unique<OutputSchedule>(params_.sublist("Output"), input_path_, *comm_);
  const std::string physics = params_.get<std::string>("Physics");
  const bool thermal = physics != "Elasticity";
  const bool mechanics = physics != "Heat Conduction";
  KILN_CHECK_INPUT(thermal || !given_in_input(params_, "Thermal"),
                   parameter_path(input_path_, "Kiln", "Thermal"),
                   "is given but Kiln/\"Physics\" is \"" << physics
                                                         << "\", which has no temperature; "
                                                            "remove it or set Physics to "
                                                            "\"Thermo-Elasticity\"");
  KILN_CHECK_INPUT(mechanics || !given_in_input(params_, "Mechanics"),
                   parameter_path(input_path_, "Kiln", "Mechanics"),
                   "is given but Kiln/\"Physics\" is \"" << physics
                                                         << "\", which has no displacement; "
                                                            "remove it or set Physics to "
                                                            "\"Thermo-Elasticity\"");
  const bool contact =
      mechanics && params_.sublist("Mechanics").sublist("Contact").get<bool>("Enabled");
  layout_ = DofLayout{thermal, mechanics, contact};
}

Simulation::~Simulation() = default;

void Simulation::setup()
{
  // Checked before the mesh is allocated, printed after the header that names the run.
  std::ostringstream memory;
  check_memory(params_, layout_, input_path_, mesh_file_, *comm_, memory);
  {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Kiln: 1 mesh"));
    const MeshFactory factory(params_.sublist("Mesh"), input_path_ + ": Kiln/Mesh", mesh_file_);
    mesh_ = factory.build();
    if (!factory.gap_side_sets().empty())
      split_gaps(mesh_, factory.gap_side_sets(),
                 parameter_path(input_path_, "Kiln/Mesh", factory.gap_parameter()));
  }
  {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Kiln: 2 partition"));
    const std::string where = input_path_ + ": Kiln/Mesh";
    cell_rank_ = params_.sublist("Mesh").get<std::string>("Partition") == "By Block"
                     ? partition_cells_by_block(mesh_, *comm_, where)
                     : partition_cells(mesh_, *comm_, where);
  }
  // The rows of the contact pairs between separately meshed bodies: their partners join the
  // DofManager's graph and overlap before its maps are built.
  std::vector<PairingRows> pairings;
  if (layout_.contact)
  {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Kiln: 2 contact pairs"));
    pairings = setup_contact_pairs(mesh_, params_, layout_, input_path_);
  }
  {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Kiln: 2 partition"));
    const std::vector<std::pair<int, int>> links = pairing_links(pairings);
    dofs_ = std::make_unique<DofManager>(mesh_, cell_rank_, comm_, layout_, links);
  }
  {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Kiln: 3 set-up"));
    const MaterialMap materials(params_, mesh_.block_ids(), input_path_);
    const Material &material = materials.uniform_material();
    problem_ = Teuchos::rcp(new CoupledProblem(mesh_, *dofs_, material, params_.sublist("Thermal"),
                                               params_.sublist("Mechanics"), input_path_ + ": Kiln",
                                               &materials, pairings));
    problem_->set_log(out_);
    solved_ = FaultInjection::wrap(problem_, params_.sublist("Debug"), input_path_ + ": Kiln/Debug",
                                   *out_);
    newton_ = std::make_unique<NewtonSolver>(params_.sublist("Solver"), solved_, out_,
                                             input_path_ + ": Kiln/Solver");
    stepper_ = std::make_unique<TimeStepper>(params_.sublist("Time Stepping"),
                                             input_path_ + ": Kiln/Time Stepping", out_);
  }
  print_header();
  *out_ << memory.str();
}

void Simulation::check()
{
  setup();
  const bool transient = params_.sublist("Time Stepping").get<std::string>("Method") != "Steady";
  KILN_CHECK_INPUT(!layout_.temperature || !transient ||
                       given_in_input(params_.sublist("Output"), "Times"),
                   parameter_path(input_path_, "Kiln/Output", "Times"),
                   "is not given, so the run would end at t = 0 without a time step (a run steps "
                   "from t = 0 to its last output time); give the output times, e.g. <Parameter "
                   "name=\"Times\" type=\"Array(double)\" value=\"{0, 100}\"/> in the Output "
                   "list, or set Kiln/Time Stepping/\"Method\" to \"Steady\"");
  if (layout_.temperature && !transient)
  {
    // Only Heat Flux conditions fix the heat flow but not the temperature level: a steady
    // solve then has no solution (the fluxes do not balance) or infinitely many.
    const Teuchos::ParameterList &conditions =
        params_.sublist("Thermal").sublist("Boundary Conditions");
    bool level_fixed = false;
    for (auto it = conditions.begin(); it != conditions.end(); ++it)
      level_fixed = level_fixed ||
                    conditions.sublist(conditions.name(it)).get<std::string>("Type") != "Heat Flux";
    KILN_CHECK_INPUT(level_fixed, input_path_ + ": Kiln/Thermal/Boundary Conditions",
                     "a steady heat problem (Kiln/Time Stepping/\"Method\" = \"Steady\") "
                     "needs a condition that fixes the temperature (Type \"Temperature\", "
                     "\"Convection\" or \"Radiation\"), but "
                         << (conditions.numParams() == 0 ? "there is none"
                                                         : "every condition is a \"Heat Flux\"")
                         << ": the fluxes set only how heat flows, so there is no steady state "
                            "(heat that comes in and never leaves) or no single one. Add a "
                            "Temperature or Convection condition, or follow the heating in time "
                            "(Method \"BDF2\" with Kiln/Output/\"Times\")");
  }
  const CheckpointSchedule checkpoints(params_.sublist("Checkpoint"), outputs_->file_base(),
                                       input_path_ + ": Kiln/Checkpoint");
  KILN_CHECK_INPUT(checkpoints.latest_path() != outputs_->file_base() + ".h5" &&
                       checkpoints.base() != outputs_->file_base(),
                   parameter_path(input_path_, "Kiln/Checkpoint", "File Base"),
                   "= \"" << checkpoints.base()
                          << "\" is also the results' File Base (Kiln/Output): "
                          << "the latest checkpoint " << checkpoints.latest_path()
                          << " would overwrite the results " << outputs_->file_base()
                          << ".h5. Give the checkpoints another base, or leave it \"\" for "
                          << outputs_->file_base() << ".checkpoint");
  // A Checkpoint/File Base of its own shared in turn: another run's checkpoints there are not
  // overwritten (a restart of the run that wrote them, or a rerun of it, goes on).
  if (checkpoints.base() != outputs_->file_base() + ".checkpoint" &&
      std::filesystem::exists(checkpoints.latest_path()))
  {
    const std::string theirs = results_summary(checkpoints.latest_path()).run_fingerprint;
    const std::string ours = RunFingerprint::of(mesh_, layout_, params_).digest();
    KILN_CHECK_INPUT(theirs == ours, parameter_path(input_path_, "Kiln/Checkpoint", "File Base"),
                     "= \"" << checkpoints.base() << "\": " << checkpoints.latest_path()
                            << " holds the checkpoints of another run (run fingerprint "
                            << (theirs.empty() ? "none" : theirs) << ", this run's " << ours
                            << ": another mesh, physics or initial state), which this run would "
                               "overwrite. Give this run a Checkpoint/File Base of its own, or "
                               "remove "
                            << checkpoints.base() << "*.h5 if they are no longer needed");
  }
  const auto &times = params_.sublist("Checkpoint").get<Teuchos::Array<double>>("Times");
  for (int i = 0; i < times.size(); ++i)
    KILN_CHECK_INPUT(times[i] <= outputs_->end_time() * (1.0 + 1e-12),
                     parameter_path(input_path_, "Kiln/Checkpoint", "Times"),
                     "entry " << i + 1 << " (" << times[i]
                              << " s) is after the end of the run, the last output time "
                              << outputs_->end_time()
                              << " s; remove it or add a later time to Kiln/Output/\"Times\"");
}

Simulation::Ending Simulation::run()
{
  check();
  const CheckpointSchedule checkpoints(params_.sublist("Checkpoint"), outputs_->file_base(),
                                       input_path_ + ": Kiln/Checkpoint");
  RunResults::make_output_folder(outputs_->file_base(),
                                 parameter_path(input_path_, "Kiln/Output", "File Base"), *comm_);
  RunResults::make_output_folder(
      checkpoints.base(), parameter_path(input_path_, "Kiln/Checkpoint", "File Base"), *comm_);
  const ResultsLock lock(outputs_->lock_path(), *comm_);
  // Checkpoints under a base of their own get a lock of their own: two runs with different
  // results but one Checkpoint/File Base would overwrite each other's checkpoints.
  const std::unique_ptr<const ResultsLock> checkpoint_lock =
      checkpoints.base() == outputs_->file_base() + ".checkpoint"
          ? nullptr
          : std::make_unique<const ResultsLock>(checkpoints.base() + ".lock", *comm_,
                                                "checkpoints with this Checkpoint/File Base",
                                                "Kiln/Checkpoint/\"File Base\"");
  // What identifies this run's problem (the mesh, its fields and the physics' input), once.
  const RunFingerprint fingerprint = RunFingerprint::of(mesh_, layout_, params_);
  restart_plan_ = std::make_unique<RestartPlan>(restart_, outputs_->file_base(),
                                                outputs_->writes_hdf5() ? ".h5" : ".exo",
                                                fingerprint.digest(), comm_, out_);
  const bool fresh = restart_plan_->fresh();
  TimeStepper::State state =
      fresh ? start() : restart_plan_->resume(fingerprint, *problem_, *newton_);
  if (!fresh)
    solution_ = state.x;
  restart_plan_->check_time_left(state.time, outputs_->end_time(), input_path_);
  // A continued run's results start with the earlier run's, read before the new files open.
  const std::string earlier_results = restart_plan_->earlier_results();
  results_ = std::make_unique<RunResults>(
      RunResults::Context{mesh_, *dofs_, cell_rank_, *problem_, *outputs_, *restart_plan_,
                          input_path_, input_xml_, fingerprint.digest(), comm_, out_},
      restart_plan_->first_gap_step(earlier_results));
  const int output_steps =
      earlier_results.empty() ? 0 : results_->continue_results(earlier_results, state.time);
  HistoryCsv history = results_->open_history(state);
  ProgressReport progress(out_, {params_.sublist("Time Stepping").get<std::string>("Method"),
                                 state.time, outputs_->end_time(), state.statistics.steps,
                                 log_is_terminal(), started_});
  RunObserver observer(
      {*problem_, mesh_, layout_, results_->field_output(), results_->writers(), *outputs_,
       checkpoints, history, progress, *newton_, fingerprint,
       CheckpointInfo{version_string, "", input_path_, input_xml_, 0, {}, {}, {}, {}, {}}, comm_,
       out_},
      output_steps);
  observer.start(state, fresh);
  bool finished = false;
  try
  {
    finished =
        stepper_->run(*solved_, *newton_, state,
                      restart_plan_->stop_times(state.time, *outputs_, checkpoints), observer);
  }
  catch (const WriteError &e)
  {
    // A file could not be written (a full disk, a file-size limit): nothing more is written,
    // not even the results' status, so that no file complete before is touched; the results
    // stay BASE.running.h5, readable up to the last complete step, and the last checkpoint
    // that was verified stays the one to continue from.
    const std::string last = observer.last_checkpoint_path();
    const std::string base = outputs_->file_base();
    const std::string running =
        outputs_->writes_hdf5() ? base + ".running.h5" + (outputs_->writes_exodus() ? " and " : "")
                                : "";
    *out_ << "stopped by the error below at t = " << state.time << " s; the results up to the "
          << "last complete output step are in " << running
          << (outputs_->writes_exodus() ? base + ".running.exo" : "")
          << (last.empty() ? std::string() : "; the last good checkpoint is " + last) << "\n";
    throw;
  }
  catch (const RunError &e)
  {
    // The last good state stays: written as an output step and as a checkpoint, and the
    // results files finished with the error as their status.
    observer.output(state);
    const std::string path = observer.checkpoint(state);
    std::ostringstream when;
    when << "stopped by an error at t = " << state.time << " s";
    results_->finish(when.str() + ": " + e.what(), state.time, history);
    progress.summary(when.str() + " (below)", state, results_->files_written(path), *comm_);
    *out_ << "stopped by the error below at t = " << state.time << " s; its last good state is in "
          << outputs_->results_files(false) << " and " << path << "\n";
    throw;
  }
  solution_ = state.x;
  if (!finished)
  {
    const std::string path = observer.checkpoint(state);
    std::ostringstream when;
    when << "stopped by " << signal_name(observer.stop_signal()) << " at t = " << state.time
         << " s";
    results_->finish(when.str() + "; continued by kiln --restart " + path, state.time, history);
    progress.summary(when.str(), state, results_->files_written(path), *comm_);
    *out_ << when.str() << " after step " << state.statistics.steps << "; checkpoint " << path
          << "; continue with: kiln " << input_path_ << " --restart " << path << "\n";
    return Ending::stopped;
  }
  if (checkpoints.at_end())
    observer.checkpoint(state);
  results_->finish("complete", state.time, history);
  progress.summary("complete", state, results_->files_written(observer.last_checkpoint_path()),
                   *comm_);
  return Ending::finished;
}

TimeStepper::State Simulation::start()
{
  solution_ = Teuchos::rcp(new NonlinearProblem::Vector(problem_->solution_map()));
  problem_->initial_condition(0.0, *solution_);
  // Without a temperature a steady solve is the equilibrium itself (the same equations at
  // t = 0): solving it twice only made NOX warn that the second one was converged.
  const bool steady = params_.sublist("Time Stepping").get<std::string>("Method") == "Steady";
  const NewtonSolver::Result equilibrium = layout_.displacement && !(steady && !layout_.temperature)
                                               ? equilibrate()
                                               : NewtonSolver::Result{};
  TimeStepper::State state = stepper_->initial_state(0.0, *solution_);
  state.statistics.add_solve(equilibrium);
  return state;
}

NewtonSolver::Result Simulation::equilibrate()
{
  // Quasi-static: the displacement at t = 0 is in equilibrium with the initial
  // temperature (and, with contact, decides which pairs start in contact).
  NonlinearProblem::Vector b(problem_->solution_map());
  problem_->set_time_derivative(0.0, 0.0, b);
  problem_->freeze_temperature(solution_.get());
  const NewtonSolver::Result r = newton_->solve(*solution_);
  problem_->freeze_temperature(nullptr);
  if (!r.converged)
    throw RunError(input_path_ +
                   ": the initial equilibrium of the displacement (t = 0, at the initial "
                   "temperature) did not converge: " +
                   newton_failure(r, newton_->max_iterations()) + ". " +
                   newton_advice(r, newton_->max_iterations()) +
                   (r.final_residual_norm < 1e-2 * r.initial_residual_norm
                        ? ""
                        : "; a body free to move as a rigid body stops it too: check that "
                          "Kiln/Mechanics/Boundary Conditions hold every rigid-body motion"));
  *out_ << "initial equilibrium: Newton " << r.newton_iterations << " (" << r.linear_iterations
        << " linear"
        << (r.linear_failures > 0 ? ", " + std::to_string(r.linear_failures) + " short of tolerance"
                                  : std::string())
        << "), |F| " << std::scientific << std::setprecision(3) << r.initial_residual_norm << " -> "
        << r.final_residual_norm << std::defaultfloat << "\n";
  problem_->step_accepted(0.0, *solution_);
  return r;
}

void Simulation::print_header() const
{
  auto &out = *out_;
  const std::string title = params_.get<std::string>("Problem Name");
  out << "Kiln " << version_string << ": " << input_path_
      << (title.empty() ? "" : " (" + title + ")") << " on " << comm_->getSize() << " MPI rank"
      << (comm_->getSize() > 1 ? "s" : "") << "\n";

  std::map<int, std::pair<int, std::vector<char>>> blocks; // id -> (cells, node flags)
  for (int c = 0; c < mesh_.n_cells(); ++c)
  {
    auto &[cells, nodes] = blocks[mesh_.block_id[c]];
    nodes.resize(mesh_.n_nodes(), 0);
    ++cells;
    for (const int n : mesh_.cell_nodes(c))
      nodes[n] = 1;
  }
  out << "mesh: " << mesh_.n_cells() << " cells, " << mesh_.n_nodes() << " nodes\n";
  for (const auto &[id, b] : blocks)
    out << "  block " << id << ": " << b.first << " cells, "
        << std::count(b.second.begin(), b.second.end(), 1) << " nodes\n";
  for (std::size_t g = 0; g < mesh_.gap_side_sets.size(); ++g)
  {
    double area = 0.0;
    std::size_t pairs = 0;
    for (const auto &p : mesh_.gap_pairs)
      if (p.gap == static_cast<int>(g))
      {
        area += p.area;
        ++pairs;
      }
    out << "  gap at side set " << mesh_.gap_side_sets[g] << ": " << pairs << " node pairs, area "
        << area << " m^2\n";
  }

  const int n_ranks = comm_->getSize();
  std::vector<int> cells(n_ranks, 0), nodes(n_ranks, 0);
  for (const int r : cell_rank_)
    ++cells[r];
  for (const int r : dofs_->node_owner())
    ++nodes[r];
  const auto balance = [](const std::vector<int> &v)
  {
    const double mean = double(std::accumulate(v.begin(), v.end(), 0)) / v.size();
    std::ostringstream s;
    s << "min " << *std::min_element(v.begin(), v.end()) << ", max "
      << *std::max_element(v.begin(), v.end()) << ", max/mean " << std::fixed
      << std::setprecision(2) << *std::max_element(v.begin(), v.end()) / mean;
    return s.str();
  };
  out << "partition ("
      << (params_.sublist("Mesh").get<std::string>("Partition") == "By Block" ? "by block"
                                                                              : "METIS k-way")
      << "): cells per rank " << balance(cells) << "; owned nodes per rank " << balance(nodes)
      << "\n";
  out << "unknowns: " << dofs_->n_global_dofs() << " ("
      << (layout_.temperature && layout_.displacement ? "temperature and displacement"
          : layout_.temperature                       ? "temperature"
                                                      : "displacement")
      << " at every node)\n";
  out << "preconditioner: " << newton_->preconditioner() << "\n";
}

void Simulation::write_mesh(const std::string &path) const
{
  const MeshFactory factory(params_.sublist("Mesh"), input_path_ + ": Kiln/Mesh", mesh_file_);
  const Mesh mesh = factory.build();
  std::string error;
  if (comm_->getRank() == 0)
  {
    try
    {
      write_exodus_mesh(mesh, path, factory.gap_side_sets());
    }
    catch (const InputError &e)
    {
      error = e.what();
    }
  }
  check_collectively(*comm_, error.empty(), "", error);
  *out_ << "wrote " << path << ": " << mesh.n_cells() << " cells, " << mesh.n_nodes() << " nodes, "
        << mesh.block_ids().size() << " blocks, " << mesh.side_sets.size()
        << " side sets (before the gap split)\n";
}
} // namespace kiln
