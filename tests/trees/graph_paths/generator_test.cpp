#include "trees/graph_paths/generator.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "trees/mesher.h"

namespace landsim::trees::graph_paths {
namespace {

Parameters crown_on_trunk() {
  VolumePrimitive crown;
  crown.origin = {0, 0, 3};
  crown.radius = 1.5;
  VolumePrimitive trunk;
  trunk.kind = PrimitiveKind::cylinder;
  trunk.radius = 0.2;
  trunk.height = 2.0;
  Parameters p;
  p.volume = InitialVolume({crown, trunk});
  p.spacing = 0.15;
  p.endpoints = 120;
  p.shell = 0.3;
  return p;
}

std::vector<double> radii_along(const StemSkeleton& s) {
  std::vector<double> r;
  for (const CrossSection& c : s.sections) r.push_back(c.radius);
  return r;
}

TEST(GraphPathsGenerator, GrowsATrunkFromTheRootUpIntoTheCrown) {
  GraphStatistics stats;
  const TreeSkeleton t = generate_skeleton(crown_on_trunk(), 5, &stats);
  ASSERT_FALSE(t.stems.empty());
  EXPECT_EQ(t.stems[0].level, 0);
  EXPECT_LT(t.stems[0].sections.front().position.z, 0.2);
  EXPECT_GT(t.stems[0].sections.back().position.z, 2.0);
  EXPECT_GT(t.stems.size(), 20u);
  EXPECT_EQ(stats.endpoints, 120u);
  EXPECT_GT(stats.nodes, 2000u);
}

TEST(GraphPathsGenerator, LeavesGrowOnlyAtTheTips) {
  const TreeSkeleton t = generate_skeleton(crown_on_trunk(), 5);
  // An endpoint on another endpoint's path is no tip and gets none: at most 3 per endpoint.
  EXPECT_LE(t.leaves.size(), 120u * 3u);
  EXPECT_GE(t.leaves.size(), 100u * 3u);
  for (const LeafSkeleton& leaf : t.leaves) {
    bool at_tip = false;
    for (const StemSkeleton& s : t.stems)
      at_tip = at_tip || s.sections.back().position == leaf.base;
    ASSERT_TRUE(at_tip);
    EXPECT_NEAR(dot(leaf.normal, leaf.direction), 0.0, 1e-9);
  }
}

TEST(GraphPathsGenerator, RadiusNeverGrowsAlongAStemOrIntoAChild) {
  const TreeSkeleton t = generate_skeleton(crown_on_trunk(), 6);
  for (const StemSkeleton& s : t.stems) {
    const auto r = radii_along(s);
    for (std::size_t k = 1; k < r.size(); ++k) ASSERT_LE(r[k], r[k - 1] + 1e-12);
    if (s.level == 0) continue;
    // A child starts at a joint on a thicker (or equal) parent section.
    bool joint = false;
    for (const StemSkeleton& parent : t.stems)
      for (const CrossSection& c : parent.sections)
        if (&parent != &s && c.position == s.sections.front().position)
          joint = joint || c.radius >= s.sections.front().radius;
    EXPECT_TRUE(joint);
  }
}

TEST(GraphPathsGenerator, SameSeedSameTreeOtherSeedOtherTree) {
  const Parameters p = crown_on_trunk();
  const TreeSkeleton a = generate_skeleton(p, 7), b = generate_skeleton(p, 7),
                     c = generate_skeleton(p, 8);
  ASSERT_EQ(a.stems.size(), b.stems.size());
  for (std::size_t i = 0; i < a.stems.size(); ++i)
    for (std::size_t k = 0; k < a.stems[i].sections.size(); ++k)
      ASSERT_EQ(a.stems[i].sections[k].position, b.stems[i].sections[k].position);
  EXPECT_NE(a.stems.back().sections.back().position, c.stems.back().sections.back().position);
}

TEST(GraphPathsGenerator, MeshesThroughTheSharedMesher) {
  const TreeGeometry g = mesh_tree(generate_skeleton(crown_on_trunk(), 9), MeshResolution{});
  EXPECT_GT(g.triangle_count(), 1000u);
}

TEST(GraphPathsGenerator, RefusesBadSpacing) {
  Parameters p = crown_on_trunk();
  p.spacing = 0.0;
  EXPECT_THROW(generate_skeleton(p, 1), InputError);
  p.spacing = 0.001;  // billions of cells and nodes
  EXPECT_THROW(generate_skeleton(p, 1), InputError);
}

}  // namespace
}  // namespace landsim::trees::graph_paths
