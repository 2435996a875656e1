// "This tree at age t" for every core: the height-age curve's documented values; a younger
// tree is smaller in height and stem count; the species' mature age draws the file's tree
// unchanged; Weber & Penn and graph paths scale as documented; the harmonic and
// self-organising younger trees are the older ones' first steps.
#include "trees/tree_age.h"

#include <gtest/gtest.h>
#include <spdlog/sinks/ringbuffer_sink.h>
#include <spdlog/spdlog.h>

#include <filesystem>

#include "trees/harmonic/generator.h"
#include "trees/harmonic/particle_growth.h"
#include "trees/species.h"

namespace landsim::trees {
namespace {

Species species(const std::string& file) {
  return load_species(std::filesystem::path(LANDSIM_SOURCE_DIR) / "data/species" / file);
}

int stems(const Tree& t) {
  int n = 0;
  for (int k : t.stats.stems_per_level) n += k;
  return n;
}

TEST(TreeAge, TheCurveHasItsDocumentedValues) {
  const AgeCurve c{30.0};
  EXPECT_EQ(size_fraction(c, 0.0), 0.0);
  EXPECT_EQ(size_fraction(c, 30.0), 1.0);
  EXPECT_EQ(size_fraction(c, 45.0), 1.0);
  // docs/SPECIES.md "Age": 28% of the height at a fifth of the mature age, 68% at half.
  EXPECT_NEAR(size_fraction(c, 6.0), 0.28, 0.005);
  EXPECT_NEAR(size_fraction(c, 15.0), 0.685, 0.005);
  double last = 0.0;
  for (double t = 0.5; t <= 30.0; t += 0.5) {
    EXPECT_GT(size_fraction(c, t), last) << t;
    last = size_fraction(c, t);
  }
  EXPECT_EQ(levels_at(c, 6.0, 3), 2);   // ceil(3 x 0.28) = 1, but a trunk and branches
  EXPECT_EQ(levels_at(c, 15.0, 3), 3);  // ceil(3 x 0.685)
  EXPECT_EQ(levels_at(c, 1.0, 4), 2);
  EXPECT_EQ(levels_at(c, 1.0, 1), 1);
  EXPECT_EQ(levels_at(c, 9.0, 4), 2);  // ceil(4 x 0.43)
  EXPECT_EQ(steps_at(c, 15.0, 20), 10);
  EXPECT_EQ(steps_at(c, 100.0, 20), 20);
  EXPECT_EQ(clamp_age(c, 0.2, "x"), 1.0);
  EXPECT_EQ(clamp_age(c, 50.0, "x"), 30.0);
}

// An age outside the curve is clamped with one warning naming the species, the age asked
// and the range; an age inside it is used silently.
TEST(TreeAge, AClampedAgeIsWarnedAbout) {
  const AgeCurve c{.mature = 30.0};
  const auto sink = std::make_shared<spdlog::sinks::ringbuffer_sink_mt>(8);
  const auto logger = spdlog::default_logger();
  logger->sinks().push_back(sink);
  EXPECT_EQ(clamp_age(c, 50.0, "aspen"), 30.0);
  EXPECT_EQ(clamp_age(c, 12.0, "aspen"), 12.0);
  logger->sinks().pop_back();
  const std::vector<std::string> lines = sink->last_formatted();
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("aspen: age 50 is outside 1 to 30 years"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("using 30"), std::string::npos) << lines[0];
}

// Every core at two ages: the younger is lower and has fewer stems; at the mature age (or
// the species' own age) the tree is the file's, bit for bit.
TEST(TreeAge, EveryCoreGrowsWithAge) {
  for (const char* file : {"quaking_aspen.toml", "quaking_aspen.xml", "graph_round_crown.toml",
                           "so_upright.toml", "harmonic_cherry.toml", "london_plane.toml"}) {
    const Species s = species(file);
    const bool measured = uses_core<measured_growth::Parameters>(s);
    const double mature = measured ? 30.0 : s.age.mature;
    const Tree young = generate(s, {.seed = 3, .age = 0.4 * mature});
    const Tree old = generate(s, {.seed = 3, .age = mature});
    EXPECT_LT(young.stats.height, 0.9 * old.stats.height) << file;
    EXPECT_LT(stems(young), stems(old)) << file;
    if (measured) continue;
    const Tree own = generate(s, {.seed = 3});
    EXPECT_EQ(own.geometry.group(Group::trunk).triangles.vertices,
              old.geometry.group(Group::trunk).triangles.vertices)
        << file;
  }
}

// Weber & Penn: Scale times the size fraction; graph paths: the whole tree scaled. At 0.75 of
// the mature age both keep every level (ceil(3 x 0.886) = 3), so the height scales exactly
// (graph paths) or nearly (Weber & Penn's random draws do not depend on Scale, but its
// leaves keep their size).
TEST(TreeAge, WeberPennAndGraphPathsScaleByTheCurve) {
  for (const char* file : {"quaking_aspen.toml", "graph_round_crown.toml"}) {
    const Species s = species(file);
    const double t = 0.75 * s.age.mature, f = size_fraction(s.age, t);
    ASSERT_NEAR(f, 0.886, 0.002);
    const Tree young = generate(s, {.seed = 5, .age = t});
    const Tree old = generate(s, {.seed = 5});
    EXPECT_EQ(stems(young), stems(old)) << file;
    EXPECT_NEAR(young.stats.height / old.stats.height, f, 0.03) << file;
  }
}

// The harmonic core's younger tree is the older one's first steps: every chain of the
// younger growth is a prefix of the older's.
TEST(TreeAge, AYoungerHarmonicTreeIsTheOldersFirstSteps) {
  const Species cherry = species("harmonic_cherry.toml");
  const auto& p = std::get<harmonic::Parameters>(cherry.parameters);
  const harmonic::Parameters individual = harmonic::vary(p, 4);
  const harmonic::Growth young = harmonic::grow(individual, 4, individual.max_age() / 3);
  const harmonic::Growth old = harmonic::grow(individual, 4);
  ASSERT_LT(young.particles(), old.particles());
  std::size_t matched = 0;
  for (const harmonic::Chain& c : young.chains) {
    bool found = false;
    for (const harmonic::Chain& d : old.chains) {
      if (d.particles.size() < c.particles.size() ||
          d.particles[0].position != c.particles[0].position)
        continue;
      found = true;
      for (std::size_t k = 0; k < c.particles.size(); ++k)
        EXPECT_EQ(c.particles[k].position, d.particles[k].position);
      break;
    }
    EXPECT_TRUE(found);
    matched += found;
  }
  EXPECT_GT(matched, 3u);
}

// generate_ages draws what generate draws at each age (the self-organising core from one
// growth, the others one by one).
TEST(TreeAge, GenerateAgesIsGenerateAtEachAge) {
  for (const char* file : {"so_upright.toml", "harmonic_cherry.toml"}) {
    const Species s = species(file);
    const std::vector<double> ages = {0.3 * s.age.mature, s.age.mature, 0.6 * s.age.mature};
    const std::vector<Tree> trees = generate_ages(s, {.seed = 2}, ages);
    ASSERT_EQ(trees.size(), ages.size());
    for (std::size_t i = 0; i < ages.size(); ++i) {
      const Tree one = generate(s, {.seed = 2, .age = ages[i]});
      EXPECT_EQ(trees[i].geometry.group(Group::trunk).triangles.vertices,
                one.geometry.group(Group::trunk).triangles.vertices)
          << file << " at " << ages[i];
      EXPECT_EQ(trees[i].stats.leaves, one.stats.leaves);
    }
  }
}

}  // namespace
}  // namespace landsim::trees
