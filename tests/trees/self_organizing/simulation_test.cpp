#include "trees/self_organizing/simulation.h"

#include <gtest/gtest.h>

#include <string>

#include "core/input_error.h"
#include "trees/self_organizing/generator.h"
#include "trees/species.h"

#include <tbb/task_arena.h>

namespace landsim::trees::self_organizing {
namespace {

Parameters crown(EnvelopeKind kind = EnvelopeKind::ellipsoid) {
  Parameters p;
  p.steps = 18;
  p.internode_length = 0.15;
  p.envelope.kind = kind;
  p.envelope.centre = {0, 0, 2.2};
  p.envelope.radii = {1.5, 1.5, 2};
  p.envelope.silhouette = {{0, 0}, {0.4, 0}, {0.4, 1.5}, {2.0, 2.5}, {1.5, 4.5}, {0, 5}};
  p.envelope.density = 80;
  return p;
}

TEST(SelfOrganizing, AnEnvelopeGrownCrownStaysInsideItsEnvelope) {
  for (EnvelopeKind kind : {EnvelopeKind::ellipsoid, EnvelopeKind::silhouette}) {
    Parameters p = crown(kind);
    if (kind == EnvelopeKind::ellipsoid) p.envelope.centre = {0, 0, 1.9};  // holds the seedling
    GrowthStatistics stats;
    const Plant plant = grow(p, 5, &stats);
    ASSERT_GT(stats.internodes, 200u);
    for (std::uint32_t i = 1; i < plant.size(); ++i)
      ASSERT_TRUE(p.envelope.contains(plant[i].tip)) << i;
  }
}

TEST(SelfOrganizing, WithoutConfinementShootsOvershootTheEnvelope) {
  // The check above could not fail if growth never reached the surface: unconfined, it does.
  Parameters p = crown(EnvelopeKind::silhouette);
  p.envelope.confine = false;
  const Plant plant = grow(p, 5);
  int outside = 0;
  for (std::uint32_t i = 1; i < plant.size(); ++i)
    outside += plant[i].alive && !p.envelope.contains(plant[i].tip) ? 1 : 0;
  EXPECT_GT(outside, 0);
}

TEST(SelfOrganizing, SameSeedSameTreeOtherSeedOtherTree) {
  const Parameters p = crown(EnvelopeKind::silhouette);
  const Plant a = grow(p, 11), b = grow(p, 11), c = grow(p, 12);
  ASSERT_EQ(a.size(), b.size());
  for (std::uint32_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].tip, b[i].tip);
    ASSERT_EQ(a[i].width, b[i].width);
  }
  bool differs = a.size() != c.size();
  for (std::uint32_t i = 0; i < std::min(a.size(), c.size()) && !differs; ++i)
    differs = !(a[i].tip == c[i].tip);
  EXPECT_TRUE(differs);
}

// The markers' passes and the bud grid's sort run on every core: the tree must be the same
// bits on one.
TEST(SelfOrganizing, TheSameTreeOnOneCoreAsOnTwo) {
  Parameters p = crown(EnvelopeKind::silhouette);
  p.envelope.density = 3000;  // some 60,000 markers: many chunks of the parallel passes
  const auto on = [&](int cores) {
    tbb::task_arena arena(cores);
    return arena.execute([&] { return grow(p, 7); });
  };
  const Plant one = on(1), two = on(2);
  ASSERT_GT(one.size(), 200u);
  ASSERT_EQ(one.size(), two.size());
  for (std::uint32_t i = 0; i < one.size(); ++i) {
    ASSERT_EQ(one[i].tip, two[i].tip) << i;
    ASSERT_EQ(one[i].width, two[i].width) << i;
  }
}

TEST(SelfOrganizing, ShootsFollowABrushStroke) {
  Parameters p;
  p.steps = 30;
  p.internode_length = 0.1;
  p.space.occupancy = 1.5;
  BrushStroke s;
  s.points = {{{0, 0, 0.3}, 0.4}, {{0, 0, 1.5}, 0.4}, {{1.5, 0, 2.0}, 0.4}};
  s.points_per_step = 0.15;
  s.markers_per_step = 80;
  s.max_age = 6;
  p.strokes = {s};
  const Plant plant = grow(p, 1);
  double farthest_x = 0.0;
  for (const Internode& n : plant.internodes())
    if (n.alive) farthest_x = std::max(farthest_x, n.tip.x);
  EXPECT_GT(farthest_x, 1.0);  // the tree turned along the stroke's second leg
}

