#pragma once
/// kiln's command line.
#include <string>
#include <vector>

namespace kiln
{
struct CommandLine
{
  enum class Mode
  {
    run,
    help,
    version,
    print_parameters,
    check,
    write_mesh
  };
  Mode mode = Mode::run;
  std::string input;       ///< the XML input file
  std::string mesh_file;   ///< --mesh FILE: an Exodus file that replaces the input's mesh
  std::string mesh_output; ///< --write-mesh OUT.exo
  std::string restart;     ///< --restart CHECKPOINT.h5
  bool timers = false;     ///< --timers: print the Trilinos timer table at the end
};

/// Parses the arguments after the program name; throws InputError for a bad
/// command line (the message ends with "run kiln --help").
CommandLine parse_command_line(const std::vector<std::string> &args);

/// The text of kiln --help.
std::string usage();
} // namespace kiln
