#include "trees/weber_penn/generator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "trees/weber_penn/shape_ratio.h"

namespace landsim::trees::weber_penn {
namespace {

GenerateOptions seeded(std::uint64_t seed) {
  GenerateOptions o;
  o.seed = seed;
  return o;
}

// A bare trunk, straight and untapered: single features are then easy to see.
Parameters bare_trunk(int curve_res) {
  Parameters p;
  p.levels = 1;
  p.scale = 10.0;
  p.scale_v = 0.0;
  p.flare = 0.0;
  p.leaves = 0;
  p.level[0].curve_res = curve_res;
  p.level[0].taper = 0.0;
  return p;
}

double angle_deg(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(dot(normalize(a), normalize(b)), -1.0, 1.0)) * 180.0 /
         std::numbers::pi;
}

// The direction of segment k of a stem whose sections are one per segment end.
Vec3 segment_direction(const StemSkeleton& s, std::size_t k) {
  return s.sections[k + 1].position - s.sections[k].position;
}

TEST(Generator, SegmentZeroDoesNotCurve) {
  Parameters p = bare_trunk(3);
  p.level[0].curve = 90.0;
  const TreeSkeleton t = generate_skeleton(p, {});
  ASSERT_EQ(t.stems.size(), 1u);
  const StemSkeleton& trunk = t.stems[0];
  ASSERT_EQ(trunk.sections.size(), 4u);
  EXPECT_NEAR(angle_deg(segment_direction(trunk, 0), {0, 0, 1}), 0.0, 1e-9);
  // nCurve / nCurveRes = 30 degrees for each later segment.
  EXPECT_NEAR(angle_deg(segment_direction(trunk, 1), {0, 0, 1}), 30.0, 1e-9);
  EXPECT_NEAR(angle_deg(segment_direction(trunk, 2), {0, 0, 1}), 60.0, 1e-9);
}

TEST(Generator, CurveBackMakesAnSShape) {
  Parameters p = bare_trunk(4);
  p.level[0].curve = 40.0;
  p.level[0].curve_back = -40.0;
  const StemSkeleton trunk = generate_skeleton(p, {}).stems[0];
  // First half turns by 2 nCurve / nCurveRes, the second half back by 2 nCurveBack / nCurveRes.
  EXPECT_NEAR(angle_deg(segment_direction(trunk, 1), {0, 0, 1}), 20.0, 1e-9);
  EXPECT_NEAR(angle_deg(segment_direction(trunk, 2), {0, 0, 1}), 0.0, 1e-9);
  EXPECT_NEAR(angle_deg(segment_direction(trunk, 3), {0, 0, 1}), 20.0, 1e-9);
}

TEST(Generator, RandomCurvatureBendsInEveryDirection) {
  // nCurveV turns each segment about a random axis across the stem, so trunks lean every
  // way, not only in the plane of nCurve.
  Parameters p = bare_trunk(5);
  p.level[0].curve_v = 80.0;
  int east = 0, west = 0, north = 0, south = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const Vec3 tip = generate_skeleton(p, seeded(seed)).stems[0].sections.back().position;
    east += tip.x > 0.2;
    west += tip.x < -0.2;
    north += tip.y > 0.2;
    south += tip.y < -0.2;
  }
  EXPECT_GT(east, 3);
  EXPECT_GT(west, 3);
  EXPECT_GT(north, 3);
  EXPECT_GT(south, 3);
}

TEST(Generator, HelixModeWindsAroundTheAxis) {
  Parameters p = bare_trunk(2);
  p.level[0].curve_v = -30.0;
  const StemSkeleton trunk = generate_skeleton(p, {}).stems[0];
  ASSERT_GT(trunk.sections.size(), 10u);  // subdivided along the helix
  const double helix_r = std::tan(30.0 * std::numbers::pi / 180.0) * 5.0 / (2.0 * std::numbers::pi);
  double farthest = 0.0;
  for (const CrossSection& c : trunk.sections)
    farthest = std::max(farthest, std::hypot(c.position.x, c.position.y));
  EXPECT_NEAR(farthest, 2.0 * helix_r,
              0.05 * helix_r);  // the helix passes the far side of its axis
  EXPECT_NEAR(trunk.sections.back().position.z, 10.0, 1e-9);  // and comes back to it
}

TEST(Generator, SplittingEverySegmentDoublesTheStems) {
  Parameters p = bare_trunk(4);
  p.level[0].seg_splits = 1.0;
  p.level[0].split_angle = 30.0;
  const TreeSkeleton t = generate_skeleton(p, {});
  // Splits happen at the ends of segments 0, 1 and 2: 2^3 stems, 7 of them clones.
  int clones = 0;
  for (const StemSkeleton& s : t.stems) clones += s.clone ? 1 : 0;
  EXPECT_EQ(t.stems.size(), 8u);
  EXPECT_EQ(clones, 7);
}

