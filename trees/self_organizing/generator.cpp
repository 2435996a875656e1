#include "trees/self_organizing/generator.h"

#include <algorithm>

#include "trees/self_organizing/bending.h"
#include "trees/self_organizing/pipe_model.h"
#include "trees/self_organizing/plant_skeleton.h"

namespace landsim::trees::self_organizing {
namespace {

// The modeler's bends, in order, on the grown plant: they were drawn on the finished tree,
// so a younger plant (ungrown) is drawn unbent.
void apply_bends(Plant& plant, const std::vector<Bend>& bends, bool grown) {
  if (!grown) return;
  for (const Bend& b : bends) bend(plant, b);
}

}  // namespace

TreeSkeleton generate_skeleton(const Parameters& p, std::uint64_t seed,
                               GrowthStatistics* statistics) {
  GrowthStatistics local;
  GrowthStatistics& stats = statistics != nullptr ? *statistics : local;
  Plant plant = grow(p, seed, &stats);
  apply_bends(plant, p.bends, true);
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
    apply_bends(young, p.bends, k >= p.steps);
    out.push_back(plant_skeleton(young, p.leaves));
  }
  return out;
}

}  // namespace landsim::trees::self_organizing
