#include "trees/self_organizing/plant_skeleton.h"

#include <algorithm>
#include <cmath>

namespace landsim::trees::self_organizing {
namespace {

// The axis from internode `first` along its main successors, stem `index`; records each of
// its internodes' stem in `stem_of`. Its parent is the stem of the internode it branches from.
StemSkeleton axis_stem(const Plant& plant, std::uint32_t first, int index,
                       std::vector<int>& stem_of) {
  StemSkeleton stem;
  stem.level = std::min(plant[first].order, 3);
  if (plant[first].parent != kNone) stem.parent = stem_of[plant[first].parent];
  std::uint32_t last = first;
  for (std::uint32_t i = first; i != kNone && plant[i].alive; i = plant[i].main) {
    const Internode& n = plant[i];
    stem.sections.push_back({n.base, n.direction, n.frame, 0.5 * n.width});
    stem_of[i] = index;
    last = i;
  }
  const Internode& end = plant[last];
  stem.sections.push_back({end.tip, end.direction, end.frame, 0.5 * end.width});
  return stem;
}

LeafSkeleton leaf_at(const Internode& n, const LeafParameters& p) {
  LeafSkeleton leaf;
  leaf.base = n.tip;
  // Along the lateral bud, tipped a little outward and down, its face turned to the sky.
  leaf.direction = normalize(n.lateral_direction + Vec3{0, 0, -0.3});
  Vec3 side = cross(leaf.direction, Vec3{0, 0, 1});
  if (length(side) < 1e-6) side = n.frame;
  leaf.normal = normalize(cross(normalize(side), leaf.direction));
  if (leaf.normal.z < 0) leaf.normal = leaf.normal * -1.0;
  leaf.length = p.length;
  leaf.width = p.width;
  return leaf;
}

// Leaf vigour 0-1: the shoot's vigour over the 90th percentile of the shoots' (the
// distribution is skewed: the leaders get most), so that the strongest tenth keep the
// species' leaf colour and weaker shoots fade towards its weak-leaf colour.
void colour_by_vigour(const std::vector<double>& vigour, std::vector<LeafSkeleton>& leaves) {
  if (vigour.empty()) return;
  std::vector<double> sorted = vigour;
  const auto at = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() * 9 / 10);
  std::nth_element(sorted.begin(), at, sorted.end());
  const double full = *at;
  for (std::size_t k = 0; k < leaves.size(); ++k)
    leaves[k].vigour = full > 0.0 ? static_cast<float>(std::min(1.0, vigour[k] / full)) : 1.0f;
}

// The step each internode's axis last grew in (the birth of the axis's living tip).
std::vector<int> axis_last_growth(const Plant& plant) {
  std::vector<int> last(plant.size(), 0);
  for (std::size_t k = plant.size(); k-- > 0;) {
    const Internode& n = plant[static_cast<std::uint32_t>(k)];
    if (!n.alive) continue;
    last[k] = n.main != kNone && plant[n.main].alive ? last[n.main] : n.birth;
  }
  return last;
}

}  // namespace

TreeSkeleton plant_skeleton(const Plant& plant, const LeafParameters& leaves) {
  TreeSkeleton skeleton;
  const std::vector<int> last = axis_last_growth(plant);
  std::vector<double> vigour;                  // of each leaf's shoot
  std::vector<int> stem_of(plant.size(), -1);  // each internode's stem
  for (std::uint32_t i = 0; i < plant.size(); ++i) {
    const Internode& n = plant[i];
    if (!n.alive) continue;
    // Axes in the order of their first internode: every parent axis before its branches.
    if (i == 0 || plant.starts_branch(i))
      skeleton.stems.push_back(
          axis_stem(plant, i, static_cast<int>(skeleton.stems.size()), stem_of));
    if (!n.stub && last[i] - n.birth < leaves.age) {
      skeleton.leaves.push_back(leaf_at(n, leaves));
      skeleton.leaves.back().stem = stem_of[i];
      vigour.push_back(n.shoot_vigour);
    }
  }
  colour_by_vigour(vigour, skeleton.leaves);
  return skeleton;
}

}  // namespace landsim::trees::self_organizing
