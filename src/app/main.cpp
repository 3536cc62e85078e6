// kiln: the command-line driver. See kiln --help.
#include "app/command_line.hpp"
#include "app/mpi_defaults.hpp"
#include "app/print_parameters.hpp"
#include "app/simulation.hpp"
#include "base/errors.hpp"
#include "base/log.hpp"
#include "base/stop_request.hpp"
#include "io/input_reader.hpp"
#include "mesh/mesh_quality.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_GlobalMPISession.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <kiln/version.hpp>
#include <mpi.h>

#include <csignal>
#include <cstdlib>
#include <iostream>
#include <new>

namespace
{
int run(const kiln::CommandLine &cl, const Teuchos::RCP<const Teuchos::Comm<int>> &comm)
{
  using Mode = kiln::CommandLine::Mode;
  auto out = kiln::rank0_stream(*comm);
  switch (cl.mode)
  {
  case Mode::help:
    *out << kiln::usage();
    return 0;
  case Mode::version:
    *out << "kiln " << kiln::version_string << "\n";
    return 0;
  case Mode::print_parameters:
    kiln::print_parameters(kiln::Simulation::valid_parameters(), *out);
    return 0;
  default:
    break;
  }
  kiln::Simulation simulation(kiln::read_input(cl.input, *comm), cl.input, comm, cl.mesh_file);
  if (cl.mode == Mode::write_mesh)
  {
    simulation.write_mesh(cl.mesh_output);
    return 0;
  }
  int status = 0;
  if (cl.mode == Mode::check)
  {
    simulation.check();
    // The mesh by block and element type: count and quality range (issue 32).
    kiln::print_mesh_quality(kiln::mesh_quality(simulation.mesh()), *out);
    *out << cl.input << ": input and mesh are valid\n";
  }
  else
  {
    simulation.set_restart(cl.restart);
    kiln::install_stop_handlers();
    status = simulation.run() == kiln::Simulation::Ending::finished ? 0 : 3;
  }
  // The table only when asked for: the run's summary has the figures a user needs.
  if (cl.timers)
    Teuchos::TimeMonitor::summarize(comm.ptr(), *out, false, true, false, Teuchos::Union);
  return status;
}

/// Run by hand (not by mpirun), `kiln --version` and `kiln --help` answer before MPI
/// starts: MPI_Init of a singleton takes 0.3 s here, 80% of such a call.
bool answered_without_mpi(int argc, char **argv)
{
  if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr)
    return false;
  try
  {
    const kiln::CommandLine cl = kiln::parse_command_line({argv + 1, argv + argc});
    if (cl.mode == kiln::CommandLine::Mode::version)
      std::cout << "kiln " << kiln::version_string << "\n";
    else if (cl.mode == kiln::CommandLine::Mode::help)
      std::cout << kiln::usage();
    else
      return false;
    return true;
  }
  catch (const std::exception &)
  {
    return false; // reported as usual, below
  }
}
} // namespace

int main(int argc, char **argv)
{
  if (answered_without_mpi(argc, argv))
    return 0;
  // On one machine Open MPI's point-to-point layer need not probe the network libraries
  // (UCX, OFI, PSM), 0.25 s of every start here, and a process run by hand need not start an
  // orted daemon (Kiln spawns no processes), 0.1 s more (doc/user-guide.md, Start-up).
  for (const auto &[name, value] : kiln::open_mpi_defaults(std::getenv))
    setenv(name.c_str(), value.c_str(), 0);
  // A file-size limit (ulimit -f) makes a write fail with EFBIG, reported like a full disk,
  // instead of killing the run with SIGXFSZ.
  std::signal(SIGXFSZ, SIG_IGN);
  Teuchos::GlobalMPISession session(&argc, &argv, nullptr);
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  try
  {
    return run(kiln::parse_command_line({argv + 1, argv + argc}), comm);
  }
  catch (const kiln::InputError &e)
  {
    kiln::end_status_line();
    // Input errors are raised alike on every rank: report once, exit 1 everywhere.
    if (comm->getRank() == 0)
      std::cerr << "kiln: error: " << e.what() << "\n";
    return 1;
  }
  catch (const kiln::RunError &e)
  {
    kiln::end_status_line();
    // Also raised alike on every rank (decided on reduced quantities).
    if (comm->getRank() == 0)
      std::cerr << "kiln: error: " << e.what() << "\n";
    return 2;
  }
  catch (const std::bad_alloc &)
  {
    // May have happened on one rank only: abort so no rank hangs.
    std::cerr << "kiln: error: rank " << comm->getRank()
              << " ran out of memory; the mesh (held whole on every rank) and its matrices "
                 "need more than this machine gives: use fewer cells (Kiln/Mesh/Box/\"Cells\" "
                 "or a coarser mesh)"
              << std::endl;
    MPI_Abort(MPI_COMM_WORLD, 2);
  }
  catch (const std::exception &e)
  {
    // Anything else may have happened on one rank only: abort so no rank hangs. A library's
    // exception text (Teuchos' source path, "Throw number") is put on one line.
    std::cerr << "kiln: internal error on rank " << comm->getRank() << ": "
              << kiln::one_line_library_message(e.what())
              << "; this is a bug in Kiln or a library it uses: please report it with the input"
              << std::endl;
    MPI_Abort(MPI_COMM_WORLD, 2);
  }
  return 2;
}
