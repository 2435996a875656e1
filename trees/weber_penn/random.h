#pragma once
// Seeded random streams for tree generation. std::mt19937_64 is specified bit for bit by the
// C++ standard and the conversion to [0, 1) is ours, so a seed gives the same tree with any
// compiler. One stream per recursion level (as Arbaro does), so that changing a deeper
// level's parameters does not reshuffle the levels above it.
#include <cstdint>
#include <random>

#include "core/counter_rng.h"

namespace landsim::trees::weber_penn {

class Random {
 public:
  Random() = default;
  Random(std::uint64_t seed, std::uint64_t stream) : engine_(hash_combine(mix64(seed), stream)) {}

  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  // The paper's "± V": uniform in [-v, v].
  double var(double v) { return uniform(-v, v); }
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace landsim::trees::weber_penn
