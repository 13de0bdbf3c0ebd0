#pragma once
// A fixed 64-bit hash of text (FNV-1a): the same on every platform, compiler and run, unlike
// std::hash, so what is made of it — a checkpoint line's checksum, a replay file's name — can be
// checked or found again anywhere.
#include <cstdint>
#include <string_view>

namespace granular {

/// FNV-1a 64 of `text`; `basis`: the starting value (FNV's offset basis unless a format fixed another).
constexpr std::uint64_t text_hash(std::string_view text, std::uint64_t basis = 14695981039346656037ull) {
  std::uint64_t h = basis;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace granular
