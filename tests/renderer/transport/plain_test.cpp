// The plain beyond the grid (renderer/transport/plain.h): a surface at a finite distance, shaded,
// shadowed and hazed like the ground it continues, and closing nodata holes.
#include "renderer/transport/plain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "renderer/spectra/colour_matching.h"
#include "renderer/transport/render.h"
#include "tests/renderer/test_scenes.h"

namespace landsim::renderer {
namespace {

using testing::flat_ground;

constexpr double kDeg = std::numbers::pi / 180.0;

// A plain at 5 m around a 100 m square footprint centred on the origin.
PlainSurface square_plain() {
  PlainSurface p;
  p.present = true;
  p.height = 5.0f;
  p.min_x = p.min_y = -50.0f;
  p.max_x = p.max_y = 50.0f;
  return p;
}

TEST(Plain, ARayComingDownMeetsItAtItsHeight) {
  const PlainSurface p = square_plain();
  const Vec3f d = normalize(Vec3f{1.0f, 0.0f, -0.1f});
  const auto hit = plain_hit(p, {{0.0f, 0.0f, 25.0f}, d});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(25.0f + hit->t * d.z, 5.0f, 1e-4f);  // 200 m out, beyond the footprint
  EXPECT_EQ(hit->normal.z, 1.0f);
  // Upward and level rays above it leave into the sky.
  EXPECT_FALSE(plain_hit(p, {{0.0f, 0.0f, 25.0f}, Vec3f{1.0f, 0.0f, 0.0f}}).has_value());
  EXPECT_FALSE(plain_hit(p, {{0.0f, 0.0f, 25.0f}, normalize(Vec3f{0, 1, 1})}).has_value());
}

TEST(Plain, ALowRayLeavingTheFootprintMeetsItsSkirt) {
  // From a valley 3 m below the rim, level toward the east: the skirt at x = 50, facing west.
  const PlainSurface p = square_plain();
  const auto level = plain_hit(p, {{10.0f, 0.0f, 2.0f}, Vec3f{1.0f, 0.0f, 0.0f}});
  ASSERT_TRUE(level.has_value());
  EXPECT_NEAR(level->t, 40.0f, 1e-4f);
  EXPECT_EQ(level->normal.x, -1.0f);
  // Rising 10 m over those 40 m it clears the rim: the sky.
  EXPECT_FALSE(plain_hit(p, {{10.0f, 0.0f, 2.0f}, normalize(Vec3f{4, 0, 1})}).has_value());
  // Outside the footprint and below the rim: in the plain already.
  const auto inside = plain_hit(p, {{80.0f, 0.0f, 2.0f}, normalize(Vec3f{0, 1, 1})});
  ASSERT_TRUE(inside.has_value());
  EXPECT_EQ(inside->t, 0.0f);
}

TEST(Plain, ADownwardRayOverTheFootprintMeetsALidOverAHole) {
  const PlainSurface p = square_plain();
  const auto hit = plain_hit(p, {{0.0f, 0.0f, 105.0f}, Vec3f{0.0f, 0.0f, -1.0f}});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->t, 100.0f, 1e-4f);
}

TEST(Plain, ItsHeightIsTheMeanOfTheMeshsRimUnlessTheSceneSaysOtherwise) {
  // Heights 0 to 80 m rising eastward over a 5 x 5 grid: the rim's mean is the middle row's
  // plus the two outer columns', (16 x 40) / 16 = 40; the centre cells do not count.
  std::vector<float> h;
  for (int r = 0; r < 5; ++r)
    for (int c = 0; c < 5; ++c)
      h.push_back(static_cast<float>(20 * c) + (r == 2 && c == 2 ? 500.0f : 0.0f));
  const terrain::ElevationGrid g(5, 5, terrain::GeoTransform{0.0, 50.0, 10.0, 10.0}, h);
  Ground ground;
  ground.mesh = terrain::build_ground_mesh(g, Vec3{});
  const PlainSurface p = plain_surface(ground);
  EXPECT_TRUE(p.present);
  EXPECT_NEAR(p.height, 40.0f, 1e-4f);
  // The footprint is the raster's extent: the outer cells are drawn to their edges.
  EXPECT_NEAR(p.min_x, 0.0f, 1e-4f);
  EXPECT_NEAR(p.max_x, 50.0f, 1e-4f);
  ground.plain_height = 12.0f;
  EXPECT_EQ(plain_surface(ground).height, 12.0f);
  EXPECT_FALSE(plain_surface(Ground{}).present);
}

double mean_luminance(const Film& film) {
  double sum = 0.0;
  const auto& rgb = film.rgb_data();
  for (std::size_t i = 0; i < film.pixel_count(); ++i)
    sum += rec709_luminance(Vec3{rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]});
  return sum / static_cast<double>(film.pixel_count());
}

