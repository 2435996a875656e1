// Rays leaving a surface (renderer/transport/surface.h offset_point): pushed off by the hit point's
// floating-point error, which grows with the coordinates only as float spacing does, so that
// the same stand of trees is lit the same wherever it stands.
#include "renderer/transport/surface.h"

#include <gtest/gtest.h>

#include <limits>

#include <algorithm>

#include <cmath>
#include <numbers>
#include <string>

#include "renderer/spectra/colour_matching.h"
#include "renderer/transport/render.h"
#include "tests/renderer/test_scenes.h"
#include "trees/species.h"

namespace landsim::renderer {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(Surface, AHitsErrorIsAFewUnitsInTheLastPlace) {
  // 3 km from the origin float spacing is 0.24 mm, 20 km out 2 mm: the bound stays within
  // a few of them (the old offset, 1e-4 x |p|, was 0.3 m and 2 m: leaves are 5-10 cm).
  const float near = hit_error({0, 0, 10}, 60.0f, {50, 20, 5});
  const float three_km = hit_error({2950, 0, 10}, 60.0f, {3000, 20, 5});
  const float twenty_km = hit_error({19950, 0, 10}, 60.0f, {20000, 20, 5});
  EXPECT_LT(near, 1e-4f);
  EXPECT_GT(three_km, 2.4e-4f);
  EXPECT_LT(three_km, 5e-3f);
  EXPECT_GT(twenty_km, 2e-3f);
  EXPECT_LT(twenty_km, 2.5e-2f);
}

// A ray leaving a surface starts exactly the hit's error bound off it, and the bound holds
// the hit point's real error without being many times larger (rays offset ten times too far
// start beyond the leaves beside them): hits on a plane far from the origin, the exact point
// in double precision.
TEST(Surface, RaysLeaveAtTheHitsErrorBound) {
  for (const float x0 : {10.0f, 3000.0f, 20000.0f}) {
    const Vec3f origin{x0, -40.0f, 25.0f};
    const Vec3f d = normalize(Vec3f{0.31f, 0.93f, -0.2f});
    // The plane z = 0.37 (not a float-friendly height): t exactly, then as a float hit.
    const double t_exact = (0.37 - static_cast<double>(origin.z)) / static_cast<double>(d.z);
    const auto t = static_cast<float>(t_exact);
    const Vec3f p = origin + d * t;
    const Vec3 exact = Vec3(origin) + Vec3(d) * t_exact;
    const float bound = hit_error(origin, t, p);
    EXPECT_GE(bound, static_cast<float>(length(Vec3(p) - exact))) << x0;
    const float magnitude = std::max({std::abs(origin.x), std::abs(origin.y), std::abs(origin.z)}) +
                            t + std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    EXPECT_LE(bound, 3.0f * std::numeric_limits<float>::epsilon() * magnitude) << x0;
    ShadingPoint v{};
    v.p = p;
    v.error = bound;
    const Vec3f up{0.0f, 0.0f, 1.0f};
    const Vec3f off = offset_point(v, up);
    EXPECT_NEAR(off.z - p.z, bound, 0.5f * bound) << x0;  // one bound up, not ten
    EXPECT_EQ(off.x, p.x);
  }
}

// A quaking aspen, one variant, leaves and bark as in the species file's colours.
const TreePrototype& aspen() {
  static const TreePrototype p = [] {
    TreePrototype t;
    const trees::Species species =
        trees::load_species(std::string(LANDSIM_SOURCE_DIR) + "/data/species/quaking_aspen.toml");
    t.geometry = trees::generate(species, {.seed = 3}).geometry;
    t.dress(species.colours);
    return t;
  }();
  return p;
}

struct LeafLight {
  double mean = 0.0;  // luminance of the leaf pixels
  double standard_error = 0.0;
  int pixels = 0;
};

// A stand of 4 x 4 aspens 6 m apart around (cx, 0) on flat ground, the sun 40 degrees up,
// seen from the same place relative to it.
LeafLight stand_at(double cx) {
  Scene s;
  s.ground.mesh = testing::flat_ground(30000.0, 0.0f);
  s.prototypes.push_back(aspen());
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      s.instances.push_back(
          {0, {cx + 6.0 * (i - 1.5), 6.0 * (j - 1.5), 0.0}, 0.7 * (i + 4 * j), 1.0});
  s.sun.direction = {std::cos(40 * kDeg) * std::sin(120 * kDeg),
                     std::cos(40 * kDeg) * std::cos(120 * kDeg), std::sin(40 * kDeg)};
  s.settings.spp = 16;
  s.settings.max_bounces = 2;
  s.settings.degradation = false;
  const View v{"v", {cx - 40.0, -32.0, 14.0}, {cx, 0.0, 6.0}, 40.0, 96, 64};
  const Film film = Renderer(s).render(v, {});
  double sum = 0.0, squares = 0.0;
  LeafLight out;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      if (film.object(x, y) != static_cast<std::uint8_t>(ObjectClass::leaf)) continue;
      const auto& rgb = film.rgb_data();
      const std::size_t i = 3 * (static_cast<std::size_t>(y) * film.width() + x);
      const double l = rec709_luminance(Vec3{rgb[i], rgb[i + 1], rgb[i + 2]});
      sum += l;
      squares += l * l;
      ++out.pixels;
    }
  out.mean = sum / out.pixels;
  out.standard_error = std::sqrt((squares / out.pixels - out.mean * out.mean) / out.pixels);
  return out;
}

