#pragma once
// Counter-based random numbers: every value is a pure function of (seed, stream, index,
// dimension), so a pixel's samples do not depend on which thread, tile or machine made them.
#include <cstdint>

namespace landsim {

// SplitMix64 finaliser: a bijective 64-bit mixer with full avalanche.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

constexpr std::uint64_t hash_combine(std::uint64_t h, std::uint64_t v) {
  return mix64(h ^ mix64(v));
}

class CounterRng {
 public:
  // One stream per (seed, key): key is, for a renderer, the pixel index; index the sample.
  constexpr CounterRng(std::uint64_t seed, std::uint64_t key, std::uint64_t index)
      : base_(hash_combine(hash_combine(mix64(seed), key), index)) {}

  // The value for one dimension of the sample, uniform in [0, 1).
  constexpr float uniform(std::uint32_t dimension) const {
    const std::uint64_t bits = hash_combine(base_, dimension);
    return static_cast<float>(bits >> 40) * (1.0f / 16777216.0f);  // top 24 bits
  }

  // Next dimension, for code that consumes dimensions in order.
  float next() { return uniform(dimension_++); }

 private:
  std::uint64_t base_;
  std::uint32_t dimension_ = 0;
};

}  // namespace landsim
