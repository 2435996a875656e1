#pragma once
// The self-organising core's entry: grow the plant, then its skeleton.
#include <cstdint>

#include "trees/self_organizing/parameters.h"
#include "trees/self_organizing/simulation.h"
#include "trees/skeleton.h"

namespace landsim::trees::self_organizing {

TreeSkeleton generate_skeleton(const Parameters& p, std::uint64_t seed,
                               GrowthStatistics* statistics = nullptr);

}  // namespace landsim::trees::self_organizing
