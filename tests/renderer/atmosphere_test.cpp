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

#include "renderer/image_output.h"
#include "renderer/render.h"
#include "renderer/sky.h"
#include "renderer/spectral_colour.h"
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
