#include "trees/self_organizing/generator.h"

#include <algorithm>

#include "trees/self_organizing/pipe_model.h"
#include "trees/self_organizing/plant_skeleton.h"

namespace landsim::trees::self_organizing {

TreeSkeleton generate_skeleton(const Parameters& p, std::uint64_t seed,
                               GrowthStatistics* statistics) {
  GrowthStatistics local;
  GrowthStatistics& stats = statistics != nullptr ? *statistics : local;
  const Plant plant = grow(p, seed, &stats);
  return plant_skeleton(plant, p.leaves);
}

std::vector<TreeSkeleton> skeletons_at_steps(const Parameters& p, std::uint64_t seed,
                                             const std::vector<int>& steps) {
  if (steps.empty()) return {};
  Parameters longest = p;
  longest.steps = std::clamp(*std::max_element(steps.begin(), steps.end()), 0, p.steps);
  const Plant grown = grow(longest, seed);
  std::vector<TreeSkeleton> out;
  for (int k : steps) {
    Plant young = grown.at_step(k);
    assign_widths(young, p.width);
    out.push_back(plant_skeleton(young, p.leaves));
  }
  return out;
}

}  // namespace landsim::trees::self_organizing
