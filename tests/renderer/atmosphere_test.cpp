// The atmosphere as a user measures it: Koschmieder's 2% at the visibility distance, single
// scattering in closed form, a flat ground's reflectance equal to its albedo through any haze,
// and the EXR's luminance layer of a white Lambertian plane is E / pi in cd/m2.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "renderer/output/reflectance.h"

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

// A scene lit by the Hosek-Wilkie sky and sun at 35 degrees, hazed to `visibility` from its
// base at the camera's height, over ground of albedo 0.2 everywhere (a small grid and the
// plain around it), with small black walls across the view at the distances given; one band at
// 550 nm (bin 8), where the visibility is defined.
Scene koschmieder_scene(double visibility, const std::vector<float>& walls) {
  Scene s;
  s.sun.direction = toward(35.0, 0.0);  // north, across the view (east)
  s.sun.irradiance = sun_irradiance(s.sky, 35.0, s.sun.angular_radius);
  s.ground.albedo = {0.2f, 0.2f, 0.2f};
  s.ground.edge_albedo = Vec3f{0.2f, 0.2f, 0.2f};
  s.ground.plain_height = 0.0f;
  s.ground.mesh = flat_ground(10.0, 0.0f);
  s.ground.materials = {GroundMaterial{{0.0f, 0.0f, 0.0f}, false}};
  s.ground.triangle_material.assign(s.ground.mesh.indices.size() / 3, 0);
  for (const float d : walls) {
    const auto first = static_cast<std::uint32_t>(s.ground.mesh.vertices.size());
    // Just wider than the view (0.6 degrees): a larger wall would shade the haze before it.
    const float h = 0.005f * d;
    for (const Vec3f& v : {Vec3f{d, -h, 20.0f - h}, Vec3f{d, h, 20.0f - h}, Vec3f{d, h, 20.0f + h},
                           Vec3f{d, -h, 20.0f + h}}) {
      s.ground.mesh.vertices.push_back(v);
      s.ground.mesh.normals.push_back({-1.0f, 0.0f, 0.0f});
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) s.ground.mesh.indices.push_back(first + i);
    s.ground.triangle_material.insert(s.ground.triangle_material.end(), 2, 1);
  }
  s.haze.enabled = true;
  s.haze.visibility = visibility;
  s.haze.base_height = 20.0;
  SpectralBand green{"550", {}};
  green.weight[8] = 1.0f;
  s.bands = {green};
  s.settings.spp = 8192;
  return s;
}

double mean_band(const Film& film) {
  double sum = 0.0;
  for (float v : film.band_data(0)) sum += v;
  return sum / static_cast<double>(film.pixel_count());
}

// Koschmieder's law, which defines the visibility: a black target at the visibility distance
// V, seen level through a horizontally uniform haze against the horizon (here a black wall
// so far that nothing of it shows), keeps 2% contrast: L_target / L_horizon = 1 - e^-3.912.
// Both radiances are the haze's own light, scattered once or many times.
TEST(Atmosphere, ABlackTargetAtTheVisibilityDistanceShowsTwoPercentContrast) {
  for (const double v : {5000.0, 10000.0}) {
    const View level{"level", {0.0, 0.0, 20.0}, {1.0, 0.0, 20.0}, 0.2, 4, 4};
    const double target =
        mean_band(Renderer(koschmieder_scene(v, {static_cast<float>(v)})).render(level, {}));
    const double horizon =
        mean_band(Renderer(koschmieder_scene(v, {static_cast<float>(20.0 * v)})).render(level, {}));
    EXPECT_NEAR(1.0 - target / horizon, 0.02, 0.003)
        << v << " m: " << target << " against " << horizon;
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
  s.haze.albedo = {0.95f, 0.95f, 0.95f};
  s.haze.molecular = false;  // the aerosol alone, grey: closed forms
  s.haze.angstrom = 0.0;
  return s;
}

// Single scattering of sunlight, the only light (paths cut after their first scattering
// point): a black sky and plain, black ground. A
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
  s.settings.max_bounces = 0;  // the haze point's light only: single scattering
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

// A flat Lambertian ground of albedo 0.15 / 0.13 / 0.09 seen from 10 m, under the Hosek-Wilkie
// sky and sun at 35 degrees, through haze of 5, 10 and 40 km: its reflectance factor pi L / E
// (E the downwelling irradiance the manifest reports, from the same medium) is its albedo.
TEST(Atmosphere, AFlatGroundReadsItsAlbedoThroughAnyHaze) {
  const Vec3f albedo{0.15f, 0.13f, 0.09f};
  for (const double v : {5000.0, 10000.0, 40000.0}) {
    Scene s;
    s.sun.direction = toward(35.0, 160.0);
    s.sun.irradiance = sun_irradiance(s.sky, 35.0, s.sun.angular_radius);
    s.ground.mesh = flat_ground(2000.0, 0.0f);
    s.ground.albedo = albedo;
    s.ground.edge_albedo = albedo;
    s.haze.enabled = true;
    s.haze.visibility = v;
    s.settings.spp = 512;
    const View down{"v", {0.0, 0.0, 10.0}, {0.0, 0.1, 0.0}, 30.0, 16, 16};
    const Film film = Renderer(s).render(down, {});
    const ImageIrradiance e = image_irradiance(s, film);
    const Vec3 rgb = mean_rgb(film);
    if (std::getenv("LANDSIM_VERBOSE"))
      std::printf("%g m: %.4f %.4f %.4f\n", v, std::numbers::pi * rgb[0] / e.rgb[0] / albedo[0],
                  std::numbers::pi * rgb[1] / e.rgb[1] / albedo[1],
                  std::numbers::pi * rgb[2] / e.rgb[2] / albedo[2]);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(std::numbers::pi * rgb[c] / e.rgb[c] / albedo[c], 1.0, 0.02)
          << v << " m, channel " << c;
  }
}

}  // namespace
}  // namespace landsim::renderer
