#pragma once
// The self-organising core's entry: grow the plant, then its skeleton; or grow it once and
// recover the tree of earlier steps from its time stamps (TreeSketch's ungrow).
#include <cstdint>
#include <vector>

#include "trees/self_organizing/parameters.h"
#include "trees/self_organizing/simulation.h"
#include "trees/skeleton.h"

namespace landsim::trees::self_organizing {

TreeSkeleton generate_skeleton(const Parameters& p, std::uint64_t seed,
                               GrowthStatistics* statistics = nullptr);

// The tree after each of `steps` (any order; each at most p.steps), from one growth to the
// largest: the same skeletons as growing each number of steps on its own.
std::vector<TreeSkeleton> skeletons_at_steps(const Parameters& p, std::uint64_t seed,
                                             const std::vector<int>& steps);

}  // namespace landsim::trees::self_organizing
