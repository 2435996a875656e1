#include "trees/harmonic/particle_growth.h"
#include "trees/species.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "core/input_error.h"

namespace landsim::trees::harmonic {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Every block row set to calm values: no wander, no harmonics, no twist, no tropism, no
// variation, no arcs; callers set what a test needs. Values are stored as in files
// (degrees), read back in radians.
Parameters calm() {
  Parameters p = default_parameters();
  p.values[5] = 0.0;  // wander noise
  p.values[6] = 0.0;  // variation
  p.values[7] = 0.0;  // tropism
  for (std::size_t row = 0; row < 4; ++row) {
    p.values[8 + row * 9 + 7] = 0.0;   // twist
    p.values[68 + row * 2] = 0.0;      // wander angle
    p.values[76 + row * 3 + 1] = 0.0;  // harmonic amplitude
  }
  for (std::size_t i = 44; i < 68; ++i) p.values[i] = 0.0;  // arcs
  return p;
}

double angle_from_vertical(const Vec3& h) { return std::acos(std::clamp(h.z, -1.0, 1.0)); }

TEST(HarmonicGrowth, WithoutWanderOrHarmonicsATrunkFollowsItsArcSectionsExactly) {
  Parameters p = calm();
  p.values[0] = 40;                                      // max age
  p.values[8 + 2] = 0.0;                                 // no branches
  p.values[8 + 5] = 400;                                 // the trunk outlives the growth
  const double arc[8] = {10, -40, 5, 20, 6, -60, 0, 0};  // span, bend (degrees; + up)
  for (int k = 0; k < 8; ++k) p.values[44 + static_cast<std::size_t>(k)] = arc[k];
  const Growth g = grow(p, 1);
  const Chain& trunk = g.chains[0];
  ASSERT_EQ(trunk.particles.size(), 41u);
  // The heading left at particle k (after k steps of bending).
  const auto tilt = [&](int k) {
    return angle_from_vertical(trunk.particles[static_cast<std::size_t>(k)].heading);
  };
  EXPECT_NEAR(tilt(10), 40 * kDeg, 1e-9);
  EXPECT_NEAR(tilt(5), 20 * kDeg, 1e-9);   // half way through the first section
  EXPECT_NEAR(tilt(15), 20 * kDeg, 1e-9);  // the second section turned 20 degrees back up
  EXPECT_NEAR(tilt(21), 80 * kDeg, 1e-9);
  EXPECT_NEAR(tilt(40), 80 * kDeg, 1e-9);  // no section left: straight on
  // A planar arc: every particle in the vertical plane of the first bend, a step apart.
  const Vec3 plane = normalize(cross(trunk.particles[1].heading, Vec3{0, 0, 1}));
  for (std::size_t k = 1; k < trunk.particles.size(); ++k) {
    EXPECT_NEAR(dot(trunk.particles[k].position, plane), 0.0, 1e-9);
    EXPECT_NEAR(length(trunk.particles[k].position - trunk.particles[k - 1].position),
                p.step_length() * p.level(0).step_scale, 1e-12);
  }
}

TEST(HarmonicGrowth, WanderAndHarmonicsMakeBranchesDepartFromTheirArcs) {
  Parameters p = calm();
  p.values[0] = 40;
  p.values[8 + 2] = 0.0;
  p.values[8 + 5] = 400;
  p.values[68] = 10.0;  // trunk wander angle
  p.values[69] = 3.0;   // every 3 steps
  p.values[76] = 0.5;   // harmonic frequency
  p.values[77] = 5.0;   // amplitude
  const Growth g = grow(p, 1);
  double off = 0.0;
  for (const Particle& q : g.chains[0].particles)
    off = std::max(off, std::hypot(q.position.x, q.position.y));
  EXPECT_GT(off, 0.05);  // the straight trunk of the calm parameters would stay on the axis
}

TEST(HarmonicGrowth, GirthGrowsWithAgeAndEarlierStepsDoNotChange) {
  const Parameters p = default_parameters();
  const Growth young = grow(p, 9, 30), old = grow(p, 9, 60);
  ASSERT_LE(young.chains.size(), old.chains.size());
  int thicker = 0;
  for (std::size_t c = 0; c < young.chains.size(); ++c) {
    const Chain& a = young.chains[c];
    const Chain& b = old.chains[c];
    ASSERT_LE(a.particles.size(), b.particles.size());
    for (std::size_t k = 0; k < a.particles.size(); ++k) {
      ASSERT_EQ(a.particles[k].position, b.particles[k].position);  // the same particle
      const double ra = particle_radius(p, a, a.particles[k], young.age);
      const double rb = particle_radius(p, b, b.particles[k], old.age);
      ASSERT_GE(rb, ra);
      thicker += rb > ra ? 1 : 0;
      // Taper: along a chain, older particles are at least as thick.
      const double previous = k > 0 ? particle_radius(p, a, a.particles[k - 1], young.age) : ra;
      ASSERT_LE(ra, previous);
    }
  }
  EXPECT_GT(thicker, 100);
}

TEST(HarmonicGrowth, NodeAndBranchCountsFollowSpacingAndProbabilities) {
  Parameters p = calm();
  p.values[0] = 3000;      // max age
  p.values[8 + 0] = 3;     // trunk node spacing
  p.values[8 + 1] = 0.6;   // node probability
  p.values[8 + 2] = 0.5;   // branch probability
  p.values[8 + 5] = 3000;  // trunk terminal age
  p.values[17 + 5] = 1;    // level-1 buds live one step: no nodes of their own
  p.values[17 + 0] = 2;
  const Growth g = grow(p, 4);
  const double steps = 3000.0, nodes = steps / 3 * 0.6, branches = nodes * 0.5;
  EXPECT_NEAR(static_cast<double>(g.nodes), nodes, 4 * std::sqrt(steps / 3 * 0.6 * 0.4));
  EXPECT_NEAR(static_cast<double>(g.chains.size() - 1), branches, 4 * std::sqrt(nodes * 0.25));
}

TEST(HarmonicGrowth, SameSeedSameTreeOtherSeedOtherTree) {
  const Parameters p = default_parameters();
  const Growth a = grow(p, 5), b = grow(p, 5), c = grow(p, 6);
  ASSERT_EQ(a.chains.size(), b.chains.size());
  for (std::size_t k = 0; k < a.chains.size(); ++k)
    ASSERT_EQ(a.chains[k].particles.back().position, b.chains[k].particles.back().position);
  EXPECT_TRUE(a.chains.size() != c.chains.size() || !(a.chains.back().particles.back().position ==
                                                      c.chains.back().particles.back().position));
}

TEST(HarmonicGrowth, SemanticParticlesFollowTheirLevelSpacingAndProbability) {
  Parameters p = default_parameters();
  p.values[88 + 0] = 2;    // leaf spacing
  p.values[88 + 1] = 1.0;  // always
  p.values[88 + 4] = 2;    // from level 2
  p.values[88 + 7] = 0.0;  // no parts
  const Growth g = grow(p, 3);
  std::size_t expected = 0;  // one leaf every second step of every level-2+ bud
  for (const Chain& c : g.chains) {
    if (c.level >= 2) expected += (c.particles.size() - 1) / 2;
  }
  EXPECT_EQ(g.leaves.size(), expected);
  EXPECT_TRUE(g.parts.empty());
  for (const SemanticParticle& l : g.leaves)
    EXPECT_LE(std::acos(std::clamp(l.normal.z, -1.0, 1.0)), p.semantic(3) * kDeg + 1e-9);
}

TEST(HarmonicGrowth, ExplosiveGrowthIsRefused) {
  Parameters p = default_parameters();
  p.values[0] = 400;
  for (std::size_t row = 0; row < 4; ++row) {
    p.values[8 + row * 9 + 0] = 2;    // a node every second step
    p.values[8 + row * 9 + 1] = 1.0;  // always
    p.values[8 + row * 9 + 2] = 1.0;  // always a branch
    p.values[8 + row * 9 + 5] = 400;  // buds that never die
  }
  EXPECT_THROW(grow(p, 1, -1, 10000), InputError);
}

// The expected count that refuses explosive species before growing is the count grown: over
// 40 seeds of every shipped harmonic species at its own parameters (no per-tree variation),
// the mean number of particles within 10% of expected_particles.
TEST(HarmonicGrowth, ExpectedParticlesIsTheMeanGrown) {
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(LANDSIM_SOURCE_DIR) + "/data/species")) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("harmonic_", 0) != 0 || entry.path().extension() != ".toml") continue;
    Parameters p = std::get<Parameters>(load_species(entry.path().string()).parameters);
    p.values[6] = 0.0;  // variation: every seed the species' own values
    double sum = 0.0;
    constexpr int kSeeds = 40;
    for (int seed = 1; seed <= kSeeds; ++seed) {
      const Growth g = grow(p, static_cast<std::uint64_t>(seed));
      for (const Chain& c : g.chains) sum += static_cast<double>(c.particles.size() - 1);
    }
    const double expected = expected_particles(p);
    EXPECT_NEAR(sum / kSeeds / expected, 1.0, 0.1)
        << name << ": " << sum / kSeeds << " grown, " << expected << " expected";
  }
}

// A species that would grow about 10^90 particles is refused while its file is read, at
// its line, before anything grows (before: 1.3 GB and seconds of growth until the 5 million
// particle guard).
TEST(HarmonicGrowth, AnExplosiveSpeciesIsRefusedWhileItsFileIsRead) {
  const std::string file = R"(core = "harmonic"
name = "explosive"
general = [400, 0.13, 4, 0.0013, 0.003, 0.3, 0.05, 0.0]
hierarchy = [
  [2, 1.0, 1.0, 25, 137, 400, 1.0, 0, 1.0],
  [2, 1.0, 1.0, 30, 137, 400, 0.75, 0, 1.0],
  [2, 1.0, 1.0, 40, 137, 400, 0.6, 0, 0.7],
  [2, 1.0, 1.0, 45, 137, 400, 0.6, 0, 0.5],
]
)";
  try {
    parse_species_toml(file, "explosive.toml");
    FAIL() << "an explosive species was read";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("explosive.toml:4:", 0), 0u) << m;
    EXPECT_NE(m.find("hierarchy"), std::string::npos) << m;
    EXPECT_NE(m.find("more than the 5000000 landsim grows"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace landsim::trees::harmonic
