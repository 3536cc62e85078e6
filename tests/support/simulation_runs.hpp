#pragma once
/// Whole runs in a test: a Simulation from an input given as a parameter list, as XML text or
/// read from inputs/, on a mesh the test writes, solver tolerances tightened, the time loop driven
/// from the deck's initial state or one of the test's own, and the nodal temperatures gathered
/// and integrated over the mesh.
#include "app/simulation.hpp"
#include "physics/coupled_problem.hpp"
#include "solvers/time_stepper.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace kiln_test
{
using Vector = kiln::NonlinearProblem::Vector;

/// The folder of the example decks, inputs/ of the source tree (ends in '/').
inline const std::string inputs = std::string(KILN_SOURCE_DIR) + "/inputs/";

/// Replaces every `key` in `text` by `value`.
void replace(std::string &text, const std::string &key, const std::string &value);
/// `value` with 17 significant digits (for XML decks made from numbers).
std::string number(double value);

/// A set-up Simulation (mesh, partition, CoupledProblem, Newton, stepper) from a Kiln
/// input given as XML text.
std::unique_ptr<kiln::Simulation>
make_simulation(const std::string &xml, const Teuchos::RCP<const Teuchos::Comm<int>> &comm);
/// The same from a Kiln input as a parameter list (parameter_lists.hpp builds them).
std::unique_ptr<kiln::Simulation>
make_simulation(const Teuchos::ParameterList &input,
                const Teuchos::RCP<const Teuchos::Comm<int>> &comm);

/// The state of a set-up Simulation at t = 0 by its problem's initial condition.
Vector initial_state(kiln::Simulation &sim);

/// Writes `mesh` to the Exodus file BASE.mesh.exo (BASE from results_files.hpp's
/// temporary_base) on rank 0 and returns its path once it is written (collective);
/// remove_results(BASE) removes it with the run's results.
std::string write_mesh_file(const kiln::Mesh &mesh, const std::string &base,
                            const Teuchos::Comm<int> &comm);

/// Sets Solver/"Absolute Tolerance" and "Relative Tolerance" (Newton) and the "Convergence
/// Tolerance" of its Block GMRES (the default Belos solver) of an input.
void set_solver_tolerances(Teuchos::ParameterList &input, double absolute, double relative,
                           double gmres);

/// Runs the time loop of a set-up Simulation from the state x at t = 0 through `times` (x holds
/// the state at the last of them on return); `output` is called at each, as by
/// TimeStepper::run (nothing if empty).
kiln::TimeStepper::Statistics run_from(kiln::Simulation &sim, Vector &x,
                                       const std::vector<double> &times,
                                       const kiln::TimeStepper::OutputFunction &output = {});

/// The temperature of every mesh node on every rank (the owned values, summed).
std::vector<double> all_node_values(const kiln::Simulation &sim, const Vector &x);

/// Sets x at every owned node to f(coordinates).
void interpolate(const kiln::Simulation &sim, const std::function<double(const kiln::Point &)> &f,
                 Vector &x);

/// sqrt(∫ (T_h - T)^2 dΩ) over the mesh with 3x3x3 Gauss points per cell; T_h is the
/// trilinear interpolant of the nodal values (all nodes, replicated).
double l2_error(const kiln::Simulation &sim, const std::vector<double> &nodal,
                const std::function<double(const kiln::Point &)> &exact);
} // namespace kiln_test