// The measurement: the same stand 3 km east read 26% brighter (its shadow rays
// started beyond the leaves within 0.3 m); now it agrees with the stand at the origin within
// noise, and 20 km out (a context's edge) too.
TEST(Surface, AStandIsLitTheSameWhereverItStands) {
  const LeafLight near = stand_at(0.0);
  ASSERT_GT(near.pixels, 500);
  for (const double cx : {3000.0, 20000.0}) {
    const LeafLight far = stand_at(cx);
    const double noise = std::hypot(near.standard_error, far.standard_error);
    EXPECT_NEAR(far.mean, near.mean, std::max(4.0 * noise, 0.02 * near.mean))
        << cx << " m east: " << far.mean << " against " << near.mean << " cd/m2 (" << far.pixels
        << " and " << near.pixels << " leaf pixels)";
  }
}

// Sloping ground 20 km out under a low sun: no pixels of self-shadowing from offsets too
// small for the float spacing there. The same view of the same ridge at the origin draws the
// same random numbers: pixel by pixel the two agree but for rounding.
TEST(Surface, FarGroundUnderALowSunHasNoSelfShadowing) {
  const auto ridge_at = [](double cx) {
    Scene s = testing::ridge_scene();
    for (Vec3f& v : s.ground.mesh.vertices) v.x += static_cast<float>(cx);
    s.sky.model = SkyKind::gradient;
    s.sky.zenith_radiance = s.sky.horizon_radiance = {50.0f, 50.0f, 50.0f};
    s.sun.direction = normalize(Vec3{std::cos(8 * kDeg), 0.3, std::sin(8 * kDeg)});
    View v = s.views.front();
    v.position.x += cx;
    v.target.x += cx;
    return Renderer(s).render(v, {});
  };
  const Film near = ridge_at(0.0), far = ridge_at(20000.0);
  int ground = 0, differ = 0;
  for (int y = 0; y < far.height(); ++y)
    for (int x = 0; x < far.width(); ++x) {
      if (far.object(x, y) != static_cast<std::uint8_t>(ObjectClass::ground) &&
          far.object(x, y) != static_cast<std::uint8_t>(ObjectClass::plain))
        continue;  // the ridge and the plain beyond it, both ground to the light
      ++ground;
      const auto lum = [&](const Film& f) {
        const auto& rgb = f.rgb_data();
        const std::size_t i = 3 * (static_cast<std::size_t>(y) * f.width() + x);
        return rec709_luminance(Vec3{rgb[i], rgb[i + 1], rgb[i + 2]});
      };
      // A self-shadowed sample loses the sun, most of this ground's light.
      differ += std::abs(lum(far) - lum(near)) > 0.1 * lum(near);
    }
  ASSERT_GT(ground, 1000);
  EXPECT_LT(differ, ground / 50) << differ << " of " << ground << " ground pixels differ";
}

}  // namespace
}  // namespace landsim::renderer
