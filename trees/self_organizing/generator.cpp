#include "trees/self_organizing/generator.h"

#include "trees/self_organizing/plant_skeleton.h"

namespace landsim::trees::self_organizing {

TreeSkeleton generate_skeleton(const Parameters& p, std::uint64_t seed,
                               GrowthStatistics* statistics) {
  GrowthStatistics local;
  GrowthStatistics& stats = statistics != nullptr ? *statistics : local;
  const Plant plant = grow(p, seed, &stats);
  return plant_skeleton(plant, p.leaves);
}

}  // namespace landsim::trees::self_organizing