// The first living branch of `plant` wider than `width` (it has branched), or 0.
std::uint32_t first_branch(const Plant& plant, double width) {
  for (std::uint32_t i = 1; i < plant.size(); ++i)
    if (plant[i].alive && plant.starts_branch(i) && plant[i].width > width) return i;
  return 0;
}

TEST(SelfOrganizing, PruningLeavesAStubThatKeepsItsWidth) {
  // Growth is sequential, so a 9-step tree is the 20-step tree as it stood before step 10.
  Parameters p = crown(EnvelopeKind::silhouette);
  p.steps = 9;
  const Plant at_nine = grow(p, 7);
  const std::uint32_t branch = first_branch(at_nine, p.width.tip);
  ASSERT_NE(branch, 0u);
  p.steps = 20;
  p.prunings = {{10, (at_nine[branch].base + at_nine[branch].tip) * 0.5, true}};
  const Plant after = grow(p, 7);
  EXPECT_TRUE(after[branch].alive);
  EXPECT_TRUE(after[branch].stub);
  for (std::uint32_t c : {after[branch].main, after[branch].lateral})
    EXPECT_TRUE(c == kNone || !after[c].alive);
  // The stub keeps the width it had when cut (wider than a tip: it had branched).
  EXPECT_DOUBLE_EQ(after[branch].width, at_nine[branch].width);
}

// TreeSketch's default pruning: the branch goes at its base and the widths below are as if
// it had never grown (the stub of the test above keeps them instead).
TEST(SelfOrganizing, PruningRemovesTheBranchAsIfItNeverGrew) {
  Parameters p = crown(EnvelopeKind::silhouette);
  p.steps = 9;
  const Plant at_nine = grow(p, 7);
  const std::uint32_t branch = first_branch(at_nine, 2 * p.width.tip);
  ASSERT_NE(branch, 0u);
  const std::uint32_t parent = at_nine[branch].parent;
  p.steps = 10;
  p.prunings = {{10, (at_nine[branch].base + at_nine[branch].tip) * 0.5, false}};
  const Plant pruned = grow(p, 7);
  EXPECT_FALSE(pruned[branch].alive);
  EXPECT_FALSE(pruned[parent].lateral_bud);  // the bud that grew it does not grow again
  // The parent's width is the pipe sum of what it still carries, nothing of the branch.
  const double kept = pruned[parent].width;
  EXPECT_EQ(pruned[parent].shed_lateral_width, 0.0);
  p.prunings = {{10, (at_nine[branch].base + at_nine[branch].tip) * 0.5, true}};
  const Plant stubbed = grow(p, 7);
  EXPECT_LT(kept, stubbed[parent].width);
}

TEST(SelfOrganizing, HeavySheddingRemovesBranches) {
  Parameters p = crown(EnvelopeKind::silhouette);
  p.light.a = 0.2;  // strong shade
  GrowthStatistics none, heavy;
  grow(p, 3, &none);
  p.vigour.shedding = 0.6;
  grow(p, 3, &heavy);
  EXPECT_EQ(none.shed_branches, 0u);
  EXPECT_GT(heavy.shed_branches, 5u);
}

TEST(SelfOrganizing, GrowthBeyondTheInternodeLimitIsRefused) {
  Parameters p;
  p.steps = 60;
  p.space.autonomous_markers = 6;
  p.max_internodes = 2000;
  EXPECT_THROW(grow(p, 1), InputError);
  p.max_internodes = 1000000;
  p.max_markers = 5000;  // and too many markers at once
  EXPECT_THROW(grow(p, 1), InputError);
}

