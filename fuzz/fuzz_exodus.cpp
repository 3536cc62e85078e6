// libFuzzer target: arbitrary bytes as an Exodus II mesh (see fuzz_targets.hpp,
// doc/fuzzing.md).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  kiln::fuzz::exodus_mesh(data, size);
  return 0;
}
