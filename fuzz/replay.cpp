// kiln_fuzz_replay input|exodus PATH...: feeds every file (of each directory, recursively)
// through the entry point the fuzzer ran (fuzz_targets.hpp), with the normal build. Each must
// end in success or a kiln::InputError; anything else is reported and the exit status is 1,
// and a crash ends the process (ctest reports it). Run by ctest on fuzz/corpus/ and
// fuzz/regressions/ (the inputs of crashes found and fixed).
#include "fuzz_targets.hpp"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

int main(int argc, char **argv)
{
  if (argc < 3 || (std::string(argv[1]) != "input" && std::string(argv[1]) != "exodus"))
  {
    std::cerr << "usage: kiln_fuzz_replay input|exodus FILE_OR_DIR...\n";
    return 2;
  }
  const bool input = std::string(argv[1]) == "input";
  // KILN_REPLAY_VERBOSE=1 names each file before it runs (to find the one a tool such as
  // valgrind complains about).
  const bool verbose = std::getenv("KILN_REPLAY_VERBOSE") != nullptr;
  std::vector<std::filesystem::path> files;
  for (int i = 2; i < argc; ++i)
  {
    const std::filesystem::path p(argv[i]);
    if (!std::filesystem::exists(p))
      continue; // e.g. fuzz/regressions/input while no crash has been found there
    if (std::filesystem::is_directory(p))
    {
      for (const auto &e : std::filesystem::recursive_directory_iterator(p))
        if (e.is_regular_file())
          files.push_back(e.path());
    }
    else
      files.push_back(p);
  }
  std::sort(files.begin(), files.end());
  int failures = 0;
  for (const auto &file : files)
  {
    if (verbose)
      std::cout << "replaying " << file.string() << std::endl;
    std::ifstream in(file, std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                          std::istreambuf_iterator<char>());
    try
    {
      if (input)
        kiln::fuzz::input_deck(bytes.data(), bytes.size());
      else
        kiln::fuzz::exodus_mesh(bytes.data(), bytes.size());
    }
    catch (const std::exception &e)
    {
      std::cout << file.string() << ": not an InputError: " << e.what() << "\n";
      ++failures;
    }
  }
  std::cout << files.size() << " files replayed, " << failures << " failed\n";
  return files.empty() || failures > 0 ? 1 : 0;
}