TEST(Generator, FractionalSplitsFollowErrorDiffusion) {
  Parameters p = bare_trunk(2);  // one split point per stem: no clone of a clone
  p.level[0].branches = 40;      // forty trunks share level 0's error value
  p.level[0].seg_splits = 0.25;
  p.level[0].split_angle = 20.0;
  const TreeSkeleton t = generate_skeleton(p, {});
  int clones = 0;
  for (const StemSkeleton& s : t.stems) clones += s.clone ? 1 : 0;
  EXPECT_EQ(clones, 10);  // 40 x 0.25 exactly
}

double azimuth_deg(const Vec3& v) { return std::atan2(v.y, v.x) * 180.0 / std::numbers::pi; }

TEST(Generator, SplitTurnsTheOriginalStemToo) {
  // One base split at the end of the trunk's first segment: clone and original both turn by
  // the split angle, the clone spreads 360 / 2 = 180 degrees about the vertical.
  Parameters p = bare_trunk(5);
  p.base_splits = 1;
  p.level[0].split_angle = 40.0;
  const TreeSkeleton t = generate_skeleton(p, {});
  ASSERT_EQ(t.stems.size(), 2u);
  const Vec3 original = segment_direction(t.stems[0], 1);
  const Vec3 clone = segment_direction(t.stems[1], 0);
  // 40 degrees less the first quarter of the correction spread over the 4 remaining segments.
  EXPECT_NEAR(angle_deg(original, {0, 0, 1}), 30.0, 1e-6);
  EXPECT_NEAR(angle_deg(clone, {0, 0, 1}), 30.0, 1e-6);
  EXPECT_NEAR(std::abs(std::remainder(azimuth_deg(original) - azimuth_deg(clone), 360.0)), 180.0,
              1e-6);
}

TEST(Generator, SplitSpreadFollowsThePaperFormula) {
  Parameters p = bare_trunk(3);
  p.level[0].seg_splits = 1.0;
  p.level[0].split_angle = 40.0;
  // 20 + 0.75 (30 + |0 - 90|) r^2 = 20 + 90 r^2 for r uniform in [0, 1): from 20 to 110
  // degrees, mean 20 + 90 / 3 = 50, and half the spreads below 20 + 90 / 4 = 42.5 (r < 0.5).
  // Over 400 seeds the mean's standard error is 90 sqrt(1/5 - 1/9) / 20 = 1.34 degrees and
  // the fraction's 0.025: the margins are three of them.
  constexpr int kSeeds = 400;
  double sum = 0.0;
  int below = 0;
  for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
    const TreeSkeleton t = generate_skeleton(p, seeded(seed));
    // stems[0] is the trunk, stems[1] its first clone (split at declination 0).
    const Vec3 a = segment_direction(t.stems[0], 1), b = segment_direction(t.stems[1], 0);
    const double spread = angle_deg({a.x, a.y, 0.0}, {b.x, b.y, 0.0});
    ASSERT_GE(spread, 20.0 - 1e-6);
    ASSERT_LE(spread, 110.0 + 1e-6);
    sum += spread;
    below += spread < 42.5;
  }
  EXPECT_NEAR(sum / kSeeds, 50.0, 4.0);
  EXPECT_NEAR(static_cast<double>(below) / kSeeds, 0.5, 0.075);
}

TEST(Generator, SplitAngleCorrectionTurnsBackOverTheRemainingSegments) {
  Parameters p = bare_trunk(5);
  p.base_splits = 1;
  p.level[0].split_angle = 30.0;
  const StemSkeleton original = generate_skeleton(p, {}).stems[0];
  EXPECT_NEAR(angle_deg(segment_direction(original, 1), {0, 0, 1}), 22.5, 1e-6);
  EXPECT_NEAR(angle_deg(segment_direction(original, 2), {0, 0, 1}), 15.0, 1e-6);
  EXPECT_NEAR(angle_deg(segment_direction(original, 4), {0, 0, 1}), 0.0, 1e-6);  // parallel again
}

TEST(Generator, ChildrenNeverThickerThanTheirParentWhereTheyGrow) {
  Parameters p;
  p.scale = 10.0;
  p.ratio_power = -2.0;  // would make short children thicker
  p.leaves = 0;
  const TreeSkeleton t = generate_skeleton(p, seeded(7));
  const double trunk_base = t.stems[0].sections[0].radius;
  for (const StemSkeleton& s : t.stems) {
    if (s.level == 1) {
      ASSERT_LE(s.sections[0].radius, trunk_base + 1e-12);
    }
  }
}

TEST(Generator, TrunkScaleEntersTheRadiusChildrenInherit) {
  Parameters p;
  p.leaves = 0;
  p.levels = 2;
  p.ratio_power = 1.0;
  p.level[0].taper = 0.0;  // a cylinder: the parent's radius never caps its children
  const TreeSkeleton a = generate_skeleton(p, seeded(5));
  p.trunk_scale = 2.0;
  const TreeSkeleton b = generate_skeleton(p, seeded(5));
  ASSERT_EQ(a.stems.size(), b.stems.size());
  EXPECT_NEAR(b.stems[0].sections[0].radius, 2.0 * a.stems[0].sections[0].radius, 1e-9);
  EXPECT_NEAR(b.stems[1].sections[0].radius, 2.0 * a.stems[1].sections[0].radius, 1e-9);
}

