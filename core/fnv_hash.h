#pragma once
// FNV-1a, 64 bits: a short, stable hash of text (a scenario's hash in the image metadata, an
// image's part of the sensor's noise seed). Not for security.
#include <cstdint>
#include <string_view>

namespace landsim {

inline constexpr std::uint64_t kFnvOffset = 0xcbf29ce484222325ULL;

// The hash of `text` continued from `hash` (kFnvOffset to begin; pass the last result to hash
// several parts as one).
constexpr std::uint64_t fnv1a(std::string_view text, std::uint64_t hash = kFnvOffset) {
  for (const char c : text) hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  return hash;
}

}  // namespace landsim
