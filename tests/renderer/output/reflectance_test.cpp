// Reflectance factors (docs/SENSOR.md "Irradiance and reflectance"): a Lambertian panel of
// known albedo under sun and sky, path-traced, reads its albedo in every reflectance layer.
#include "renderer/output/reflectance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "renderer/atmosphere/sky.h"
#include "renderer/spectra/colour_matching.h"
#include "renderer/spectra/sensor_band.h"
#include "renderer/spectra/spectral_colour.h"
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
  for (const char* layer : {"reflectance.X", "reflectance.Y", "reflectance.Z",
                            "reflectance.band.red", "reflectance.photons.nir"})
    EXPECT_NEAR(layer_mean(film, layer) / kAlbedo, 1.0, 0.01) << layer;
}

// A saturated green (a surface reflecting 540-560 nm only, as light that crossed many leaves
// is): its Rec. 709 R and B are negative, its reflectance layers are the CIE tristimulus
// reflectance factors, integrals of non-negative functions: not negative, and equal to the
// colour-matching functions summed over the lit bins.
TEST(Reflectance, ASaturatedGreenReadsItsTristimulusReflectanceNeverNegative) {
  const double rho = 0.8;
  Spectrum reflectance = Spectrum::constant(0.0f);
  for (int k = 0; k < kSpectrumBins; ++k)
    if (bin_start(k) >= 540.0 && bin_start(k) < 560.0) reflectance[k] = static_cast<float>(rho);
  const Spectrum e = Spectrum::constant(1.0f);  // W m-2 nm-1 on the ground
  const Vec3f radiance =
      spectrum_to_rgb(reflectance * e * static_cast<float>(1.0 / std::numbers::pi));
  ASSERT_LT(std::min(radiance.x, radiance.z), 0.0f);  // out of Rec. 709's gamut
  Film film(2, 1);
  for (int i = 0; i < 3; ++i) film.rgb_data()[static_cast<std::size_t>(i)] = radiance[i];
  ImageIrradiance irradiance;
  irradiance.rgb = spectrum_to_rgb(e);
  irradiance.xyz = spectrum_to_xyz(e);
  add_reflectance(film, irradiance);
  // The tristimulus reflectance factor: sum of rho x the CIE function over the lit bins, over
  // the CIE function's sum under the flat light.
  Vec3 lit{}, all{};
  for (double l = 380.5; l < 1020.0; l += 1.0) {
    all += cie1931_xyz_bar(l);
    if (l >= 540.0 && l < 560.0) lit += cie1931_xyz_bar(l) * rho;
  }
  const char* names[3] = {"reflectance.X", "reflectance.Y", "reflectance.Z"};
  for (int c = 0; c < 3; ++c) {
    const auto& plane = film.band_data(c);
    EXPECT_NEAR(plane[0], lit[c] / all[c], 1e-4 + 1e-4 * lit[c] / all[c]) << names[c];
    EXPECT_GE(plane[0], 0.0f) << names[c];
    EXPECT_EQ(plane[1], 0.0f) << names[c];  // a black pixel: 0, not rounding below it
  }
  EXPECT_EQ(film.band_name(0), "reflectance.X");
}

}  // namespace
}  // namespace landsim::renderer
