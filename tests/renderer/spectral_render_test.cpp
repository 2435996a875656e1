// Rendering in bands (renderer/transport/path_tracer, film, image_output, render): a white plane's
// band radiance is the band's irradiance over pi; band layers survive the EXR and the tile packing.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "renderer/atmosphere/sky.h"
#include "renderer/output/image_output.h"
#include "renderer/spectra/sensor_band.h"
#include "renderer/transport/render.h"
#include "terrain/ground_mesh.h"
#include "tests/renderer/test_scenes.h"
#include "tests/support/temp_dir.h"

namespace landsim::renderer {
namespace {

using testing::flat_ground;

constexpr double kDeg = std::numbers::pi / 180.0;

Scene white_plane_with_bands() {
  Scene s;
  s.ground.mesh = flat_ground(1e4);
  s.ground.albedo = {1.0f, 1.0f, 1.0f};
  const double elevation = 50.0;
  s.sun.direction = {0.0, -std::cos(elevation * kDeg), std::sin(elevation * kDeg)};
  s.sky.turbidity = 3.0;
  s.sun.irradiance = sun_irradiance(s.sky, elevation, s.sun.angular_radius);
  s.settings.spp = 32;
  s.bands = {sensor_band("red", box_response(660.0, 60.0)),
             sensor_band("nir", box_response(835.0, 130.0)),
             sensor_band("blue", box_response(470.0, 60.0))};
  s.views.push_back({"down", {0.0, 0.0, 10.0}, {5.0, 0.0, 0.0}, 40.0, 16, 16});
  return s;
}

TEST(SpectralRender, WhitePlaneBandRadianceIsBandIrradianceOverPi) {
  const Scene s = white_plane_with_bands();
  const Film film = Renderer(s).render(s.views[0], {});
  ASSERT_EQ(film.band_count(), 3);
  // The irradiance on the plane, bin by bin: the sun's spectrum x sin(elevation), plus the
  // sky's radiance integrated over the upper hemisphere (midpoint rule, 1 degree steps).
  const SkyModel sky(s.sky, s.sun, s.ground.albedo, s.spectral_grid);
  const Spectrum e = sky.sun_spectral_irradiance() * static_cast<float>(s.sun.direction.z) +
                     testing::sky_hemisphere_irradiance(sky);
  for (int b = 0; b < 3; ++b) {
    double want = 0.0;
    for (int k = 0; k < kSpectrumBins; ++k) want += s.bands[b].weight[k] * e[k];
    want /= std::numbers::pi;
    double got = 0.0;
    for (int y = 0; y < film.height(); ++y)
      for (int x = 0; x < film.width(); ++x) got += film.band(x, y, b);
    got /= static_cast<double>(film.pixel_count());
    EXPECT_NEAR(got / want, 1.0, 0.02) << film.band_name(b) << ": " << got << " against " << want;
  }
}

TEST(SpectralRender, BandLayersSurviveTheExrInTheScenesOrder) {
  Scene s = white_plane_with_bands();
  s.settings.spp = 2;
  const Film film = Renderer(s).render(s.views[0], {});
  const landsim::testing::TempDir dir;
  write_exr(film, dir / "bands.exr", {});
  Film back = read_exr(dir / "bands.exr");
  // OpenEXR lists channels alphabetically: blue, nir, red; the scene's order is red, nir, blue.
  ASSERT_EQ(back.band_names(), (std::vector<std::string>{"blue", "nir", "red"}));
  ASSERT_TRUE(back.order_bands(film.band_names()));
  EXPECT_FALSE(back.order_bands({"red", "green", "blue"}));
  for (int b = 0; b < 3; ++b) EXPECT_EQ(back.band_data(b), film.band_data(b)) << b;
  EXPECT_GT(film.band(3, 3, 1), film.band(3, 3, 0));  // 130 nm of near infrared against 60
}

TEST(SpectralRender, PackedTilesCarryTheBands) {
  Scene s = white_plane_with_bands();
  s.settings.spp = 1;
  const Film film = Renderer(s).render(s.views[0], {});
  Film copy = make_film(s, s.views[0]);
  unpack_tiles(pack_tiles(film, 0, tile_count(s.views[0])), 0, tile_count(s.views[0]), copy);
  for (int b = 0; b < 3; ++b) EXPECT_EQ(copy.band_data(b), film.band_data(b)) << b;
  EXPECT_GT(copy.band(0, 0, 0), 0.0f);
}

}  // namespace
}  // namespace landsim::renderer
