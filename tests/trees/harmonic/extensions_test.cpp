// The harmonic core beyond the 100 floats: the paper's four harmonic terms per level, internode
// growth with age, and the further semantic parts (flowers, thorns, auxiliary buds).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tests/trees/species_files.h"
#include "trees/harmonic/generator.h"
#include "trees/harmonic/particle_growth.h"
#include "trees/species.h"

namespace landsim::trees::harmonic {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// No wander, twist, tropism, variation, arcs or harmonics; a trunk that outlives the growth
// and no branches unless a test sets them.
Parameters calm(int age) {
  Parameters p = default_parameters();
  p.values[0] = age;
  p.values[5] = p.values[6] = p.values[7] = 0.0;
  for (std::size_t row = 0; row < 4; ++row) {
    p.values[8 + row * 9 + 7] = 0.0;   // twist
    p.values[68 + row * 2] = 0.0;      // wander angle
    p.values[76 + row * 3 + 1] = 0.0;  // harmonic amplitude
  }
  for (std::size_t i = 44; i < 68; ++i) p.values[i] = 0.0;  // arcs
  p.values[8 + 2] = 0.0;                                    // no branches
  p.values[8 + 5] = 400;
  return p;
}

// With only harmonics a chain turns about its side axis each step by H(age): the angle
// between successive headings is |a0 sin(f0 t + p0) + sum of the further terms|.
TEST(HarmonicTerms, ALevelsTurnIsTheSumOfItsFourTerms) {
  Parameters p = calm(30);
  p.values[76 + 0] = 0.4, p.values[76 + 1] = 3.0, p.values[76 + 2] = 10.0;  // row 0, degrees
  p.terms = {{0, 0.9, 2.0 * kDeg, 45 * kDeg},
             {0, 0.15, 4.0 * kDeg, 0.0},
             {0, 1.7, 1.0 * kDeg, 200 * kDeg},
             {1, 2.0, 20 * kDeg, 0.0}};  // level 1: not the trunk's
  const Growth g = grow(p, 1);
  const Chain& trunk = g.chains[0];
  ASSERT_EQ(trunk.particles.size(), 31u);
  for (int t = 0; t < 30; ++t) {
    const double h = 3.0 * kDeg * std::sin(0.4 * t + 10 * kDeg) +
                     2.0 * kDeg * std::sin(0.9 * t + 45 * kDeg) + 4.0 * kDeg * std::sin(0.15 * t) +
                     1.0 * kDeg * std::sin(1.7 * t + 200 * kDeg);
    const Vec3& a = trunk.particles[static_cast<std::size_t>(t)].heading;
    const Vec3& b = trunk.particles[static_cast<std::size_t>(t) + 1].heading;
    EXPECT_NEAR(std::acos(std::clamp(dot(a, b), -1.0, 1.0)), std::abs(h), 1e-7) << t;
  }
}

TEST(HarmonicTerms, SpeciesFilesGiveAtMostThreeFurtherTermsPerLevel) {
  const std::string head = "core = \"harmonic\"\n";
  const Species s = parse_species_toml(
      head + "harmonic_terms = [[1, 0.5, 3, 90], [1, 0.2, 1, 0], [2, 1.0, 2, 0]]\n", "h.toml");
  const auto& p = std::get<Parameters>(s.parameters);
  ASSERT_EQ(p.terms.size(), 3u);
  EXPECT_EQ(p.terms[2].level, 2);
  EXPECT_NEAR(p.terms[0].amplitude, 3 * kDeg, 1e-12);
  EXPECT_NEAR(p.terms[0].phase, 90 * kDeg, 1e-12);
  const std::string four = trees::testing::species_error(
      head + "harmonic_terms = [[1, 0.5, 3, 0], [1, 0.2, 1, 0], [1, 1, 1, 0], [1, 2, 1, 0]]\n",
      "h.toml");
  EXPECT_NE(four.find("h.toml:2"), std::string::npos) << four;
  EXPECT_NE(four.find("at most 3 further terms for level 1"), std::string::npos) << four;
  const std::string range =
      trees::testing::species_error(head + "harmonic_terms = [[1, 0.5, 45, 0]]\n", "h.toml");
  EXPECT_NE(range.find("amplitude 0-30 degrees"), std::string::npos) << range;
}

TEST(HarmonicTerms, TheKeysBeyondTheLayoutReadBackFromTheirFormat) {
  Parameters p = default_parameters();
  p.terms = {{2, 0.5, 3 * kDeg, 90 * kDeg}};
  p.elongation = {0.3, 5};
  p.parts = {{PartKind::flower, 3, false, 0.5, 0.04, 2, 40 * kDeg, 6},
             {PartKind::bud, 2, true, 0.7, 0.02, 1, 30 * kDeg, 5}};
  const Species s = parse_species_toml("core = \"harmonic\"\n" + format_parameters(p), "f.toml");
  const auto& q = std::get<Parameters>(s.parameters);
  ASSERT_EQ(q.terms.size(), 1u);
  EXPECT_NEAR(q.terms[0].phase, p.terms[0].phase, 1e-12);
  EXPECT_EQ(q.elongation.steps, 5);
  EXPECT_DOUBLE_EQ(q.elongation.initial, 0.3);
  ASSERT_EQ(q.parts.size(), 2u);
  EXPECT_EQ(q.parts[0].kind, PartKind::flower);
  EXPECT_EQ(q.parts[0].petals, 6);
  EXPECT_TRUE(q.parts[1].at_nodes);
  EXPECT_NEAR(q.parts[1].angle, 30 * kDeg, 1e-12);
}

// Internodes start at `initial` of their length and reach it `steps` later: at the growth's
// age each segment's length follows its own age, and everything grown at a particle stays
// on it.
TEST(Elongation, EachInternodesLengthFollowsItsAgeAndChildrenStayAttached) {
  Parameters p = calm(24);
  p.values[8 + 0] = 3, p.values[8 + 1] = 1.0, p.values[8 + 2] = 1.0;   // a branch every 3 steps
  p.values[8 + 9 + 5] = 10;                                            // level 1 lives 10 steps
  p.values[88 + 0] = 2, p.values[88 + 1] = 1.0, p.values[88 + 4] = 1;  // leaves on level 1
  p.elongation = {0.25, 6};
  const Growth g = grow(p, 2);
  ASSERT_GT(g.chains.size(), 3u);
  for (const Chain& c : g.chains) {
    const double full = p.step_length() * p.level(c.level).step_scale;
    for (std::size_t k = 1; k < c.particles.size(); ++k) {
      const int age = g.age - c.particles[k].birth;
      const double expected = full * (0.25 + 0.75 * std::min(1.0, age / 6.0));
      ASSERT_NEAR(length(c.particles[k].position - c.particles[k - 1].position), expected, 1e-9);
    }
  }
  for (std::size_t c = 1; c < g.chains.size(); ++c) {
    const Chain& child = g.chains[c];
    EXPECT_EQ(child.particles[0].position,
              g.chains[child.parent_chain].particles[child.parent_particle].position);
  }
  for (const SemanticParticle& l : g.leaves)
    EXPECT_EQ(l.position, g.chains[l.chain].particles[l.particle].position);
  // The straight trunk falls short of its full-grown height by its young internodes' deficit.
  Parameters full = p;
  full.elongation = {};
  const Growth h = grow(full, 2);
  double deficit = 0.0;
  for (const Particle& q : h.chains[0].particles)
    if (q.birth > 0)
      deficit += p.step_length() * p.level(0).step_scale * 0.75 *
                 (1.0 - std::min(1.0, (h.age - q.birth) / 6.0));
  EXPECT_GT(deficit, 2.0 * p.step_length());
  EXPECT_NEAR(h.chains[0].particles.back().position.z - g.chains[0].particles.back().position.z,
              deficit, 1e-9);
}

TEST(Parts, ThornsFlowersAndBudsFollowTheirSpacingLevelAndNodes) {
  Parameters p = calm(20);
  p.values[8 + 0] = 4, p.values[8 + 1] = 1.0, p.values[8 + 2] = 1.0;  // a branch every 4 steps
  p.values[8 + 9 + 5] = 8;
  p.values[88 + 1] = 0.0;  // no leaves
  p.values[88 + 7] = 0.0;  // no seed balls
  p.parts = {{PartKind::thorn, 1, false, 1.0, 0.01, 0, 70 * kDeg, 5},
             {PartKind::flower, 4, false, 1.0, 0.05, 1, 40 * kDeg, 6},
             {PartKind::bud, 1, true, 1.0, 0.02, 0, 30 * kDeg, 5}};
  const Growth g = grow(p, 4);
  std::size_t thorns = 0, flowers = 0, buds = 0;
  for (const SemanticParticle& s : g.parts) {
    thorns += s.kind == 3, flowers += s.kind == 2, buds += s.kind == 4;
    if (s.kind != 3) continue;  // a thorn stands off its shoot at its angle
    const Vec3& shoot = g.chains[s.chain].particles[s.particle].heading;
    EXPECT_NEAR(std::acos(std::clamp(dot(s.direction, shoot), -1.0, 1.0)), 70 * kDeg, 1e-6);
  }
  std::size_t steps = 0, level1_fourths = 0;
  for (const Chain& c : g.chains) {
    steps += c.particles.size() - 1;
    if (c.level >= 1) level1_fourths += (c.particles.size() - 1) / 4;
  }
  EXPECT_EQ(thorns, steps);  // every step of every level
  EXPECT_EQ(flowers, level1_fourths);
  EXPECT_EQ(buds, g.nodes);  // one at every node
  // Flowers are petals drawn at vigour 0 (the flower colour); thorns and buds bark stems.
  const TreeSkeleton s = growth_skeleton(p, g, {});
  std::size_t petals = 0;
  for (const LeafSkeleton& l : s.leaves) petals += l.vigour == 0.0f;
  EXPECT_EQ(petals, 6 * flowers);
  std::size_t drawn_chains = 0;  // a chain of one particle draws no stem
  for (const Chain& c : g.chains) drawn_chains += c.particles.size() >= 2;
  EXPECT_EQ(s.stems.size(), drawn_chains + thorns + buds);
}

TEST(Parts, TheFlowerColourIsTheSecondLeafColour) {
  const Species s = parse_species_toml(
      "core = \"harmonic\"\n[colours]\nleaf = [0.1, 0.2, 0.1]\nflower = [0.8, 0.3, 0.4]\n",
      "f.toml");
  EXPECT_FLOAT_EQ(s.colours.leaf_weak.x, 0.8f);
  EXPECT_FLOAT_EQ(s.colours.leaf_weak.z, 0.4f);
  const std::string both = trees::testing::species_error(
      "core = \"harmonic\"\n[colours]\nleaf_weak = [0.1, 0.2, 0.1]\nflower = [0.8, 0.3, 0.4]\n",
      "f.toml");
  EXPECT_NE(both.find("flower"), std::string::npos) << both;
  EXPECT_NE(both.find("not both"), std::string::npos) << both;
}

}  // namespace
}  // namespace landsim::trees::harmonic
