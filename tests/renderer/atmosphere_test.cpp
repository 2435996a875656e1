// The atmosphere as a user measures it: dense fog over an endless plain converges to the
// sky's horizon, and the EXR's luminance layer of a white Lambertian plane is E / pi in cd/m2.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "renderer/atmosphere/sky.h"
#include "renderer/output/image_output.h"
#include "renderer/spectra/colour_matching.h"
#include "renderer/spectra/spectral_colour.h"
#include "renderer/transport/render.h"
#include "terrain/ground_mesh.h"
#include "tests/renderer/test_scenes.h"
#include "tests/support/temp_dir.h"

namespace landsim::renderer {
namespace {

using testing::flat_ground;

constexpr double kDeg = std::numbers::pi / 180.0;

Vec3 toward(double elevation_deg, double azimuth_deg) {
  const double el = elevation_deg * kDeg, az = azimuth_deg * kDeg;
  return {std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), std::sin(el)};
}

Vec3 mean_rgb(const Film& film) {
  Vec3 sum{};
  const auto& rgb = film.rgb_data();
  for (std::size_t i = 0; i < film.pixel_count(); ++i)
    sum += Vec3{rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]};
  return sum / static_cast<double>(film.pixel_count());
}

TEST(Atmosphere, LevelViewThroughFogSeesTheSkysHorizon) {
  // 500 m visibility over an endless plain: the only ground is a small patch far below, so
  // level rays run through the fog forever. Sun at 40 degrees in the south-east.
  Scene s;
  s.ground.mesh = flat_ground(10.0, -5000.0f);
  s.sun.direction = toward(40.0, 135.0);
  s.sky.turbidity = 3.0;
  s.sun.irradiance = sun_irradiance(s.sky, 40.0, s.sun.angular_radius);
  s.haze.enabled = true;
  s.haze.visibility = 500.0;
  s.haze.base_height = 0.0;
  s.settings.spp = 16;
  const SkyModel sky(s.sky, s.sun, s.ground.albedo);
  // Four azimuths, one of them toward the sun; a 1 degree field of view about the level.
  for (double azimuth : {0.0, 90.0, 135.0, 250.0}) {
    const Vec3 d = toward(0.0, azimuth);
    const View v{"level", {0.0, 0.0, 0.0}, d * 100.0, 1.0, 8, 8};
    const Vec3 got = mean_rgb(Renderer(s).render(v, {}));
    // The tracer is spectral: its horizon is the spectral tables' (whose colour differs from
    // the RGB tables' by a few percent per channel, docs/SPECTRAL.md).
    const Vec3 want(spectrum_to_rgb(sky.horizon_band_spectral(Vec3f(d))));
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(got[c] / want[c], 1.0, 0.03)
          << "azimuth " << azimuth << " channel " << c << ": " << got[c] << " against " << want[c];
  }
}

// A quad (two triangles) at height z over x in [x0, x1], y in [y0, y1], facing down.
terrain::GroundMesh roof(float x0, float x1, float y0, float y1, float z) {
  terrain::GroundMesh m;
  m.vertices = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
  m.normals.assign(4, Vec3f{0.0f, 0.0f, -1.0f});
  m.indices = {0, 2, 1, 0, 3, 2};
  return m;
}

// Haze of 3 km visibility and 1 km scale height from z = 0 under a uniform sky of `sky`
// cd/m2, over black ground and a black plain: the light is the test's own.
Scene hazy_scene(float sky) {
  Scene s;
  s.ground.albedo = {0.0f, 0.0f, 0.0f};
  s.ground.edge_albedo = Vec3f{0.0f, 0.0f, 0.0f};
  s.sky.model = SkyKind::gradient;
  s.sky.zenith_radiance = s.sky.horizon_radiance = {sky, sky, sky};
  s.haze.enabled = true;
  s.haze.visibility = 3000.0;
  s.haze.scale_height = 1000.0;
  s.haze.base_height = 0.0;
  return s;
}