// What growing the species file's text says when it refuses, or "" if it grows.
std::string growth_refusal(const std::string& text, const std::string& file) {
  try {
    generate(parse_species_toml(text, file), TreeOptions{});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A brush painting 100,000 markers a step through a 20 m sphere, shoots of 20 metamers: the
// internodes multiply every step. Refused at the step whose shoots would pass the limit,
// before they grow (a second and ~200 MB in a Release build; it was 6 s and 835 MB at the
// old 10^6 limit, refused after growing), naming the file, the limit and the keys.
TEST(SelfOrganizing, AnExplodingSpeciesIsRefusedNamingItsFileLimitAndKeys) {
  ASSERT_EQ(Parameters{}.max_internodes, 100000u);
  const std::string m = growth_refusal(
      "core = \"self_organizing\"\nname = \"hostile\"\n[growth]\nsteps = 300\n"
      "internode_length = 0.12\n[vigour]\nmax_shoot = 20\n[[stroke]]\n"
      "points = [[0, 0, 0.4, 10], [0, 0, 40, 20]]\npoints_per_step = 0.1\n"
      "markers_per_step = 100000\nmax_age = 150\n",
      "hostile.toml");
  EXPECT_EQ(m.rfind("hostile.toml: ", 0), 0u) << m;
  EXPECT_NE(m.find("limit of 100000 internodes at step "), std::string::npos) << m;
  EXPECT_NE(m.find("its shoots would make "), std::string::npos) << m;
  for (const char* key : {"growth.steps", "vigour.max_shoot", "markers_per_step", "max_age"})
    EXPECT_NE(m.find(key), std::string::npos) << key << " in " << m;
}

// A hundred autonomous markers per bud and shoots of 20 metamers: the markers multiply with
// the buds. Refused before a step's buds drop them, at the step that would drop more than 2
// million (it held 20 million, 1.3 GB, before the first guard; 3 s at the 10-million guard on
// markers held), naming the file, the limit and the keys.
TEST(SelfOrganizing, AutonomousMarkersAreRefusedBeforeTheBudsDropThem) {
  const std::string m = growth_refusal(
      "core = \"self_organizing\"\nname = \"auto\"\n[growth]\nsteps = 100\n"
      "internode_length = 0.12\n[space]\nautonomous_markers = 100\n[vigour]\nmax_shoot = 20\n",
      "auto.toml");
  EXPECT_EQ(m.rfind("auto.toml: ", 0), 0u) << m;
  EXPECT_NE(m.find(" autonomous markers at step "), std::string::npos) << m;
  EXPECT_NE(m.find("more than the limit of 2000000 a step"), std::string::npos) << m;
  for (const char* key : {"space.autonomous_markers", "vigour.max_shoot"})
    EXPECT_NE(m.find(key), std::string::npos) << key << " in " << m;
}

TEST(SelfOrganizing, SkeletonHasOneStemPerAxisAndLeavesOnYoungShoots) {
  const Parameters p = crown(EnvelopeKind::silhouette);
  GrowthStatistics stats;
  const Plant plant = grow(p, 2, &stats);
  const TreeSkeleton s = generate_skeleton(p, 2);
  std::size_t axes = 0;
  for (std::uint32_t i = 0; i < plant.size(); ++i)
    axes += plant[i].alive && (i == 0 || plant.starts_branch(i)) ? 1 : 0;
  EXPECT_EQ(s.stems.size(), axes);
  EXPECT_EQ(s.stems[0].level, 0);
  EXPECT_GT(s.stems[0].sections.front().radius, s.stems[0].sections.back().radius);
  EXPECT_GT(s.leaves.size(), 50u);
  EXPECT_LT(s.leaves.size(), stats.internodes);
  // Leaves are coloured by their shoot's vigour: full on the strong shoots, less on weak.
  int full = 0, weaker = 0;
  for (const LeafSkeleton& leaf : s.leaves) {
    ASSERT_GE(leaf.vigour, 0.0f);
    ASSERT_LE(leaf.vigour, 1.0f);
    (leaf.vigour == 1.0f ? full : weaker) += 1;
  }
  EXPECT_GT(full, 0);
  EXPECT_GT(weaker, 0);
}

}  // namespace
}  // namespace landsim::trees::self_organizing
