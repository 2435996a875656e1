// Physical checks of the renderer: white furnace, haze against its analytic transmittance,
// a sun shadow where geometry puts it, linearity in sun irradiance, AOV consistency, and
// checkpoint / resume.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "core/counter_rng.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/atmosphere/medium.h"
#include "renderer/output/image_output.h"
#include "renderer/transport/render.h"
#include "terrain/ground_mesh.h"
#include "tests/renderer/film_stats.h"
#include "tests/renderer/test_scenes.h"
#include "tests/support/single_item.h"
#include "tests/support/temp_dir.h"

namespace landsim::renderer {
namespace {

using testing::flat_ground;

Sky uniform_sky(float l) {
  Sky s;
  s.model = SkyKind::gradient;
  s.zenith_radiance = s.horizon_radiance = {l, l, l};
  return s;
}

using test::mean_luminance;

TEST(Physics, WhiteFurnace) {
  // Albedo 1 under a uniform sky of radiance L, no sun: every surface returns L.
  Scene s;
  s.ground.mesh = flat_ground(1e4);
  s.ground.albedo = {1.0f, 1.0f, 1.0f};
  s.sky = uniform_sky(0.5f);
  s.sun.irradiance = {0.0f, 0.0f, 0.0f};
  s.settings.spp = 64;
  s.settings.max_bounces = 64;
  const View down{"v", {0.0, 0.0, 10.0}, {5.0, 0.0, 0.0}, 40.0, 24, 24};
  const Film film = Renderer(s).render(down, {});
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) ASSERT_EQ(film.object(x, y), 1);  // all ground
  EXPECT_NEAR(mean_luminance(film), 0.5, 0.5 * 0.02);
}

// The haze's aerosol alone (no air, grey), bin 8 (550 nm): its extinction and the closed
// forms the medium draws and dims with.
Haze grey_aerosol(double visibility) {
  Haze h;
  h.enabled = true;
  h.visibility = visibility;
  h.molecular = false;
  h.angstrom = 0.0;
  return h;
}

TEST(Physics, HazeTransmittanceMatchesTheAnalyticFormula) {
  Haze h = grey_aerosol(5000.0);
  h.scale_height = 800.0;
  h.base_height = 100.0;
  const Medium haze(h);
  constexpr int k = 8;
  const auto sigma = [&](double z) { return haze.extinction(z, k, true); };
  const auto depth = [&](const Vec3& o, const Vec3& d, double t) {
    return haze.optical_depth(haze.unit_depths(o, d, t, true), k);
  };
  EXPECT_NEAR(sigma(100.0), 3.912 / 5000.0, 1e-12);  // Koschmieder at the base
  for (const Vec3& d :
       {normalize(Vec3{1.0, 0.0, 0.2}), normalize(Vec3{0.3, 1.0, -0.1}), Vec3{1.0, 0.0, 0.0}}) {
    const Vec3 o{0.0, 0.0, 400.0};
    const double t = 3000.0;
    double tau = 0.0;  // midpoint rule over the exponential density
    const int n = 100000;
    for (int i = 0; i < n; ++i) tau += sigma(o.z + d.z * (i + 0.5) * t / n) * t / n;
    EXPECT_NEAR(depth(o, d, t), tau, 1e-6 * tau);
    EXPECT_NEAR(haze.transmittance(o, d, t, true)[k], std::exp(-tau), 1e-6);
  }
  // Straight up to infinity: sigma(z0) x H.
  EXPECT_NEAR(depth({0, 0, 100.0}, {0, 0, 1}, kInfiniteDistance), 3.912 / 5000.0 * 800.0, 1e-9);
  EXPECT_EQ(
      haze.transmittance({0, 0, 100.0}, normalize(Vec3{1, 0, -0.01}), kInfiniteDistance, true)[k],
      0.0f);
}

TEST(Physics, HazeDistancesFollowExtinctionTimesTransmittance) {
  const Medium haze(grey_aerosol(2000.0));
  constexpr int k = 8;
  const auto depth = [&](const Vec3& o, const Vec3& d, double t) {
    return haze.optical_depth(haze.unit_depths(o, d, t, true), k);
  };
  const Vec3 o{0, 0, 50}, d = normalize(Vec3{1, 0, 0.05});
  const double t = 4000.0, s_mid = 1000.0;
  const double expected = -std::expm1(-depth(o, d, s_mid)) / -std::expm1(-depth(o, d, t));
  int below = 0;
  const int n = 100000;
  const double scattered = -std::expm1(-depth(o, d, t));
  for (int i = 0; i < n; ++i) {
    // The optical depth at which to stop, uniform in 1 - exp(-tau) over the segment.
    const double tau = -std::log1p(-CounterRng(1, i, 0).uniform(0) * scattered);
    below += haze.distance_at(o, d, t, true, k, tau) < s_mid;
  }
  EXPECT_NEAR(below / static_cast<double>(n), expected, 0.005);
}

TEST(Physics, SunShadowFallsWhereGeometryPutsIt) {
  // A 2 m wide, 4 m tall panel standing at the origin in the plane x = 0; sun from the
  // west (-x) at 45 degrees: the shadow covers x in [0, 4] behind it, y in [-1, 1].
  Scene s;
  s.ground.mesh = flat_ground(200.0);
  s.ground.albedo = {0.5f, 0.5f, 0.5f};
  s.sky = uniform_sky(0.0f);
  s.sun.direction = normalize(Vec3{-1.0, 0.0, 1.0});
  s.sun.angular_radius = 1e-4;
  s.settings.spp = 4;
  s.settings.max_bounces = 0;
  TreePrototype panel;
  trees::TriangleSet& t = panel.geometry.group(trees::Group::trunk).triangles;
  t.vertices = {{0, -1, 0}, {0, 1, 0}, {0, 1, 4}, {0, -1, 4}};
  t.normals.assign(4, Vec3f{1, 0, 0});
  t.indices = {0, 1, 2, 0, 2, 3};
  test::make_single_item(panel.geometry.group(trees::Group::trunk));
  s.prototypes.push_back(panel);
  s.instances.push_back({0, {}, 0.0, 1.0});
  // Straight down from 30 m over (2, 0), 20 m of ground in view.
  const View down{"v",
                  {2.0, 0.0, 30.0},
                  {2.0, 0.001, 0.0},
                  2.0 * std::atan(10.0 / 30.0) * 180.0 / std::numbers::pi,
                  80,
                  80};
  const Film film = Renderer(s).render(down, {});
  const Camera cam(down);
  int checked_in = 0, checked_out = 0;
  for (int y = 0; y < 80; ++y) {
    for (int x = 0; x < 80; ++x) {
      if (film.object(x, y) != 1) continue;
      const Ray r = *cam.ray(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
      const Vec3f p = r.origin + r.direction * film.depth(x, y);
      const bool in_shadow = p.x > 0.3f && p.x < 3.7f && std::abs(p.y) < 0.7f;
      const bool clearly_lit = p.x < -0.3f || p.x > 4.3f || std::abs(p.y) > 1.3f;
      if (in_shadow) {
        EXPECT_LT(film.luminance(x, y), 0.01f) << p.x << " " << p.y;
        ++checked_in;
      } else if (clearly_lit) {
        EXPECT_GT(film.luminance(x, y), 0.1f) << p.x << " " << p.y;
        ++checked_out;
      }
    }
  }
  EXPECT_GT(checked_in, 20);
  EXPECT_GT(checked_out, 200);
}

Scene lit_ridge() {
  Scene s;
  std::vector<float> h;
  for (int r = 0; r < 21; ++r)
    for (int c = 0; c < 21; ++c)
      h.push_back(static_cast<float>(30.0 - 0.5 * std::abs(c - 10.0) * 5.0));
  s.ground.mesh = terrain::build_ground_mesh(
      terrain::ElevationGrid(21, 21, terrain::GeoTransform{0, 105, 5, 5}, h), Vec3{});
  s.sky = uniform_sky(0.0f);
  s.sun.direction = normalize(Vec3{0.5, 0.2, 0.8});
  s.settings.spp = 2;
  s.settings.max_bounces = 3;
  return s;
}

TEST(Physics, BrightnessIsLinearInSunIrradiance) {
  Scene a = lit_ridge();
  Scene b = lit_ridge();
  b.sun.irradiance = a.sun.irradiance * 2.0f;
  const View v{"v", {52.0, -60.0, 80.0}, {52.0, 50.0, 10.0}, 45.0, 32, 24};
  const Film fa = Renderer(a).render(v, {});
  const Film fb = Renderer(b).render(v, {});
  double sa = 0.0, sb = 0.0;
  for (std::size_t i = 0; i < fa.rgb_data().size(); ++i) {
    sa += fa.rgb_data()[i];
    sb += fb.rgb_data()[i];
    ASSERT_NEAR(fb.rgb_data()[i], 2.0f * fa.rgb_data()[i], 1e-5f * (1.0f + fb.rgb_data()[i]));
  }
  EXPECT_GT(sa, 1.0);
  EXPECT_NEAR(sb / sa, 2.0, 1e-5);
}

TEST(Physics, WaterMirrorsTheSkyWithSchlicksFresnel) {
  // Water with a black body under a uniform sky of 5000 cd/m2 and no sun: what a pixel sees
  // is the mirrored sky times Schlick's F = 0.02 + 0.98 (1 - cos)^5 (docs/SCENARIO.md
  // [ground] water). Two grazing angles of a 0.5 degree view: 60 and 85 degrees from the normal.
  // The mirror is chosen with probability F, so the mean is a binomial share of N samples:
  // its relative standard error is sqrt((1 - F) / (F N)), 1.3% at 60 degrees for 64 x 64
  // pixels of 64 samples (8 x 8 pixels made it 10.6%: a 3% tolerance passed by luck).
  Scene s;
  s.ground.mesh = flat_ground(5e4);
  s.ground.materials = {{{0.0f, 0.0f, 0.0f}, true}};
  s.ground.triangle_material.assign(s.ground.mesh.triangle_count(), 1);
  s.sky.model = SkyKind::gradient;
  s.sky.zenith_radiance = s.sky.horizon_radiance = {5000.0f, 5000.0f, 5000.0f};
  s.sun.irradiance = {0.0f, 0.0f, 0.0f};
  s.settings.spp = 64;
  for (const double incidence : {60.0, 85.0}) {
    const double down = (90.0 - incidence) * std::numbers::pi / 180.0;
    const View v{"v",
                 {0.0, 0.0, 10.0},
                 {std::cos(down) * 100.0, 0.0, 10.0 - std::sin(down) * 100.0},
                 0.5,
                 64,
                 64};
    const Film film = Renderer(s).render(v, {});
    double mean = 0.0;
    for (int y = 0; y < film.height(); ++y)
      for (int x = 0; x < film.width(); ++x) {
        // The water's mesh or the plain beyond it, which shades as the ground it continues.
        ASSERT_TRUE(film.object(x, y) == static_cast<std::uint8_t>(ObjectClass::ground) ||
                    film.object(x, y) == static_cast<std::uint8_t>(ObjectClass::plain));
        mean += film.luminance(x, y);
      }
    mean /= static_cast<double>(film.pixel_count());
    const double c = std::cos(incidence * std::numbers::pi / 180.0);
    const double fresnel = 0.02 + 0.98 * std::pow(1.0 - c, 5.0);
    const double samples = static_cast<double>(film.pixel_count()) * s.settings.spp;
    const double standard_error = std::sqrt((1.0 - fresnel) / (fresnel * samples));
    EXPECT_NEAR(mean / (5000.0 * fresnel), 1.0, 4.0 * standard_error) << incidence << " degrees";
  }
}

TEST(Physics, AovsAgreeWithTheScene) {
  Scene s = lit_ridge();
  TreePrototype box;
  trees::TriangleSet& t = box.geometry.group(trees::Group::leaves).triangles;
  t.vertices = {{0, -3, 0}, {0, 3, 0}, {0, 3, 6}, {0, -3, 6}};
  t.normals.assign(4, Vec3f{1, 0, 0});
  t.indices = {0, 1, 2, 0, 2, 3};
  test::make_single_item(box.geometry.group(trees::Group::leaves));
  // A hand-made leaf has no disc for far ranges: drawn at full detail.
  s.settings.degradation = false;
  box.species = 7;
  s.prototypes = {box};
  s.instances = {{0, {40.0, 50.0, 25.0}, std::numbers::pi / 2, 1.0},
                 {0, {65.0, 50.0, 25.0}, std::numbers::pi / 2, 1.0}};
  const View v{"v", {52.0, -30.0, 40.0}, {52.0, 50.0, 25.0}, 50.0, 96, 64};
  const Film film = Renderer(s).render(v, {});
  const Camera cam(v);
  int leaves = 0;
  for (int y = 0; y < film.height(); ++y) {
    for (int x = 0; x < film.width(); ++x) {
      if (film.object(x, y) != static_cast<std::uint8_t>(ObjectClass::leaf)) {
        EXPECT_EQ(film.instance(x, y), kNoId);
        continue;
      }
      ++leaves;
      EXPECT_EQ(film.species(x, y), 7u);
      const std::uint32_t id = film.instance(x, y);
      ASSERT_LT(id, 2u);
      // The hit point, from depth along the pixel's (first-sample) ray, lies on that instance.
      const Ray r = *cam.ray(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
      const Vec3f p = r.origin + r.direction * film.depth(x, y);
      EXPECT_NEAR(p.x, s.instances[id].position.x, 3.5);
      EXPECT_NEAR(p.y, 50.0f, 0.5f);
    }
  }
  EXPECT_GT(leaves, 20);
}

// The first checkpoint is written soon after the start even when checkpoint_seconds is
// long: a render killed early keeps its first waves.
TEST(Physics, FirstCheckpointComesEarly) {
  const Scene s = lit_ridge();
  const View v{"v", {52.0, -60.0, 80.0}, {52.0, 50.0, 10.0}, 45.0, 200, 120};  // 104 tiles
  landsim::testing::TempDir dir;
  for (const double first : {0.0, 1e6}) {
    RenderOptions o;
    o.checkpoint = dir / "v.checkpoint.exr";
    o.render_key = "ridge";
    o.checkpoint_seconds = 1e6;
    o.first_checkpoint_seconds = first;
    bool seen = false;  // a checkpoint on disk while the render was still running
    o.progress = [&](double p) {
      if (p < 1.0) seen = seen || std::filesystem::exists(o.checkpoint);
    };
    Renderer(s).render(v, o);
    EXPECT_EQ(seen, first == 0.0) << "first checkpoint after " << first << " s";
    EXPECT_FALSE(std::filesystem::exists(o.checkpoint));  // removed when complete
  }
}

// A render of `v` stopped after `tiles` tiles, its checkpoint in `dir` (key "ridge"); the
// options to render it again.
RenderOptions interrupted(const Scene& s, const View& v, const landsim::testing::TempDir& dir,
                          int tiles) {
  RenderOptions first;
  first.checkpoint = dir / "v.checkpoint.exr";
  first.render_key = "ridge";
  first.stop = [tiles](int tiles_done) { return tiles_done >= tiles; };
  EXPECT_THROW(Renderer(s).render(v, first), RenderInterrupted);
  EXPECT_TRUE(std::filesystem::exists(first.checkpoint));
  return first;
}

TEST(Physics, KilledAndResumedEqualsUninterrupted) {
  const Scene s = lit_ridge();
  const View v{"v", {52.0, -60.0, 80.0}, {52.0, 50.0, 10.0}, 45.0, 200, 120};  // 13 x 8 = 104 tiles
  const Film whole = Renderer(s).render(v, {});
  landsim::testing::TempDir dir;
  RenderOptions first = interrupted(s, v, dir, 64);
  ASSERT_TRUE(std::filesystem::exists(first.checkpoint));
  RenderOptions second = first;
  second.stop = nullptr;
  second.resume = true;
  RenderStats stats;
  const Film resumed = Renderer(s).render(v, second, &stats);
  EXPECT_FALSE(std::filesystem::exists(first.checkpoint));  // removed when complete
  EXPECT_TRUE(test::same_rgb_bits(whole, resumed));
  EXPECT_EQ(whole.object_data(), resumed.object_data());
  EXPECT_EQ(whole.depth_data(), resumed.depth_data());
  // A checkpoint of another render is not used.
  first.render_key = "other";
  EXPECT_THROW(Renderer(s).render(v, first), RenderInterrupted);
  second.render_key = "ridge";
  RenderStats fresh;
  Renderer(s).render(v, second, &fresh);
  EXPECT_GT(fresh.rays, stats.rays);  // it started again from tile 0
}

// A checkpoint whose tiles_done is no number an int holds (a damaged or foreign file) is a
// checkpoint of another render: the render starts afresh (std::stoi's exception escaped).
TEST(Physics, ACheckpointWithADamagedTileCountStartsAfresh) {
  const Scene s = lit_ridge();
  const View v{"v", {52.0, -60.0, 80.0}, {52.0, 50.0, 10.0}, 45.0, 80, 48};
  landsim::testing::TempDir dir;
  const RenderOptions first = interrupted(s, v, dir, 4);
  ASSERT_TRUE(std::filesystem::exists(first.checkpoint));
  const Film saved = read_exr(first.checkpoint);
  RenderOptions again = first;
  again.stop = nullptr;
  again.resume = true;
  RenderStats whole;
  Renderer(s).render(v, {}, &whole);
  for (const char* damaged : {"99999999999", "lots", "12abc"}) {
    write_exr(saved, first.checkpoint, {{"render_key", "ridge"}, {"tiles_done", damaged}}, nullptr,
              false);
    RenderStats resumed;
    EXPECT_NO_THROW(Renderer(s).render(v, again, &resumed)) << damaged;
    EXPECT_EQ(resumed.rays, whole.rays) << damaged;  // every tile traced again
  }
}

}  // namespace
}  // namespace landsim::renderer