// Single scattering of sunlight, the only light: a black sky and plain, black ground. A
// level ray at the haze's base height z0 runs through constant extinction sigma0, and every
// point on it sees the sun through the same slant optical depth sigma0 H / sin(elevation):
// L = a p(theta) E T_sun integral of sigma0 exp(-sigma0 s) ds. Unshadowed the integral is 1;
// under a roof casting its shadow on the ray over [s1, s2] it loses exp(-sigma0 s1) -
// exp(-sigma0 s2). Here sigma0 = 3.912 / 3000 m, H = 1000 m, the sun 60 degrees up, the
// Henyey-Greenstein phase of g = 0.7, a = 0.95.
TEST(Atmosphere, SunlitHazeIsSingleScatteringAndAShadowedColumnIsDarkerByItsShare) {
  Scene s = hazy_scene(0.0f);
  s.ground.mesh = flat_ground(10.0, -5000.0f);
  const double elevation = 60.0 * kDeg;
  s.sun.direction = {0.0, std::cos(elevation), std::sin(elevation)};
  s.sun.irradiance = {80000.0f, 80000.0f, 80000.0f};
  s.settings.spp = 256;
  const double sigma = 3.912 / 3000.0, g = 0.7;
  const double t_sun = std::exp(-sigma * 1000.0 / std::sin(elevation));
  // Across the sun's azimuth (scattered at 90 degrees), toward it and away from it: the
  // Henyey-Greenstein phase at cos theta = 0, 0.5 and -0.5.
  for (const Vec3& d : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, -1, 0}}) {
    const double c = dot(d, s.sun.direction);
    const double phase =
        (1 - g * g) / (4 * std::numbers::pi * std::pow(1 + g * g - 2 * g * c, 1.5));
    const double want = 0.95 * phase * 80000.0 * t_sun;
    const View v{"v", {0.0, 0.0, 0.0}, d * 1000.0, 0.2, 4, 4};
    const double got = rec709_luminance(mean_rgb(Renderer(s).render(v, {})));
    EXPECT_NEAR(got / want, 1.0, 0.03) << "cos theta " << c << ": " << got << " against " << want;
  }
  const View level{"level", {0.0, 0.0, 0.0}, {1000.0, 0.0, 0.0}, 0.2, 4, 4};
  const double open = rec709_luminance(mean_rgb(Renderer(s).render(level, {})));
  // A roof 20 m up over x in [300, 900], wide across the view: its shadow (11.5 m toward the
  // sun's opposite side) lies on the ray over the same x; the camera, 3.8 degrees under its
  // near edge, does not see it.
  const terrain::GroundMesh below = s.ground.mesh;
  s.ground.mesh = roof(300.0f, 900.0f, -3000.0f, 3000.0f, 20.0f);
  for (std::size_t i = 0; i < below.vertices.size(); ++i) {
    s.ground.mesh.vertices.push_back(below.vertices[i]);
    s.ground.mesh.normals.push_back(below.normals[i]);
  }
  for (std::uint32_t i : below.indices) s.ground.mesh.indices.push_back(i + 4);
  const double shadowed = rec709_luminance(mean_rgb(Renderer(s).render(level, {})));
  const double share = std::exp(-sigma * 300.0) - std::exp(-sigma * 900.0);
  EXPECT_NEAR(shadowed / open, 1.0 - share, 0.02) << "the shadow's share " << share;
}

// Skylight toward the horizon, the only light: a black wall at distance d, seen level
// through the haze under a uniform sky of L cd/m2 (no sun), takes L (1 - exp(-sigma0 d)) —
// Koschmieder's veil: the haze in-scatters the horizon's radiance.
TEST(Atmosphere, ADistantBlackWallTakesTheHorizonsRadianceByKoschmieder) {
  Scene s = hazy_scene(5000.0f);
  s.sun.direction = {0.0, 0.0, 1.0};
  s.sun.irradiance = {0.0f, 0.0f, 0.0f};
  s.settings.spp = 64;
  const double sigma = 3.912 / 3000.0;
  for (const float d : {500.0f, 1500.0f, 4000.0f}) {
    // The wall: a vertical quad across the view at x = d.
    s.ground.mesh.vertices = {{d, -500, -500}, {d, 500, -500}, {d, 500, 500}, {d, -500, 500}};
    s.ground.mesh.normals.assign(4, Vec3f{-1.0f, 0.0f, 0.0f});
    s.ground.mesh.indices = {0, 1, 2, 0, 2, 3};
    const View level{"level", {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 0.2, 4, 4};
    const double got = rec709_luminance(mean_rgb(Renderer(s).render(level, {})));
    const double want = 5000.0 * (1.0 - std::exp(-sigma * d));
    EXPECT_NEAR(got / want, 1.0, 0.03) << d << " m: " << got << " against " << want;
  }
}

TEST(Atmosphere, LuminanceLayerOfAWhitePlaneIsIrradianceOverPi) {
  // White Lambertian plane, sun of 80 klx at 50 degrees, uniform sky of 4000 cd/m2:
  // E = 80000 sin 50 + pi 4000 lux, and the plane's luminance is E / pi.
  Scene s;
  s.ground.mesh = flat_ground(1e4, 0.0f);
  s.ground.albedo = {1.0f, 1.0f, 1.0f};
  s.sky.model = SkyKind::gradient;
  s.sky.zenith_radiance = s.sky.horizon_radiance = {4000.0f, 4000.0f, 4000.0f};
  s.sun.direction = toward(50.0, 200.0);
  s.sun.irradiance = {80000.0f, 80000.0f, 80000.0f};
  s.settings.spp = 32;
  const View down{"v", {0.0, 0.0, 10.0}, {5.0, 0.0, 0.0}, 40.0, 16, 16};
  const Film film = Renderer(s).render(down, {});
  const landsim::testing::TempDir dir;
  const auto path = dir / "plane.exr";
  write_exr(film, path, {});

  Imf::InputFile in(path.c_str());
  ASSERT_NE(in.header().channels().findChannel("Y"), nullptr);
  ASSERT_TRUE(Imf::hasWhiteLuminance(in.header()));
  EXPECT_EQ(Imf::whiteLuminance(in.header()), 1.0f);
  std::vector<float> y(film.pixel_count());
  Imf::FrameBuffer fb;
  fb.insert("Y", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(y.data()), sizeof(float),
                            sizeof(float) * 16));
  in.setFrameBuffer(fb);
  in.readPixels(0, 15);
  double mean = 0.0;
  for (float v : y) mean += v;
  mean /= static_cast<double>(y.size());
  const double e = 80000.0 * std::sin(50.0 * kDeg) + std::numbers::pi * 4000.0;
  EXPECT_NEAR(mean / (e / std::numbers::pi), 1.0, 0.02) << mean;
}

}  // namespace
}  // namespace landsim::renderer
