#include "trees/graph_paths/generator.h"

#include <gtest/gtest.h>

#include <numbers>

#include "core/input_error.h"
#include "tests/trees/graph_paths/crown_on_trunk.h"
#include "trees/mesher.h"

namespace landsim::trees::graph_paths {
namespace {

using testing::crown_on_trunk;

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

Parameters iterated(int levels) {
  Parameters p = crown_on_trunk();
  p.endpoint_min_z = 2.0;
  p.iteration.levels = levels;
  p.iteration.radius = 0.6;
  p.iteration.endpoints = 4;
  p.iteration.spacing_ratio = 0.25;
  return p;
}

TEST(GraphPathsGenerator, RadiusNeverGrowsAlongAStemOrIntoAChild) {
  const TreeSkeleton t = generate_skeleton(iterated(2), 6);
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
  const Parameters p = iterated(1);
  const TreeSkeleton a = generate_skeleton(p, 7), b = generate_skeleton(p, 7),
                     c = generate_skeleton(p, 8);
  ASSERT_EQ(a.stems.size(), b.stems.size());
  for (std::size_t i = 0; i < a.stems.size(); ++i)
    for (std::size_t k = 0; k < a.stems[i].sections.size(); ++k)
      ASSERT_EQ(a.stems[i].sections[k].position, b.stems[i].sections[k].position);
  EXPECT_NE(a.stems.back().sections.back().position, c.stems.back().sections.back().position);
}

double farthest_leaf(const TreeSkeleton& t, const Vec3& from) {
  double d = 0.0;
  for (const LeafSkeleton& leaf : t.leaves) d = std::max(d, length(leaf.base - from));
  return d;
}

double mean_leaf_z(const TreeSkeleton& t) {
  double z = 0.0;
  for (const LeafSkeleton& leaf : t.leaves) z += leaf.base.z;
  return z / static_cast<double>(t.leaves.size());
}

TEST(GraphPathsGenerator, IteratedSubgraphsGrowBeyondTheInitialVolume) {
  GraphStatistics one, three;
  const TreeSkeleton a = generate_skeleton(iterated(0), 2, &one);
  const TreeSkeleton b = generate_skeleton(iterated(2), 2, &three);
  EXPECT_GT(b.stems.size(), 3 * a.stems.size());
  EXPECT_GT(three.nodes, one.nodes);
  EXPECT_GT(b.leaves.size(), 4 * a.leaves.size());
  // The crown sphere has radius 1.5 about (0, 0, 3); level-1 cones reach 0.6 m beyond it.
  EXPECT_LE(farthest_leaf(a, {0, 0, 3}), 1.5);
  EXPECT_GT(farthest_leaf(b, {0, 0, 3}), 1.8);
  EXPECT_LE(farthest_leaf(b, {0, 0, 3}), 1.5 + 0.6 + 0.3 + 1e-9);
}

TEST(GraphPathsGenerator, DownwardRotationMakesWeepingBranches) {
  Parameters willow = iterated(3);
  willow.iteration.size_ratio = 0.8;
  willow.iteration.rotation = 50.0 * std::numbers::pi / 180;
  const double straight = mean_leaf_z(generate_skeleton(iterated(3), 4));
  const double weeping = mean_leaf_z(generate_skeleton(willow, 4));
  EXPECT_LT(weeping, straight - 0.3);
}

// Statistics of a three-level tree (seed 5) with the lifespan rule at `lifespan`, each child
// ending with `terminate`, under a light of `light` strength from +x; lifespan 0: without it.
GraphStatistics with_lifespan(double lifespan, double terminate, double light) {
  Parameters p = iterated(3);
  p.iteration.use_lifespan = lifespan > 0.0;
  p.iteration.lifespan = lifespan;
  p.iteration.terminate_probability = terminate;
  p.iteration.light = {1, 0, 0};
  p.iteration.light_strength = light;
  GraphStatistics stats;
  generate_skeleton(p, 5, &stats);
  return stats;
}

// Its graph nodes; its subgraphs' endpoints.
std::size_t nodes_with_lifespan(double lifespan, double terminate = 0.3, double light = 0.0) {
  return with_lifespan(lifespan, terminate, light).nodes;
}
std::size_t endpoints_with_lifespan(double lifespan, double terminate, double light) {
  return with_lifespan(lifespan, terminate, light).endpoints;
}

TEST(GraphPathsGenerator, LifespanEndsSomeBranchesEarly) {
  const std::size_t free_growth = nodes_with_lifespan(0.0), bush = nodes_with_lifespan(2.0);
  EXPECT_LT(bush, free_growth * 3 / 4);
  EXPECT_GT(bush, 0u);
}

// Section 3.3.3's decrement is a uniform part of the current lifespan L, so without the
// 30% ending (and without light) no lifespan runs out: a lifespan of 1 grows as far as
// free growth. (A fixed-size loss of about 1 per level stopped most branches at level 2.)
TEST(GraphPathsGenerator, ALifespanLosesAPartOfItselfAndNeverRunsOutAlone) {
  EXPECT_EQ(nodes_with_lifespan(1.0, 0.0), nodes_with_lifespan(0.0));
}

// The decrement itself: under a light, a branch facing away loses up to twice its lifespan
// and may run out with no ending drawn, so fewer subgraphs grow (6% fewer endpoints) than with
// the rule off under the same light. A lifespan never decremented would grow them all.
TEST(GraphPathsGenerator, ALifespanThatIsDecrementedRunsOutFacingAwayFromTheLight) {
  const std::size_t free_growth = endpoints_with_lifespan(0.0, 0.0, 1.0);
  const std::size_t decremented = endpoints_with_lifespan(1.0, 0.0, 1.0);
  EXPECT_LT(decremented, free_growth * 97 / 100);
  EXPECT_GT(decremented, 0u);
}

TEST(GraphPathsGenerator, LightFavoursTheSubgraphsFacingIt) {
  Parameters p = iterated(2);
  p.iteration.light = {1, 0, 0};
  p.iteration.light_strength = 1.0;
  const TreeSkeleton t = generate_skeleton(p, 6);
  int lit = 0, shaded = 0;
  for (const LeafSkeleton& leaf : t.leaves) (leaf.base.x > 0 ? lit : shaded) += 1;
  EXPECT_GT(lit, 1.3 * shaded);
  // Without the light the two sides are alike.
  p.iteration.light_strength = 0.0;
  const TreeSkeleton even = generate_skeleton(p, 6);
  lit = shaded = 0;
  for (const LeafSkeleton& leaf : even.leaves) (leaf.base.x > 0 ? lit : shaded) += 1;
  EXPECT_LT(lit, 1.15 * shaded);
  EXPECT_GT(lit, 0.87 * shaded);
}

TEST(GraphPathsGenerator, MeshesThroughTheSharedMesher) {
  const TreeGeometry g = mesh_tree(generate_skeleton(crown_on_trunk(), 9), MeshResolution{});
  EXPECT_GT(g.triangle_count(), 1000u);
}

// Endpoints the modeler places: a branch reaches each (within a node spacing), which the
// random endpoints alone do not do.
TEST(GraphPathsGenerator, ManualEndpointsAreReached) {
  const std::vector<Vec3> wanted = {{1.2, 0, 3.4}, {-0.6, 0.9, 4.1}, {0.3, -1.1, 2.6}};
  const auto nearest_tip = [](const TreeSkeleton& s, const Vec3& q) {
    double best = 1e300;
    for (const StemSkeleton& stem : s.stems)
      for (const CrossSection& c : stem.sections) best = std::min(best, length(c.position - q));
    return best;
  };
  Parameters p = crown_on_trunk();
  p.endpoints = 2;
  const TreeSkeleton plain = generate_skeleton(p, 4);
  p.manual_endpoints = wanted;
  const TreeSkeleton placed = generate_skeleton(p, 4);
  int missed_before = 0;
  for (const Vec3& q : wanted) {
    EXPECT_LT(nearest_tip(placed, q), p.spacing);
    missed_before += nearest_tip(plain, q) > 2 * p.spacing;
  }
  EXPECT_GE(missed_before, 2);
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
