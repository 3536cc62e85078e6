// libFuzzer target: arbitrary bytes as a Kiln input deck (see fuzz_targets.hpp, doc/fuzzing.md).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  kiln::fuzz::input_deck(data, size);
  return 0;
}