// Flat ground of one albedo under a sun 35 degrees up in the south, 5 km visibility haze.
Scene hazy_ground(double half) {
  Scene s;
  s.ground.mesh = flat_ground(half, 0.0f);
  s.ground.albedo = {0.2f, 0.2f, 0.15f};
  s.ground.edge_albedo = s.ground.albedo;
  s.sun.direction = {0.0, -std::cos(35.0 * kDeg), std::sin(35.0 * kDeg)};
  s.haze.enabled = true;
  s.haze.visibility = 5000.0;
  s.settings.spp = 64;
  return s;
}

// A patch of the plain 430 m away (the starter scenario's case) reads as ground there would,
// not as the haze of an endless path: before, 3.9 times brighter with haze than without.
TEST(Plain, BeyondTheGridItIsHazedAsGroundAtItsDistance) {
  const View v{"v", {0.0, 0.0, 10.0}, {430.0, 0.0, 0.0}, 1.0, 8, 8};
  const double plain = mean_luminance(Renderer(hazy_ground(50.0)).render(v, {}));
  const double ground = mean_luminance(Renderer(hazy_ground(2000.0)).render(v, {}));
  RecordProperty("plain_cd_m2", std::to_string(plain));
  RecordProperty("ground_cd_m2", std::to_string(ground));
  EXPECT_NEAR(plain / ground, 1.0, 0.03) << plain << " against " << ground;
}

// A nodata hole seen from above: the plain's lid, at the ground's brightness (before: the
// hazed sky's, 2.3 times brighter in the near-nadir view).
TEST(Plain, ANodataHoleShowsThePlainNotTheSky) {
  std::vector<float> h(41 * 41, 0.0f);
  for (int r = 15; r < 26; ++r)
    for (int c = 15; c < 26; ++c) h[static_cast<std::size_t>(r * 41 + c)] = std::nanf("");
  const terrain::ElevationGrid g(41, 41, terrain::GeoTransform{-205.0, 205.0, 10.0, 10.0}, h);
  Scene holed = hazy_ground(200.0);
  holed.ground.mesh = terrain::build_ground_mesh(g, Vec3{});
  const Scene whole = hazy_ground(200.0);
  // Straight into the hole's middle from 1.5 km, 5 degrees off the vertical.
  const View v{"v", {130.0, 0.0, 1500.0}, {0.0, 0.0, 0.0}, 2.0, 8, 8};
  const double hole = mean_luminance(Renderer(holed).render(v, {}));
  const double ground = mean_luminance(Renderer(whole).render(v, {}));
  RecordProperty("hole_cd_m2", std::to_string(hole));
  RecordProperty("ground_cd_m2", std::to_string(ground));
  EXPECT_NEAR(hole / ground, 1.0, 0.03) << hole << " against " << ground;
}

// A wall at the grid's edge shadows the plain beyond it as it would shadow ground there.
TEST(Plain, ItIsShadowedByTheTerrain) {
  const auto with_wall = [](Scene s) {
    // A wall 40 m high along y = 45, x in [-40, 40]: under the sun in the south its shadow
    // lies north of it, over y in [45, 102], mostly beyond the small grid's edge at y = 50.
    terrain::GroundMesh& m = s.ground.mesh;
    const auto base = static_cast<std::uint32_t>(m.vertices.size());
    m.vertices.insert(m.vertices.end(), {{-40.0f, 45.0f, 0.0f},
                                         {40.0f, 45.0f, 0.0f},
                                         {40.0f, 45.0f, 40.0f},
                                         {-40.0f, 45.0f, 40.0f}});
    m.normals.insert(m.normals.end(), 4, Vec3f{0.0f, -1.0f, 0.0f});
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    return s;
  };
  const Scene small = with_wall(hazy_ground(50.0));
  const Scene large = with_wall(hazy_ground(2000.0));
  // Looking down from the north-east at the shadow (x 0, y 80) and at lit ground (x 0, y 130).
  for (const double y : {80.0, 130.0}) {
    const View v{"v", {150.0, 250.0, 120.0}, {0.0, y, 0.0}, 1.0, 8, 8};
    const double plain = mean_luminance(Renderer(small).render(v, {}));
    const double ground = mean_luminance(Renderer(large).render(v, {}));
    EXPECT_NEAR(plain / ground, 1.0, 0.04) << "y " << y << ": " << plain << " against " << ground;
  }
}

}  // namespace
}  // namespace landsim::renderer
