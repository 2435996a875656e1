#include "trees/graph_paths/root_system.h"

#include <gtest/gtest.h>

#include "core/counter_rng.h"
#include "tests/trees/graph_paths/crown_on_trunk.h"
#include "tests/trees/species_files.h"
#include "trees/graph_paths/generator.h"
#include "trees/graph_paths/refinement.h"
#include "trees/species.h"

namespace landsim::trees::graph_paths {
namespace {

// The tests' crown (1.2 m) on its trunk, with a root ball 1.5 m wide and 1 m deep.
Parameters rooted() {
  Parameters p = testing::crown_on_trunk(1.2, 40);
  p.endpoint_min_z = 2.0;
  p.roots.radius = 1.5;
  p.roots.depth = 1.0;
  p.roots.laterals = 10;
  return p;
}

// The stems added after the crown's: those whose sections reach below the root point.
std::size_t crown_stem_count(const Parameters& p, std::uint64_t seed) {
  Parameters bare = p;
  bare.roots.radius = 0.0;
  return generate_skeleton(bare, seed).stems.size();
}

TEST(RootSystem, RootsStayBelowGroundAndConnectToTheTrunkBase) {
  const Parameters p = rooted();
  const TreeSkeleton t = generate_skeleton(p, 3);
  const std::size_t crown = crown_stem_count(p, 3);
  ASSERT_GT(t.stems.size(), crown + 5);
  const CrossSection& trunk_base = t.stems[0].sections.front();
  const StemSkeleton& first = t.stems[crown];
  EXPECT_EQ(first.parent, 0);  // a branch of the trunk
  EXPECT_EQ(first.sections.front().position, trunk_base.position);
  for (std::size_t i = crown; i < t.stems.size(); ++i) {
    const StemSkeleton& stem = t.stems[i];
    ASSERT_GE(stem.parent, i == crown ? 0 : static_cast<int>(crown)) << i;
    // Every section but the joint with the trunk's base lies at or below the ground (z = 0).
    for (std::size_t k = i == crown ? 1 : 0; k < stem.sections.size(); ++k)
      ASSERT_LE(stem.sections[k].position.z, 1e-9) << "stem " << i << " section " << k;
    for (const CrossSection& c : stem.sections) ASSERT_LE(c.radius, trunk_base.radius + 1e-12);
  }
  for (const LeafSkeleton& leaf : t.leaves) EXPECT_LT(leaf.stem, static_cast<int>(crown));
}

double deepest(const TreeSkeleton& t) {
  double z = 0.0;
  for (const StemSkeleton& s : t.stems)
    for (const CrossSection& c : s.sections) z = std::min(z, c.position.z);
  return z;
}

double widest(const TreeSkeleton& t) {
  double r = 0.0;
  for (const StemSkeleton& s : t.stems)
    for (const CrossSection& c : s.sections)
      if (c.position.z < 0.0) r = std::max(r, std::hypot(c.position.x, c.position.y));
  return r;
}

TEST(RootSystem, TheTaprootReachesTheBottomAndLateralsTheShell) {
  Parameters p = rooted();
  const TreeSkeleton with = generate_skeleton(p, 4);
  EXPECT_LT(deepest(with), -0.8);  // the taproot's endpoint: 0.95 of the 1 m depth
  EXPECT_GT(widest(with), 1.1);    // laterals in the outer 0.3 of the 1.5 m radius
  p.roots.taproot = false;
  EXPECT_GT(deepest(generate_skeleton(p, 4)), -0.9);
  p.roots.radius = 0.0;  // off: nothing below the ground
  EXPECT_GE(deepest(generate_skeleton(p, 4)), -1e-9);
}

TEST(RootSystem, IteratedLevelsAddRootletsThatStayBelowGround) {
  Parameters p = rooted();
  const std::size_t plain = generate_skeleton(p, 5).stems.size();
  p.roots.levels = 1;
  const TreeSkeleton t = generate_skeleton(p, 5);
  EXPECT_GT(t.stems.size(), plain + 10);
  const std::size_t crown = crown_stem_count(p, 5);
  for (std::size_t i = crown; i < t.stems.size(); ++i)
    for (std::size_t k = i == crown ? 1 : 0; k < t.stems[i].sections.size(); ++k)
      ASSERT_LE(t.stems[i].sections[k].position.z, 1e-9);
}

TEST(RootSystem, SpeciesFileReadsRootsAndRefusesARootlessBall) {
  const std::string base = "core = \"graph_paths\"\n[[volume]]\nkind = \"sphere\"\nradius = 1.0\n";
  const Species s = parse_species_toml(
      base + "[roots]\nradius = 2.0\ndepth = 0.8\nlaterals = 5\nlevels = 1\ntaproot = false\n",
      "r.toml");
  const RootParameters& r = std::get<Parameters>(s.parameters).roots;
  EXPECT_DOUBLE_EQ(r.radius, 2.0);
  EXPECT_DOUBLE_EQ(r.depth, 0.8);
  EXPECT_EQ(r.laterals, 5);
  EXPECT_EQ(r.levels, 1);
  EXPECT_FALSE(r.taproot);
  const std::string none = trees::testing::species_error(
      base + "[roots]\nradius = 2.0\nlaterals = 0\ntaproot = false\n", "r.toml");
  EXPECT_NE(none.find("r.toml:7"), std::string::npos) << none;
  EXPECT_NE(none.find("laterals"), std::string::npos) << none;
  // A root ball far too finely sampled is refused before generating, as the crown's.
  const std::string dense =
      trees::testing::species_error(base + "[roots]\nradius = 50\nspacing = 0.01\n", "r.toml");
  EXPECT_NE(dense.find("limit"), std::string::npos) << dense;
}

// Manual endpoints with refinement: each joins the limb whose sphere is nearest and is
// reached there.
TEST(RootSystem, ManualEndpointsJoinTheNearestRefinedLimb) {
  Parameters p = rooted();
  p.roots.radius = 0.0;
  p.endpoints = 8;
  p.refinement.spheres = 3;
  p.refinement.radius = 0.6;
  p.junction = {0, 0, 2};
  const auto parts = refine(p.volume, p.refinement, p.junction, hash_combine(7, 4));
  ASSERT_FALSE(parts.empty());
  std::vector<Vec3> wanted;
  for (const Subvolume& part : parts) wanted.push_back(part.sphere.origin + Vec3{0.3, 0, 0.2});
  p.manual_endpoints = wanted;
  const TreeSkeleton t = generate_skeleton(p, 7);
  for (const Vec3& q : wanted) {
    double best = 1e300;
    for (const StemSkeleton& stem : t.stems)
      for (const CrossSection& c : stem.sections) best = std::min(best, length(c.position - q));
    EXPECT_LT(best, p.spacing);
  }
}

}  // namespace
}  // namespace landsim::trees::graph_paths
