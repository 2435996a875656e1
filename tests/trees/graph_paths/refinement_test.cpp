#include "trees/graph_paths/refinement.h"

#include <gtest/gtest.h>

#include <numeric>

#include "trees/graph_paths/generator.h"

namespace landsim::trees::graph_paths {
namespace {

InitialVolume crown() {
  VolumePrimitive s;
  s.origin = {0, 0, 5};
  s.radius = 3.0;
  return InitialVolume({s});
}

TEST(Refinement, SpheresLieInsideApartAndJoinTheJunction) {
  const RefinementParameters r{.spheres = 5, .radius = 1.0, .cone_ratio = 0.4, .separation = 1.5};
  const Vec3 junction{0, 0, 1};
  const auto parts = refine(crown(), r, junction, 3);
  ASSERT_EQ(parts.size(), 5u);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    EXPECT_TRUE(crown().contains(parts[i].sphere.origin));
    EXPECT_TRUE(parts[i].volume.contains(junction + (parts[i].sphere.origin - junction) * 0.02));
    for (std::size_t j = i + 1; j < parts.size(); ++j)
      EXPECT_GE(length(parts[i].sphere.origin - parts[j].sphere.origin), 1.5);
  }
  const auto again = refine(crown(), r, junction, 3);
  const auto other = refine(crown(), r, junction, 4);
  EXPECT_EQ(parts[0].sphere.origin, again[0].sphere.origin);
  EXPECT_NE(parts[0].sphere.origin, other[0].sphere.origin);
}

TEST(Refinement, EndpointsAreAllottedBySizeAndSumToTheTotal) {
  std::vector<Subvolume> parts(3);
  parts[0].size = 1.0;
  parts[1].size = 2.0;
  parts[2].size = 7.0;
  const auto n = allot_endpoints(103, parts);
  EXPECT_EQ(std::accumulate(n.begin(), n.end(), std::size_t{0}), 103u);
  EXPECT_LT(n[0], n[1]);
  EXPECT_LT(n[1], n[2]);
  EXPECT_NEAR(static_cast<double>(n[2]), 0.7 * 103, 2.0);
  const auto few = allot_endpoints(2, parts);
  EXPECT_EQ(few, (std::vector<std::size_t>{1, 1, 1}));  // every limb gets one
}

TEST(Refinement, EachSubvolumeIsItsOwnLimbFromTheJunction) {
  Parameters p;
  p.volume = crown();
  p.root = {0, 0, 0};
  p.junction = {0, 0, 0};  // the limbs meet at the root: a bare root node
  p.spacing = 0.3;
  p.endpoints = 80;
  p.shell = 0.3;
  p.refinement = {.spheres = 4, .radius = 1.2, .cone_ratio = 0.4, .separation = 1.5};
  GraphStatistics stats;
  const TreeSkeleton t = generate_skeleton(p, 8, &stats);
  // No edges between subvolumes: each limb reaches the root on its own, so exactly four
  // stems start there (the trunk continuing into one limb, and three more).
  int from_root = 0;
  for (const StemSkeleton& s : t.stems) from_root += s.sections.front().position == p.root ? 1 : 0;
  EXPECT_EQ(from_root, 4);
  EXPECT_EQ(stats.endpoints, 80u);
}

TEST(Refinement, ATrunkLeadsFromTheRootToARaisedJunction) {
  Parameters p;
  p.volume = crown();
  p.junction = {0, 0, 2.5};
  p.spacing = 0.3;
  p.endpoints = 60;
  p.refinement = {.spheres = 3, .radius = 1.2, .cone_ratio = 0.4, .separation = 1.5};
  const TreeSkeleton t = generate_skeleton(p, 9);
  ASSERT_FALSE(t.stems.empty());
  const StemSkeleton& trunk = t.stems[0];
  EXPECT_LT(trunk.sections.front().position.z, 0.5);
  bool passes_junction = false;
  for (const CrossSection& c : trunk.sections)
    passes_junction |= length(c.position - p.junction) < 0.5;
  EXPECT_TRUE(passes_junction);
}

}  // namespace
}  // namespace landsim::trees::graph_paths
