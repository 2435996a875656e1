// Wind sway (Weber & Penn section 4.7) on every core's skeleton (trees/sway.h).
#include "trees/sway.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "tests/support/temp_dir.h"
#include "trees/species.h"

namespace landsim::trees {
namespace {

using landsim::testing::source_file;

TEST(Sway, AnglesFollowThePapersFormulaAtAJoint) {
  // L = 2 m, Z = 0.25, r_Z = 0.05 m, r_0 = 0.08 m, speed 10, gust 5, t = 30 s, phases 0.3 and
  // 1.1, a stretch of a quarter of the stem (nCurveRes = 4). By hand (python3, math):
  // a0 = 4 x 2 x 0.75 / 0.05 = 120, a1 = 24, a2 = 12 + 12 = 24, rate = 0.08 / 2 x 30 / 15 =
  // 0.08; x: (24 sin 0.38 + 24 sin 0.266) / 4 = 3.80277; y: (24 sin 1.18 + 24 sin 0.826) / 4
  // = 9.95899 degrees.
  const WindState wind{30.0, 10.0, 5.0, 1};
  const SwayAngles a = sway_angles(wind, 2.0, 0.25, 0.05, 0.08, 0.5, 0.3, 1.1);
  EXPECT_NEAR(a.x, 3.80277, 1e-5);
  EXPECT_NEAR(a.y, 9.95899, 1e-5);
  // Other joints of another stem: speed 3, gust 1, t = 12 s, phases 2.0 and 4.5, a fifth of
  // the stem. Z = 0, r = 0.08: a0 = 100, a1 = 6, a2 = 2 + 3 = 5, rate = 0.032;
  // x: (6 sin 2.032 + 5 sin 1.4224) / 5 = 2.06363, y: (6 sin 4.532 + 5 sin 3.1724) / 5 =
  // -1.21133. Z = 0.75, r = 0.03: a0 = 66.667, every angle 2/3 of those.
  const WindState light{12.0, 3.0, 1.0, 1};
  const SwayAngles base = sway_angles(light, 2.0, 0.0, 0.08, 0.08, 0.4, 2.0, 4.5);
  EXPECT_NEAR(base.x, 2.06363, 1e-5);
  EXPECT_NEAR(base.y, -1.21133, 1e-5);
  const SwayAngles upper = sway_angles(light, 2.0, 0.75, 0.03, 0.08, 0.4, 2.0, 4.5);
  EXPECT_NEAR(upper.x, 2.06363 * 2.0 / 3.0, 1e-5);
  EXPECT_NEAR(upper.y, -1.21133 * 2.0 / 3.0, 1e-5);
  // At the tip of a linearly tapered stem a0 stays 4 L / r_0: (1 - Z) / r_Z is constant.
  EXPECT_NEAR(sway_amplitude(2.0, 0.9, 0.008), 4.0 * 2.0 / 0.08, 1e-9);
  // a0 is not capped (a twig 1000 times thinner than long: 4000 degrees), but each joint's
  // turn is bounded by its share of kMaxStemTurn.
  EXPECT_EQ(sway_amplitude(1.0, 0.0, 0.001), 4000.0);
  const SwayAngles storm = sway_angles({0.0, 100.0, 100.0, 1}, 1.0, 0.0, 0.001, 0.001, 0.25,
                                       std::numbers::pi / 2, -std::numbers::pi / 2);
  EXPECT_EQ(storm.x, 0.25 * kMaxStemTurn);
  EXPECT_EQ(storm.y, -0.25 * kMaxStemTurn);
  // Calm: no angle.
  const SwayAngles calm = sway_angles({30.0, 0.0, 0.0, 1}, 2.0, 0.25, 0.05, 0.08, 0.5, 0.3, 1.1);
  EXPECT_EQ(calm.x, 0.0);
  EXPECT_EQ(calm.y, 0.0);
}

TEST(Sway, AThickerOrShorterStemSwaysLess) {
  const WindState wind{0.0, 10.0, 5.0, 1};  // t = 0: b is the phase alone
  const auto angle = [&](double length, double radius) {
    // The same share of the stem, at the same place, with the same phases.
    return std::abs(sway_angles(wind, length, 0.2, radius, radius, 0.25 * length, 1.0, 1.0).x);
  };
  EXPECT_LT(angle(2.0, 0.1), angle(2.0, 0.05));                 // thicker
  EXPECT_LT(angle(1.0, 0.05), angle(2.0, 0.05));                // shorter
  EXPECT_NEAR(angle(2.0, 0.1), 0.5 * angle(2.0, 0.05), 1e-12);  // a0 is 1 / r
}

TEST(Sway, LeavesFlutterFasterThanStemsSwayWithinTheirBound) {
  const WindState wind{3.0, 5.0, 4.0, 11};
  // min(45, 3 x (5 + 4)) = 27 degrees at most; leaves differ, and each changes within 0.1 s.
  double largest = 0.0;
  int changed = 0;
  for (std::size_t leaf = 0; leaf < 200; ++leaf) {
    const double a = flutter_angle(wind, leaf);
    largest = std::max(largest, std::abs(a));
    WindState later = wind;
    later.time += 0.1;
    changed += std::abs(flutter_angle(later, leaf) - a) > 1.0;
  }
  EXPECT_LE(largest, 27.0 + 1e-9);
  EXPECT_GT(largest, 20.0);
  EXPECT_GT(changed, 150);
  EXPECT_NE(flutter_angle(wind, 0), flutter_angle(wind, 1));
  EXPECT_EQ(flutter_angle({3.0, 0.0, 0.0, 11}, 0), 0.0);  // calm
  EXPECT_LE(std::abs(flutter_angle({3.0, 100.0, 100.0, 11}, 5)), kMaxFlutter);
}

Species species(const std::string& file) {
  return load_species(source_file("data/species/" + file).string());
}

// One species of each core.
const char* const kCores[] = {"quaking_aspen.toml", "graph_column.toml", "so_envelope.toml",
                              "london_plane.toml", "harmonic_cherry.toml"};

Tree tree(const Species& s, double time, double speed, double gust) {
  TreeOptions o;
  o.seed = 7;
  o.time = time;
  o.wind_speed = speed;
  o.wind_gust = gust;
  o.quality = 0.5;
  return generate(s, o);
}

const std::vector<Vec3f>& vertices(const Tree& t, Group g) {
  return t.geometry.group(g).triangles.vertices;
}

TEST(Sway, EveryCoreSwaysWithWindAndStandsStillWithout) {
  for (const char* file : kCores) {
    const Species s = species(file);
    const Tree calm0 = tree(s, 0.0, 0.0, 0.0), calm5 = tree(s, 5.0, 0.0, 0.0);
    const Tree windy1 = tree(s, 1.0, 10.0, 5.0), windy4 = tree(s, 4.0, 10.0, 5.0);
    for (Group g : {Group::trunk, Group::leaves}) {
      EXPECT_EQ(vertices(calm0, g), vertices(calm5, g)) << file;  // bit-identical
      ASSERT_EQ(vertices(windy1, g).size(), vertices(windy4, g).size()) << file;
    }
    // The crown moves between two frames (the trunk's base does not).
    double moved = 0.0;
    const auto& a = vertices(windy1, Group::leaves);
    const auto& b = vertices(windy4, Group::leaves);
    ASSERT_FALSE(a.empty()) << file;
    for (std::size_t i = 0; i < a.size(); ++i) moved = std::max(moved, double(length(a[i] - b[i])));
    EXPECT_GT(moved, 0.01) << file;
    // The trunk's base stays where it grows.
    TreeOptions o;
    o.seed = 7;
    o.quality = 0.5;
    const TreeSkeleton calm = core_skeleton(s, o);
    TreeSkeleton windy = calm;
    apply_sway(windy, {4.0, 10.0, 5.0, 7});
    EXPECT_EQ(windy.stems[0].sections[0].position, calm.stems[0].sections[0].position) << file;
    EXPECT_NE(windy.stems[0].sections.back().position, calm.stems[0].sections.back().position)
        << file;
  }
}

// The distance from `p` to the nearest stretch of `stem`.
double distance_to(const StemSkeleton& stem, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < stem.sections.size(); ++k) {
    const Vec3 a = stem.sections[k].position, ab = stem.sections[k + 1].position - a;
    const double t = std::clamp(dot(p - a, ab) / std::max(dot(ab, ab), 1e-30), 0.0, 1.0);
    best = std::min(best, length(p - (a + ab * t)));
  }
  return stem.sections.size() == 1 ? length(p - stem.sections[0].position) : best;
}

TEST(Sway, NoStemOrLeafDetachesUnderTheStrongestWind) {
  for (const char* file : kCores) {
    const Species s = species(file);
    TreeOptions o;
    o.seed = 7;
    o.quality = 0.5;
    TreeSkeleton calm = core_skeleton(s, o);
    complete_attachments(calm);
    TreeSkeleton windy = calm;
    apply_sway(windy, {2.0, 100.0, 100.0, 7});
    std::size_t children = 0;
    for (std::size_t i = 0; i < calm.stems.size(); ++i) {
      const int parent = calm.stems[i].parent;
      if (parent < 0 || calm.stems[i].sections.empty()) continue;
      ASSERT_LT(parent, static_cast<int>(i)) << file;
      const auto& pc = calm.stems[static_cast<std::size_t>(parent)];
      const auto& pw = windy.stems[static_cast<std::size_t>(parent)];
      const double before = distance_to(pc, calm.stems[i].sections.front().position);
      const double after = distance_to(pw, windy.stems[i].sections.front().position);
      EXPECT_LE(after, before + 1e-6 * (1.0 + before)) << file << " stem " << i;
      ++children;
    }
    EXPECT_GT(children, 0u) << file;
    for (std::size_t i = 0; i < calm.leaves.size(); ++i) {
      const int stem = calm.leaves[i].stem;
      ASSERT_GE(stem, 0) << file;
      const double before =
          distance_to(calm.stems[static_cast<std::size_t>(stem)], calm.leaves[i].base);
      const double after =
          distance_to(windy.stems[static_cast<std::size_t>(stem)], windy.leaves[i].base);
      EXPECT_LE(after, before + 1e-6 * (1.0 + before)) << file << " leaf " << i;
    }
  }
}

}  // namespace
}  // namespace landsim::trees
