// Reflectance factors (docs/SENSOR.md "Irradiance and reflectance"): a Lambertian panel of
// known albedo under sun and sky, path-traced, reads its albedo in every reflectance layer.
#include "renderer/output/reflectance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "renderer/atmosphere/sky.h"
#include "renderer/spectra/sensor_band.h"
#include "renderer/transport/render.h"
#include "tests/renderer/test_scenes.h"

namespace landsim::renderer {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr float kAlbedo = 0.3f;

double layer_mean(const Film& film, const std::string& name) {
  const auto& names = film.band_names();
  const auto it = std::find(names.begin(), names.end(), name);
  EXPECT_NE(it, names.end()) << name;
  if (it == names.end()) return 0.0;
  double sum = 0.0;
  for (const float v : film.band_data(static_cast<int>(it - names.begin()))) sum += v;
  return sum / static_cast<double>(film.pixel_count());
}

TEST(Reflectance, LambertianPanelReadsItsAlbedo) {
  Scene s;
  s.ground.mesh = testing::flat_ground(1e4);
  s.ground.albedo = {kAlbedo, kAlbedo, kAlbedo};
  s.sun.direction = {0.3, -std::cos(42.0 * kDeg), std::sin(42.0 * kDeg)};
  s.sun.direction = normalize(s.sun.direction);
  s.sun.irradiance = sun_irradiance(s.sky, 42.0, s.sun.angular_radius);
  s.settings.spp = 32;
  s.bands = {sensor_band("red", box_response(660.0, 60.0)),
             photon_band("photons.nir", box_response(835.0, 130.0))};
  s.views.push_back({"down", {0.0, 0.0, 30.0}, {0.0, 0.0, 0.0}, 40.0, 48, 48});
  Film film = Renderer(s).render(s.views[0], {});
  const ImageIrradiance e = image_irradiance(s, film);
  EXPECT_NEAR(e.height, 0.0, 1e-3);  // the panel under the image's centre
  ASSERT_EQ(e.layers.size(), 2u);
  add_reflectance(film, e);
  for (const char* layer : {"reflectance.R", "reflectance.G", "reflectance.B",
                            "reflectance.band.red", "reflectance.photons.nir"})
    EXPECT_NEAR(layer_mean(film, layer) / kAlbedo, 1.0, 0.01) << layer;
}

}  // namespace
}  // namespace landsim::renderer