TEST(Generator, SameSeedSameTreeOtherSeedOtherTree) {
  Parameters p;
  p.leaves = 20;
  const TreeSkeleton a = generate_skeleton(p, seeded(11));
  const TreeSkeleton b = generate_skeleton(p, seeded(11));
  const TreeSkeleton c = generate_skeleton(p, seeded(12));
  ASSERT_EQ(a.stems.size(), b.stems.size());
  ASSERT_EQ(a.leaves.size(), b.leaves.size());
  for (std::size_t i = 0; i < a.stems.size(); ++i) {
    ASSERT_EQ(a.stems[i].sections.size(), b.stems[i].sections.size());
    for (std::size_t k = 0; k < a.stems[i].sections.size(); ++k) {
      ASSERT_EQ(a.stems[i].sections[k].position, b.stems[i].sections[k].position);
    }
  }
  ASSERT_GT(a.stems.size(), 2u);
  ASSERT_GT(c.stems.size(), 2u);
  EXPECT_NE(a.stems[1].sections.back().position, c.stems[1].sections.back().position);
}

double declination_of_last_segments(const TreeSkeleton& t, int level) {
  double sum = 0.0;
  int n = 0;
  for (const StemSkeleton& s : t.stems) {
    if (s.level != level || s.sections.size() < 2) continue;
    sum += angle_deg(s.sections.back().position - s.sections[s.sections.size() - 2].position,
                     {0, 0, 1});
    ++n;
  }
  return sum / n;
}

TEST(Generator, AttractionUpLiftsAndNegativeDroops) {
  Parameters p;
  p.leaves = 0;
  p.levels = 3;
  p.level[2].curve_res = 4;
  p.level[2].down_angle = 60.0;
  const double neutral = declination_of_last_segments(generate_skeleton(p, seeded(2)), 2);
  p.attraction_up = 1.0;
  const double up = declination_of_last_segments(generate_skeleton(p, seeded(2)), 2);
  p.attraction_up = -1.0;
  const double down = declination_of_last_segments(generate_skeleton(p, seeded(2)), 2);
  EXPECT_LT(up, neutral - 10.0);
  EXPECT_GT(down, neutral + 10.0);
  EXPECT_LE(down, 180.0);
}

// The envelope test of section 4.6, written out from the paper for the check.
bool inside(const Vec3& v, const Parameters& p) {
  const double r = std::hypot(v.x, v.y);
  const double ratio = (p.scale - v.z) / (p.scale * (1.0 - p.base_size));
  const Envelope e{p.prune_width, p.prune_width_peak, p.prune_power_low, p.prune_power_high};
  return r / p.scale < p.prune_width * shape_ratio(kEnvelope, ratio, e);
}

int points_outside(const Parameters& p) {
  const TreeSkeleton t = generate_skeleton(p, seeded(21));
  int outside = 0;
  for (const StemSkeleton& s : t.stems) {
    if (s.level == 0) continue;  // the trunk is never pruned
    for (std::size_t k = 1; k < s.sections.size(); ++k)
      outside += inside(s.sections[k].position, p) ? 0 : 1;
  }
  return outside;
}

TEST(Generator, PruneRatioOneKeepsEveryStemInsideTheEnvelope) {
  Parameters p;
  p.scale = 12.0;
  p.scale_v = 0.0;
  p.base_size = 0.3;
  p.leaves = 0;
  p.level[1].length = 0.6;
  p.level[1].down_angle = 70.0;
  p.prune_width = 0.35;
  p.prune_width_peak = 0.6;
  p.prune_power_low = 0.5;
  p.prune_power_high = 0.5;
  EXPECT_GT(points_outside(p), 10);  // unpruned, the crown overhangs the envelope
  p.prune_ratio = 1.0;
  EXPECT_EQ(points_outside(p), 0);
}

TEST(Generator, NegativeLeavesMakeAFanAtTheStemEnd) {
  Parameters p;
  p.levels = 2;
  p.leaves = -9;
  p.leaf_distrib = 3;  // cylindrical: every stem gets all nine
  const TreeSkeleton t = generate_skeleton(p, seeded(3));
  int level1 = 0;
  for (const StemSkeleton& s : t.stems) level1 += s.level == 1 ? 1 : 0;
  EXPECT_EQ(t.leaves.size(), static_cast<std::size_t>(9 * level1));
}

TEST(Generator, QualityTradesLeafCountForLeafSize) {
  Parameters p;
  p.levels = 2;
  p.leaves = 40;
  GenerateOptions half = seeded(3);
  half.quality = 0.25;
  const TreeSkeleton full = generate_skeleton(p, seeded(3));
  const TreeSkeleton quarter = generate_skeleton(p, half);
  EXPECT_NEAR(static_cast<double>(quarter.leaves.size()) / static_cast<double>(full.leaves.size()),
              0.25, 0.02);
  EXPECT_NEAR(quarter.leaves[0].length / full.leaves[0].length, 2.0, 1e-9);  // 1 / sqrt(quality)
}

}  // namespace
}  // namespace landsim::trees::weber_penn
