#pragma once
/// The entry points fuzzed by libFuzzer (fuzz_input, fuzz_exodus) and replayed by ctest
/// through kiln_fuzz_replay: each takes arbitrary bytes and must end in success or a
/// kiln::InputError; any other exception escapes (libFuzzer reports it as a crash, the
/// replay driver as a failure), and a crash is a crash.
#include <cstddef>
#include <cstdint>

namespace kiln::fuzz
{
/// The bytes as an input deck: read (kiln::parse_input), validated against the whole valid
/// tree and checked as the Simulation constructor does; no mesh is built.
void input_deck(const std::uint8_t *data, std::size_t size);

/// The bytes as an Exodus II mesh file: written to a scratch file, read
/// (kiln::read_exodus_mesh, which checks a classic netCDF header first) and checked
/// (kiln::check_mesh).
void exodus_mesh(const std::uint8_t *data, std::size_t size);
} // namespace kiln::fuzz
