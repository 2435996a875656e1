#include "renderer/materials/ground_shading.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "renderer/materials/bark_texture.h"
#include "renderer/scene.h"

namespace landsim::renderer {
namespace {

const Vec3 kUp{0.0, 0.0, 1.0};
const Vec3 kSun = normalize(Vec3{1.0, 0.0, 1.0});  // from the east, 45 degrees up

Ground grey_ground() {
  Ground g;
  g.albedo = {0.2f, 0.2f, 0.2f};
  g.materials = {{{0.1f, 0.1f, 0.1f}, false},   {{0.02f, 0.03f, 0.04f}, true},
                 {{0.35f, 0.33f, 0.3f}, false}, {{0.2f, 0.15f, 0.1f}, false},
                 {{0.1f, 0.2f, 0.05f}, false},  {{0.1f, 0.2f, 0.05f}, false},
                 {{0.1f, 0.2f, 0.05f}, false},  {{0.2f, 0.2f, 0.2f}, false}};
  return g;
}

TEST(GroundShading, VariationStaysWithinItsBoundAndUsesIt) {
  GroundShading s;
  s.variation.fill(0.2f);
  s.seed = 11;
  float lo = 2.0f, hi = 0.0f;
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 200; ++j) {
      const float f = ground_variation(s, 0, i * 7.3, j * 5.1);
      lo = std::min(lo, f);
      hi = std::max(hi, f);
    }
  EXPECT_GE(lo, 0.8f - 1e-6f);
  EXPECT_LE(hi, 1.2f + 1e-6f);
  EXPECT_GT(hi - lo, 0.25f);  // most of the +-20% is used
  s.variation[0] = 0.0f;
  EXPECT_EQ(ground_variation(s, 0, 123.0, 456.0), 1.0f);
}

TEST(GroundShading, SameSeedSameGroundAnotherSeedAnother) {
  GroundShading a, b, c;
  a.variation.fill(0.2f);
  b = a;
  c = a;
  a.seed = b.seed = 5;
  c.seed = 6;
  int differ = 0;
  for (int i = 0; i < 100; ++i) {
    const double x = i * 37.1, y = i * 11.7;
    EXPECT_EQ(ground_variation(a, 4, x, y), ground_variation(b, 4, x, y));
    differ += ground_variation(a, 4, x, y) != ground_variation(c, 4, x, y);
  }
  EXPECT_GT(differ, 90);
}

TEST(GroundShading, SteepSlopesBecomeRockAndSunFacingSlopesTakeTheirTint) {
  Ground g = grey_ground();
  GroundRule rock;
  rock.measure = TerrainMeasure::slope;
  rock.above = 35.0;
  rock.on = 1u << 0;
  rock.becomes = 3;
  GroundRule dry;
  dry.measure = TerrainMeasure::sun_facing;
  dry.above = 0.2;
  dry.on = 1u << 0;
  dry.tint = {1.2f, 1.1f, 0.9f};
  g.shading.rules = {rock, dry};
  const Vec3 p{100.0, 200.0, 50.0};
  // Flat: the terrain's own albedo, no tint (a flat ground faces no azimuth).
  EXPECT_EQ(shade_ground(g, 0, p, kUp, kSun).albedo, g.albedo);
  // 30 degrees facing west, away from the sun: still terrain, untinted.
  const double s30 = std::sin(30.0 * M_PI / 180.0), c30 = std::cos(30.0 * M_PI / 180.0);
  EXPECT_EQ(shade_ground(g, 0, p, Vec3{-s30, 0.0, c30}, kSun).albedo, g.albedo);
  // 30 degrees facing east: tinted terrain.
  const Vec3f east = shade_ground(g, 0, p, Vec3{s30, 0.0, c30}, kSun).albedo;
  EXPECT_FLOAT_EQ(east.x, 0.2f * 1.2f);
  EXPECT_FLOAT_EQ(east.z, 0.2f * 0.9f);
  // 50 degrees facing west: rock (whose id the tint rule does not name).
  const double s50 = std::sin(50.0 * M_PI / 180.0), c50 = std::cos(50.0 * M_PI / 180.0);
  EXPECT_EQ(shade_ground(g, 0, p, Vec3{-s50, 0.0, c50}, kSun).albedo, g.materials[2].albedo);
  // Water is not named by either rule: unchanged on any slope.
  const ShadedGround water = shade_ground(g, 2, p, Vec3{-s50, 0.0, c50}, kSun);
  EXPECT_TRUE(water.water);
  EXPECT_EQ(water.albedo, g.materials[1].albedo);
}

TEST(GroundShading, SoftBoundsFrayTheEdgeAcrossTheThreshold) {
  Ground g = grey_ground();
  GroundRule rock;
  rock.measure = TerrainMeasure::height;
  rock.above = 100.0;
  rock.softness = 10.0;
  rock.on = 1u << 0;
  rock.becomes = 3;
  g.shading.rules = {rock};
  int rocky_below = 0, bare_above = 0;
  for (int i = 0; i < 400; ++i) {
    const double x = i * 3.7, y = i * 1.3;
    rocky_below += shade_ground(g, 0, {x, y, 95.0}, kUp, kSun).albedo != g.albedo;
    bare_above += shade_ground(g, 0, {x, y, 105.0}, kUp, kSun).albedo == g.albedo;
    // Far from the threshold the rule is certain.
    ASSERT_EQ(shade_ground(g, 0, {x, y, 80.0}, kUp, kSun).albedo, g.albedo);
    ASSERT_NE(shade_ground(g, 0, {x, y, 120.0}, kUp, kSun).albedo, g.albedo);
  }
  EXPECT_GT(rocky_below, 20);
  EXPECT_GT(bare_above, 20);
}

TEST(GroundShading, TexturesAreProjectedWithoutStretchingOnCliffs) {
  Ground g = grey_ground();
  // Stripes 4 texels wide in both directions: a checkerboard of 2 x 2 blocks.
  std::vector<float> rgb;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const float v = ((x / 2) + (y / 2)) % 2 == 0 ? 0.2f : 1.0f;
      rgb.insert(rgb.end(), {v, v, v});
    }
  g.shading.textures[0] = std::make_shared<GroundTexture>(TextureImage(4, 4, rgb));
  g.shading.texture_size = 2.0;
  // Up a vertical cliff facing east the texture still changes every metre of height; a
  // projection from above alone would paint the whole cliff one colour.
  float lo = 10.0f, hi = 0.0f;
  for (int k = 0; k < 16; ++k) {
    const float v =
        shade_ground(g, 0, {10.25, 3.25, k * 0.25 + 0.125}, {1.0, 0.0, 0.0}, kSun).albedo.x;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_GT(hi, 1.5f * lo);
  // Without textures (vertex colours for exports) the material's own albedo.
  EXPECT_EQ(shade_ground(g, 0, {10.25, 3.25, 1.0}, {1.0, 0.0, 0.0}, kSun, false).albedo, g.albedo);
}

}  // namespace
}  // namespace landsim::renderer
