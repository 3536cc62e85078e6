#pragma once
/// 64-bit FNV-1a over the bytes of trivially copyable values: the fingerprints of checkpoints
/// (the mesh) and of the solver's kept preconditioner.
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace kiln
{
/// FNV-1a's starting value.
inline constexpr std::uint64_t fnv1a_start = 14695981039346656037ull;

/// The hash of the bytes of data[0..n), continued from `hash`.
template <typename T>
std::uint64_t fnv1a(const T *data, const std::size_t n, std::uint64_t hash = fnv1a_start)
{
  static_assert(std::is_trivially_copyable_v<T>, "fnv1a hashes the bytes of its values");
  const auto *bytes = reinterpret_cast<const unsigned char *>(data);
  for (std::size_t i = 0; i < n * sizeof(T); ++i)
    hash = (hash ^ bytes[i]) * 1099511628211ull;
  return hash;
}
} // namespace kiln
