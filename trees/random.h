#pragma once
// Seeded random streams for tree generation, shared by every tree core. std::mt19937_64 is
// specified bit for bit by the C++ standard and the conversion to [0, 1) is ours, so a seed
// gives the same tree with any compiler. Cores key streams by what they generate (Weber &
// Penn: one per recursion level, as Arbaro does), so that changing one part's parameters
// does not reshuffle the others.
#include <cstdint>
#include <random>

#include "core/counter_rng.h"

namespace landsim::trees {

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

}  // namespace landsim::trees
