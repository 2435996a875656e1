// Range degradation inside the renderer: levels chosen per instance, blended per pixel.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "renderer/acceleration/embree_scene.h"
#include "renderer/acceleration/stochastic_lod.h"
#include "renderer/camera.h"
#include "renderer/materials/grass_patch.h"
#include "renderer/transport/render.h"
#include "tests/renderer/film_stats.h"
#include "tests/renderer/test_scenes.h"
#include "tests/renderer/thread_counts.h"
#include "trees/species.h"

namespace landsim::renderer {
namespace {

// A quaking aspen (the paper's Table 2 tree) alone under the sky.
const TreePrototype& aspen() {
  static const TreePrototype p = [] {
    TreePrototype t;
    const trees::Species species =
        trees::load_species(std::string(LANDSIM_SOURCE_DIR) + "/data/species/quaking_aspen.toml");
    t.geometry = trees::generate(species, {}).geometry;
    t.bark_albedo = {0.3f, 0.25f, 0.2f};
    t.leaf_reflectance = {0.1f, 0.2f, 0.05f};
    t.leaf_transmittance = {0.05f, 0.1f, 0.02f};
    t.degradation = trees::degradation_factors(1.0, trees::Season::summer, false);
    return t;
  }();
  return p;
}

Scene aspen_scene() {
  Scene s;
  s.prototypes.push_back(aspen());
  s.instances.push_back({0, {0.0, 0.0, 0.0}, 0.3, 1.0});
  s.sun.direction = normalize(Vec3{-0.5, -0.6, 0.8});
  s.settings.max_bounces = 1;
  return s;
}

// A close view framing the tree (about 14 m tall) whose degradation is that of calibrated
// range r2: the drawn geometry is measured finely whatever range it stands for.
// At 128 pixels the tree is about 105 pixels tall (drawn at one level per tree); at 256,
// 210 (blended pixel by pixel).
View framing_view(double r2, int pixels = 128) {
  View v{"v", {-30.0, -12.0, 7.0}, {0.0, 0.0, 7.0}, 35.0, pixels, pixels};
  const double at = trees::calibrated_range(length(v.target - v.position), v.height, v.fov_y_deg);
  v.detail_range_scale = r2 / at;
  return v;
}

// The fraction of the frame the tree covers: 4 x 4 rays per pixel, each with its pixel's
// mask, as the renderer traces them.
double coverage(const EmbreeScene& embree, const View& view) {
  const Camera camera(view);
  int hits = 0;
  for (int y = 0; y < view.height; ++y)
    for (int x = 0; x < view.width; ++x) {
      const std::uint32_t mask = pixel_ray_mask(static_cast<std::uint64_t>(y) * view.width +
                                                static_cast<std::uint64_t>(x));
      for (int k = 0; k < 16; ++k) {
        const float dx = 0.125f + 0.25f * static_cast<float>(k % 4);
        const float dy = 0.125f + 0.25f * static_cast<float>(k / 4);
        const Ray ray = *camera.ray(static_cast<float>(x) + dx, static_cast<float>(y) + dy);
        hits += embree.intersect(ray, 0.0f, 1e30f, mask).has_value();
      }
    }
  return hits / (16.0 * view.width * view.height);
}

TEST(DegradationRender, CoverageHasNoJumpBetweenRangesOnePercentApart) {
  const Scene s = aspen_scene();
  double full = 0.0;
  {
    Scene off = s;
    off.settings.degradation = false;
    const View v = framing_view(1.0);
    full = coverage(EmbreeScene(off, &v), v);
  }
  ASSERT_GT(full, 0.05);
  // Around every threshold of section 5 for summer (s = 0.5, d = 200) and between them.
  for (double r2 : {20.0, 25.0, 40.0, 50.0, 75.0, 100.0, 150.0, 200.0, 250.0, 300.0, 400.0, 500.0,
                    600.0, 700.0, 800.0, 1000.0, 1500.0, 2000.0}) {
    const View a = framing_view(r2 / 1.005), b = framing_view(r2 * 1.005);
    const double ca = coverage(EmbreeScene(s, &a), a), cb = coverage(EmbreeScene(s, &b), b);
    EXPECT_LT(std::abs(cb - ca) / full, 0.01) << "r2 " << r2 << ": " << ca << " -> " << cb;
    // Widened far primitives keep the tree's area (measured: within 1% at every range;
    // without widening a quarter of the leaves would remain past r2 = 600).
    EXPECT_GT(ca, 0.95 * full) << r2;
  }
}

// A distant view at 1080p's pixel size (40 degrees over 1080 pixels), cropped to the tree.
View distant_view(double range) {
  return View{"v", {-range, 0.0, 7.0}, {0.0, 0.0, 7.0}, 40.0 * 96.0 / 1080.0, 96, 96};
}

using test::mean_luminance;

TEST(DegradationRender, ATreeAt600mLooksAsAtFullDetail) {
  Scene s = aspen_scene();
  s.settings.spp = 16;
  const View v = distant_view(600.0);
  const Film degraded = Renderer(s).render(v, {});
  s.settings.degradation = false;
  const Film full = Renderer(s).render(v, {});
  double diff = 0.0, tree_pixels = 0.0;
  int drawn_below_full = 0;
  for (int y = 0; y < v.height; ++y)
    for (int x = 0; x < v.width; ++x) {
      diff += std::abs(degraded.luminance(x, y) - full.luminance(x, y));
      tree_pixels += full.object(x, y) >= 2;
      drawn_below_full += degraded.level(x, y) > 0;
    }
  ASSERT_GT(tree_pixels, 50.0);
  EXPECT_GT(drawn_below_full, 50);  // it was degraded (lod layer)
  // The bound docs/DEGRADATION.md states: the mean absolute difference over the crop is
  // under 2% of its mean pixel value (measured: 0.43%).
  const double mean = mean_luminance(full);
  EXPECT_LT(diff / static_cast<double>(full.pixel_count()) / mean, 0.02);
}

TEST(DegradationRender, TheBlendIsTheSameInEveryRunAndThreadCount) {
  Scene s = aspen_scene();
  s.settings.spp = 2;
  // Half way between two anchor steps (octaves where leaves are discs only), so pixels
  // dither between two levels.
  const View v = framing_view(0.5 * (step_r2(19) + step_r2(21)), 256);
  const auto [a, b] = test::render_on_one_and_two_threads(Renderer(s), v);
  int lower = 0, upper = 0;
  for (int y = 0; y < v.height; ++y)
    for (int x = 0; x < v.width; ++x) {
      ASSERT_EQ(a.rgb(x, y).x, b.rgb(x, y).x);
      ASSERT_EQ(a.level(x, y), b.level(x, y));
      lower += a.level(x, y) == 19;
      upper += a.level(x, y) == 21;
    }
  EXPECT_GT(lower, 100);
  EXPECT_GT(upper, 100);
  EXPECT_NEAR(static_cast<double>(upper) / (lower + upper), 0.5, 0.15);
}

TEST(DegradationRender, SmallTreesTakeOneLevelEachInProportion) {
  // 100 trees about 7 pixels tall on an arc 700 m around the camera, all half way between
  // two anchors (octaves 19 and 21).
  Scene s = aspen_scene();
  s.instances.clear();
  for (int k = 0; k < 100; ++k) {
    const double a = (k - 49.5) / 49.5 * 30.0 * std::numbers::pi / 180.0;
    s.instances.push_back({0, {700.0 * std::cos(a), 700.0 * std::sin(a), -1.5}, 0.0, 1.0});
  }
  View v{"v", {0.0, 0.0, 7.0}, {700.0, 0.0, 7.0}, 70.0, 400, 400};
  const double at = trees::calibrated_range(700.0, v.height, v.fov_y_deg);
  v.detail_range_scale = 0.5 * (step_r2(19) + step_r2(21)) / at;
  const EmbreeScene embree(s, &v);
  const Camera camera(v);
  std::map<std::int32_t, std::set<int>> levels;  // per tree, the levels its pixels show
  for (int y = 0; y < v.height; ++y)
    for (int x = 0; x < v.width; ++x) {
      const auto hit = embree.intersect(
          *camera.ray(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f), 0.0f, 1e30f,
          pixel_ray_mask(static_cast<std::uint64_t>(y * v.width + x)));
      if (hit && hit->instance >= 0) levels[hit->instance].insert(hit->level);
    }
  ASSERT_GT(levels.size(), 80u);
  int upper = 0;
  for (const auto& [tree, seen] : levels) {
    EXPECT_EQ(seen.size(), 1u) << "tree " << tree;  // one level for all its pixels
    upper += *seen.begin() == 21;
    EXPECT_TRUE(*seen.begin() == 19 || *seen.begin() == 21);
  }
  // Half of them at the upper level, within 4 standard deviations.
  const double n = static_cast<double>(levels.size());
  EXPECT_NEAR(upper / n, 0.5, 4.0 * std::sqrt(0.25 / n));
}

TEST(DegradationRender, WithoutDegradationEveryTreeIsDrawnInFull) {
  Scene s = aspen_scene();
  s.settings.spp = 1;
  s.settings.degradation = false;
  const View v = distant_view(600.0);
  const Film f = Renderer(s).render(v, {});
  int trees = 0;
  for (int y = 0; y < v.height; ++y)
    for (int x = 0; x < v.width; ++x) {
      trees += f.object(x, y) >= 2;
      EXPECT_EQ(f.level(x, y), 0u);
    }
  EXPECT_GT(trees, 50);
}

TEST(StochasticLod, MasksSplitRaysInTheWeightsProportion) {
  for (double w : {0.0, 0.1, 0.25, 0.5, 0.77, 1.0}) {
    for (std::uint64_t key : {0ull, 7ull, 123456789ull}) {
      const LevelMasks m = level_masks(w, key);
      EXPECT_EQ(m.lower & m.upper, 0u);
      EXPECT_EQ(m.lower | m.upper, kAllBuckets);
      EXPECT_EQ(std::popcount(m.upper), std::lround(w * kMaskBuckets));
      const LevelMasks again = level_masks(w, key);
      EXPECT_EQ(again.upper, m.upper);
    }
  }
  // Objects are decorrelated: the same weight picks different buckets for different keys.
  EXPECT_NE(level_masks(0.5, 1).upper, level_masks(0.5, 2).upper);
  // Every pixel's mask is a single bucket.
  for (std::uint64_t p = 0; p < 100; ++p) EXPECT_EQ(std::popcount(pixel_ray_mask(p)), 1);
}

TEST(StochasticLod, LadderPositionsInterpolateBetweenSteps) {
  EXPECT_EQ(ladder_position(0.0).step, 0);
  EXPECT_DOUBLE_EQ(step_r2(1), 1.0);
  EXPECT_DOUBLE_EQ(step_r2(3), 2.0);
  const LadderPosition p = ladder_position(1.2 * step_r2(20));  // steps are sqrt 2 apart
  EXPECT_EQ(p.step, 20);
  EXPECT_NEAR(p.weight, 0.2 / (std::sqrt(2.0) - 1.0), 1e-9);
  EXPECT_EQ(ladder_position(1e9).step, kDetailSteps - 1);
  EXPECT_EQ(ladder_position(1e9).weight, 0.0);
}

// Calibrated range r2 at 1000 pixels and 60 degrees is the distance itself.
GrassBlend blend_at(double r2) { return grass_blend(r2); }

TEST(GrassBlend, LevelsBlendAroundEachLevelsEndAndFadeAfterTheLast) {
  EXPECT_EQ(blend_at(10.0).lower, 0);
  EXPECT_EQ(blend_at(10.0).upper_weight, 0.0);
  // Half way at each end (40, 160, 640), none of the next level a factor sqrt 2 before it.
  for (int level = 0; level < kGrassLevels; ++level) {
    const double end = 40.0 * std::pow(4.0, level);
    const GrassBlend mid = blend_at(end);
    EXPECT_EQ(mid.lower, level);
    EXPECT_EQ(mid.upper, level + 1 < kGrassLevels ? level + 1 : -1);
    EXPECT_NEAR(mid.upper_weight, 0.5, 1e-9);
    EXPECT_NEAR(blend_at(end / std::sqrt(2.0) * 1.0001).upper_weight, 0.0, 1e-3);
    EXPECT_NEAR(blend_at(end * std::sqrt(2.0) * 0.9999).upper_weight, 1.0, 1e-3);
  }
  EXPECT_EQ(blend_at(2000.0).lower, -1);  // past the last level: no blades
  // The weight grows continuously with range: no jump between ranges 1% apart.
  double previous = 0.0;
  for (double r2 = 29.0; r2 < 56.0; r2 *= 1.01) {
    const double w = blend_at(r2).upper_weight;
    EXPECT_LT(std::abs(w - previous), 0.05) << r2;
    previous = w;
  }
}

TEST(GrassBlend, BlendedTilesGetTwoPatchesWithComplementaryMasks) {
  const GrassCover cover = testing::grass_strip(40);
  const View view{"v", {-2.0, 2.0, 1.5}, {100.0, 2.0, 0.0}, 60.0, 100, 1000};
  std::map<std::pair<float, float>, std::uint32_t> masks;  // per tile centre: OR of masks
  int tiles_twice = 0;
  std::map<std::pair<float, float>, int> count;
  for_each_grass_patch(cover, view, true, [&](const GrassPatchPlacement& p) {
    const std::pair<float, float> at{p.frame[9], p.frame[10]};
    EXPECT_EQ(masks[at] & p.mask, 0u);  // no bucket sees two levels
    masks[at] |= p.mask;
    tiles_twice += ++count[at] == 2;
  });
  EXPECT_GT(tiles_twice, 3);
  // Within 160 m every tile is drawn for every ray, at one level or the other.
  for (const auto& [at, m] : masks) EXPECT_EQ(m, kAllBuckets) << at.first;
  // Without blending: one patch per tile, seen by every ray.
  for_each_grass_patch(cover, view, false,
                       [&](const GrassPatchPlacement& p) { EXPECT_EQ(p.mask, kAllBuckets); });
}

}  // namespace
}  // namespace landsim::renderer
