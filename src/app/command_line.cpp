#include "app/command_line.hpp"

#include "base/errors.hpp"

namespace kiln
{
std::string usage()
{
  return "Kiln: coupled thermo-mechanics with contact.\n"
         "\n"
         "usage:\n"
         "  kiln INPUT.xml                       run the input (alone or under mpirun)\n"
         "  kiln --check INPUT.xml               validate the input and the mesh, solve nothing\n"
         "  kiln --write-mesh OUT.exo INPUT.xml  write the input's mesh as Exodus II\n"
         "  kiln --print-parameters              print every valid parameter with its default,\n"
         "                                       unit and documentation\n"
         "  kiln --version                       print the version\n"
         "  kiln --help                          print this text\n"
         "options:\n"
         "  --mesh FILE.exo   use this Exodus II file as the mesh (Mesh/Type = \"Exodus\",\n"
         "                    Mesh/Exodus/\"File\" = FILE.exo)\n"
         "  --restart FILE.h5 continue the run from this checkpoint (Kiln/Checkpoint); the\n"
         "                    input may change the time stepping, solver, output and\n"
         "                    checkpoints, not the problem\n"
         "  --timers          print the table of the Trilinos timers (Kiln's phases, NOX,\n"
         "                    Belos, MueLu) at the end of a run or a check\n"
         "\n"
         "SIGTERM, SIGINT (Ctrl-C) or SIGUSR1 stop a run after its current step with a\n"
         "checkpoint; a second one ends it at once. Under mpirun send SIGUSR1 (mpirun passes\n"
         "it to every rank; on SIGTERM it kills them a second later). SLURM: --signal=B:USR1@120.\n"
         "\n"
         "Exit status: 0 on success, 1 for an error in the input, the mesh or the command line,\n"
         "2 for a run that cannot go on (its last good state is written), 3 for a run stopped\n"
         "by a signal (its checkpoint is written).\n"
         "Documentation: doc/user-guide.md\n";
}

CommandLine parse_command_line(const std::vector<std::string> &args)
{
  const std::string hint = "; run kiln --help";
  CommandLine cl;
  bool mode_set = false;
  const auto set_mode = [&](const CommandLine::Mode m, const std::string &flag)
  {
    KILN_CHECK_INPUT(!mode_set, "command line",
                     flag << " cannot be combined with another mode" << hint);
    cl.mode = m;
    mode_set = true;
  };
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string &a = args[i];
    const auto value = [&](const std::string &what)
    {
      KILN_CHECK_INPUT(i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0, "command line",
                       a << " needs " << what << hint);
      return args[++i];
    };
    if (a == "--help" || a == "-h")
      set_mode(CommandLine::Mode::help, a);
    else if (a == "--version")
      set_mode(CommandLine::Mode::version, a);
    else if (a == "--print-parameters")
      set_mode(CommandLine::Mode::print_parameters, a);
    else if (a == "--check")
      set_mode(CommandLine::Mode::check, a);
    else if (a == "--write-mesh")
    {
      KILN_CHECK_INPUT(cl.mesh_output.empty(), "command line",
                       "--write-mesh is given twice; give it once, with one output file" << hint);
      set_mode(CommandLine::Mode::write_mesh, a);
      cl.mesh_output = value("an output file name (OUT.exo)");
    }
    else if (a == "--mesh")
    {
      const std::string previous = cl.mesh_file;
      cl.mesh_file = value("an Exodus file name");
      KILN_CHECK_INPUT(previous.empty(), "command line",
                       "--mesh is given twice (\"" << previous << "\", \"" << cl.mesh_file
                                                   << "\"); a run reads one mesh: give --mesh "
                                                      "once"
                                                   << hint);
    }
    else if (a == "--timers")
      cl.timers = true;
    else if (a == "--restart")
    {
      KILN_CHECK_INPUT(cl.restart.empty(), "command line",
                       "--restart is given twice; a run continues from one checkpoint" << hint);
      cl.restart = value("a checkpoint file name (NAME.h5)");
    }
    else if (a.rfind("-", 0) == 0)
      KILN_CHECK_INPUT(false, "command line", "unknown option \"" << a << "\"" << hint);
    else
    {
      KILN_CHECK_INPUT(cl.input.empty(), "command line",
                       "more than one input file (\"" << cl.input << "\", \"" << a << "\")"
                                                      << hint);
      cl.input = a;
    }
  }
  const bool needs_input = cl.mode == CommandLine::Mode::run ||
                           cl.mode == CommandLine::Mode::check ||
                           cl.mode == CommandLine::Mode::write_mesh;
  KILN_CHECK_INPUT(!needs_input || !cl.input.empty(), "command line",
                   "no input file given; usage: kiln [options] INPUT.xml" << hint);
  KILN_CHECK_INPUT(needs_input || cl.input.empty(), "command line",
                   "an input file is not used with this option" << hint);
  KILN_CHECK_INPUT(!cl.timers || cl.mode == CommandLine::Mode::run ||
                       cl.mode == CommandLine::Mode::check,
                   "command line",
                   "--timers prints the timers of a run or a check; it cannot be combined with "
                   "this mode"
                       << hint);
  KILN_CHECK_INPUT(cl.restart.empty() || cl.mode == CommandLine::Mode::run, "command line",
                   "--restart continues a run; it cannot be combined with another mode" << hint);
  return cl;
}
} // namespace kiln
