#include "trees/graph_paths/root_system.h"

#include <algorithm>

#include "core/counter_rng.h"
#include "trees/graph_paths/generator.h"

namespace landsim::trees::graph_paths {

// The ball (a half ellipsoid; the upper half's nodes
// are cut at the root point's height), the taproot's endpoint, the laterals from the shell.
Parameters root_parameters(const Parameters& crown) {
  const RootParameters& r = crown.roots;
  const double depth = r.depth > 0.0 ? r.depth : r.radius;
  Parameters p;
  VolumePrimitive ball;
  ball.kind = PrimitiveKind::ellipsoid;
  ball.origin = crown.root;
  ball.radii = {r.radius, r.radius, depth};
  p.volume = InitialVolume({ball});
  p.root = crown.root;
  p.node_max_z = crown.root.z;
  p.spacing = r.spacing > 0.0 ? r.spacing : crown.spacing;
  p.policy = crown.policy;
  p.cone_subdivisions = crown.cone_subdivisions;
  p.search_radius = crown.search_radius;
  p.threshold = crown.threshold;
  p.weight_noise = crown.weight_noise;
  p.endpoints = r.laterals;
  p.shell = r.shell * r.radius;
  if (r.taproot) p.manual_endpoints = {crown.root - Vec3{0, 0, 0.95 * depth}};
  p.skeleton = crown.skeleton;
  p.skeleton.thickness_power = r.power;
  p.skeleton.leaves_per_endpoint = 0;
  p.iteration.levels = r.levels;
  p.iteration.radius = r.level_radius * r.radius;
  p.iteration.endpoints = r.level_endpoints;
  p.iteration.power = r.power;
  p.max_nodes = crown.max_nodes;
  return p;
}

TreeSkeleton root_skeleton(const Parameters& crown, std::uint64_t seed, GraphStatistics& stats) {
  const Parameters p = root_parameters(crown);
  const BranchTree tree = grow_branch_tree(p, hash_combine(seed, 0x2007), stats);
  return branch_skeleton(tree, thickness(tree, level_powers(p)), p.skeleton);
}

void attach_roots(TreeSkeleton& tree, const TreeSkeleton& roots) {
  if (tree.stems.empty() || roots.stems.empty()) return;
  const double trunk_base = tree.stems[0].sections.front().radius;
  double thickest = 0.0;
  for (const StemSkeleton& stem : roots.stems)
    for (const CrossSection& c : stem.sections) thickest = std::max(thickest, c.radius);
  const double f = thickest > trunk_base ? trunk_base / thickest : 1.0;
  const int offset = static_cast<int>(tree.stems.size());
  for (StemSkeleton stem : roots.stems) {
    stem.level = std::min(stem.level + 1, 3);
    for (CrossSection& c : stem.sections) c.radius *= f;
    if (stem.parent < 0) {  // the root system's first stem starts at the trunk's base
      CrossSection joint = stem.sections.front();
      joint.position = tree.stems[0].sections.front().position;
      const Vec3 down = stem.sections.front().position - joint.position;
      if (length(down) > 1e-9) joint.axis = normalize(down);
      stem.sections.insert(stem.sections.begin(), joint);
    }
    stem.parent = stem.parent < 0 ? 0 : stem.parent + offset;
    tree.stems.push_back(std::move(stem));
  }
}

}  // namespace landsim::trees::graph_paths
