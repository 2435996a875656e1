#include "renderer/materials/grass_patch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "renderer/acceleration/embree_scene.h"
#include "renderer/transport/render.h"
#include "terrain/ground_mesh.h"
#include "tests/renderer/test_scenes.h"

namespace landsim::renderer {
namespace {

terrain::GroundMesh flat_ground(double west, double south, double size) {
  std::vector<float> h(9, 0.0f);
  const double cell = size / 2.0;
  const terrain::ElevationGrid g(
      3, 3, terrain::GeoTransform{west - cell / 2, south + size + cell / 2, cell, cell}, h);
  return terrain::build_ground_mesh(g, Vec3{});
}

// A flat field of grass type 1 over [0, size]^2 in 4 m tiles; the mask's 1 m cells grant
// type 1 except where `road` says.
template <typename Road>
Scene grass_field(int tiles, Road road) {
  Scene s;
  const double size = 4.0 * tiles;
  s.ground.mesh = flat_ground(-10.0, -10.0, size + 20.0);
  GrassCover& g = s.grass;
  g.tile = 4.0;
  g.cols = g.rows = tiles;
  g.type.assign(static_cast<std::size_t>(tiles * tiles), 1);
  g.height.assign(g.type.size(), 0.0f);
  g.normal.assign(g.type.size(), Vec3f{0, 0, 1});
  GrassMask& m = g.mask;
  m.cols = m.rows = static_cast<int>(size);
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols; ++c) m.type.push_back(road(c + 0.5, r + 0.5) ? 0 : 1);
  return s;
}

// docs/DEGRADATION.md "Grass": level 0 has every blade (density x tile area), level k keeps
// 1 / 4^k of them, each 2^k times as wide.
TEST(GrassPatch, LevelsKeepAQuarterOfTheBladesEachTwiceAsWide) {
  const GrassType type;  // 150 blades per square metre, 4 mm wide
  const auto blades_and_width = [&](int level) {
    const GrassBlades b = make_grass_patch(type, 4.0, level, 7);
    double radius = 0.0;
    const std::size_t points = b.points.size() / 4;
    for (std::size_t i = 0; i < points; ++i) radius += b.points[4 * i + 3];
    return std::pair{static_cast<double>(b.first.size()) / kSegmentsPerBlade,
                     2.0 * radius / static_cast<double>(points)};
  };
  const auto [blades0, width0] = blades_and_width(0);
  EXPECT_NEAR(blades0, 150.0 * 16.0, 0.02 * 150.0 * 16.0);
  for (int level = 1; level < kGrassLevels; ++level) {
    const auto [blades, width] = blades_and_width(level);
    EXPECT_NEAR(blades, blades0 / std::pow(4.0, level), 0.05 * blades0 / std::pow(4.0, level))
        << level;
    EXPECT_NEAR(width, width0 * std::pow(2.0, level), 0.05 * width0 * std::pow(2.0, level))
        << level;
  }
}

// Without blending each tile is drawn at the level its calibrated range r2 asks for (at 1000
// pixels and 60 degrees, r2 is the distance): level 0 to 40, 1 to 160, 2 to 640, no blades
// beyond. A strip of 4 m tiles running 1 km from the camera: the tiles per level are the
// bounds' spans over 4 m.
TEST(GrassPatch, EachLevelHoldsTheTilesBetweenItsRangeBounds) {
  const GrassCover cover = testing::grass_strip(250);
  const View view{"v", {0.0, 2.0, 0.0}, {100.0, 2.0, 0.0}, 60.0, 100, 1000};
  std::map<int, int> per_level;
  for_each_grass_patch(cover, view, false, [&](const GrassPatchPlacement& p) {
    const double distance = std::hypot(p.frame[9] - 0.0, p.frame[10] - 2.0);
    const double bounds[] = {0.0, 40.0, 160.0, 640.0};
    ASSERT_GE(p.level, 0);
    EXPECT_GE(distance, bounds[p.level]) << p.level;
    EXPECT_LT(distance, bounds[p.level + 1]) << p.level;
    ++per_level[p.level];
  });
  EXPECT_EQ(per_level[0], 10);   // centres 2, 6, ... 38 m
  EXPECT_EQ(per_level[1], 30);   // 42 ... 158 m
  EXPECT_EQ(per_level[2], 120);  // 162 ... 638 m
  EXPECT_EQ(per_level.size(), 3u);
}

TEST(GrassPatch, TilesTakeEveryVariantTurnAndMirrorImage) {
  std::set<int> variants, turns, mirrors;
  for (std::size_t k = 0; k < 500; ++k) {
    const TileLook look = tile_look(k);
    variants.insert(look.variant);
    turns.insert(look.turns);
    mirrors.insert(look.mirrored);
    // The turned, mirrored frame still stands on the tile: z up, centre kept, axes unit.
    const std::array<float, 12> f = grass_patch_frame({5, 6, 7}, {0, 0, 1}, look);
    EXPECT_FLOAT_EQ(f[8], 1.0f);
    EXPECT_FLOAT_EQ(f[9], 5.0f);
    EXPECT_NEAR(std::hypot(f[0], f[1]), 1.0, 1e-6);
    EXPECT_NEAR(f[0] * f[3] + f[1] * f[4], 0.0, 1e-6);
  }
  EXPECT_EQ(variants.size(), static_cast<std::size_t>(kGrassVariants));
  EXPECT_EQ(turns.size(), 4u);
  EXPECT_EQ(mirrors.size(), 2u);
}

// Rays along the road (north), descending at 20 degrees, aimed at ground points of one
// column x: how many end in grass.
int grass_hits(const EmbreeScene& e, double x) {
  const Vec3 d = normalize(Vec3{0.0, std::cos(0.35), -std::sin(0.35)});
  int hits = 0;
  for (int i = 0; i < 200; ++i) {
    const Vec3 target{x, 10.0 + i * 0.1, 0.0};
    const Ray ray{Vec3f(target - d * 5.0), Vec3f(d)};
    const std::optional<Hit> h = e.intersect(ray, 0.0f, 10.0f);
    hits += h && h->object == ObjectClass::grass;
  }
  return hits;
}

TEST(GrassPatch, NoBladeStandsOnARoadAndFieldEdgesFollowTheMapNotTheTiles) {
  // A road 4 m wide from x = 18 to 22: it halves the tiles 16-20 and 20-24.
  Scene s = grass_field(10, [](double x, double) { return x > 18.0 && x < 22.0; });
  s.grass.types[0].blade_width = 0.01;
  // Near and fine enough that every tile has all its blades (level 0).
  const View view{"v", {20.0, 20.0, 3.0}, {20.0, 25.0, 0.0}, 40.0, 1000, 1000};
  const EmbreeScene e(s, &view);
  for (double x : {19.6, 20.0, 20.4}) EXPECT_EQ(grass_hits(e, x), 0) << x;
  // Only the tiles the road cuts need the blade filter.
  const auto flat = [](float x) { return grass_patch_frame({x, 6.0f, 0.0f}, {0, 0, 1}); };
  EXPECT_TRUE(grass_tile_whole(s.grass.mask, flat(14.0f), 4.0, 1));   // 12-16 m
  EXPECT_FALSE(grass_tile_whole(s.grass.mask, flat(18.0f), 4.0, 1));  // 16-20 m
  EXPECT_FALSE(grass_tile_whole(s.grass.mask, flat(22.0f), 4.0, 1));  // 20-24 m
  EXPECT_FALSE(grass_tile_whole(s.grass.mask, flat(14.0f), 4.0, 2));  // another type
  // The grass half of the tile the road halves keeps its blades, as the open field does.
  EXPECT_GT(grass_hits(e, 17.0), 100);
  EXPECT_GT(grass_hits(e, 10.0), 100);
  // Without a mask the same rays over the road would meet blades.
  s.grass.mask = {};
  const EmbreeScene unmasked(s, &view);
  EXPECT_GT(grass_hits(unmasked, 20.0), 100);
}

TEST(GrassPatch, KeptBladesAreTheOnesTheRendererKeeps) {
  const Scene s = grass_field(2, [](double x, double) { return x > 4.0; });
  const GrassBlades patch = make_grass_patch(s.grass.types[0], 4.0, 0, grass_patch_seed(0, 1));
  // The tile from x = 2 to 6 is half road: about half its blades remain, none past x = 4.
  const std::array<float, 12> frame = grass_patch_frame({4.0f, 2.0f, 0.0f}, {0, 0, 1});
  const GrassBlades kept = kept_blades(patch, frame, s.grass.mask, 1);
  EXPECT_GT(kept.first.size(), patch.first.size() / 3);
  EXPECT_LT(kept.first.size(), 2 * patch.first.size() / 3);
  for (std::size_t p = 0; p < kept.points.size(); p += 4 * (kSegmentsPerBlade + 1))
    EXPECT_LT(kept.points[p] + 4.0f, 4.0f + 1e-4f);  // roots west of the road
}

TEST(GrassPatch, AWholeTileLosesNoBladeToTheMaskEvenTilted) {
  // Grass west of x = 16, the tile 12-16 m against the edge: tilted frames lean its roots
  // past 16 m, so it is whole only when no root crosses.
  const Scene s = grass_field(8, [](double x, double) { return x > 16.0; });
  const GrassBlades patch = make_grass_patch(s.grass.types[0], 4.0, 0, grass_patch_seed(0, 2));
  int whole = 0, cut = 0;
  for (int k = 0; k < 200; ++k) {
    const float tilt = 0.01f * static_cast<float>(k % 40), turn = 0.37f * static_cast<float>(k);
    const Vec3f normal{tilt * std::cos(turn), tilt * std::sin(turn), 1.0f};
    const std::array<float, 12> frame =
        grass_patch_frame({14.0f, 6.0f, 0.0f}, normal, tile_look(static_cast<std::size_t>(k)));
    const bool keeps_all =
        kept_blades(patch, frame, s.grass.mask, 1).first.size() == patch.first.size();
    if (grass_tile_whole(s.grass.mask, frame, 4.0, 1)) {
      ASSERT_TRUE(keeps_all) << k;  // the renderer would draw this tile unfiltered
      ++whole;
    } else {
      ++cut;
    }
  }
  EXPECT_GT(whole, 0);  // the flat and slightly tilted ones
  EXPECT_GT(cut, 0);    // the ones leaning past the edge
}

// Normalised autocorrelation of a film's luminance along x at lag `lag`.
double autocorrelation(const Film& film, int lag) {
  double mean = 0.0;
  const int w = film.width(), h = film.height();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) mean += film.luminance(x, y);
  mean /= w * h;
  double num = 0.0, den = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x + lag < w; ++x) {
      num += (film.luminance(x, y) - mean) * (film.luminance(x + lag, y) - mean);
      den += (film.luminance(x, y) - mean) * (film.luminance(x, y) - mean);
    }
  return num / den;
}

TEST(GrassPatch, AGrassFieldSeenFromAboveHasNoPeriodAtTheTile) {
  Scene s = grass_field(24, [](double, double) { return false; });
  s.grass.types[0].density_per_m2 = 60.0;
  s.grass.types[0].blade_width = 0.02;
  s.grass.types[0].curvature = 0.8;
  s.sun.direction = normalize(Vec3{0.3, 0.2, 1.0});
  s.settings.spp = 1;
  // Straight down over the middle of the field: 48 m across 192 pixels, a tile every 16.
  View view{"top", {48.0, 48.0, 100.0}, {48.0, 48.0001, 0.0}, 0.0, 192, 192};
  view.fov_y_deg = 2.0 * std::atan(24.0 / 100.0) * 180.0 / M_PI;
  const Film film = Renderer(s).render(view, {});
  const double at_tile = autocorrelation(film, 16);
  double around = 0.0;
  for (int lag : {12, 13, 14, 18, 19, 20}) around += autocorrelation(film, lag) / 6.0;
  // A repeated patch makes the tile's lag stand out; varied, turned patches do not.
  EXPECT_LT(at_tile - around, 0.03) << at_tile << " vs " << around;
}

}  // namespace
}  // namespace landsim::renderer
