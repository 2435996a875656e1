// The atmosphere's parts per pixel (renderer/output/atmosphere_layers.h) against what holds
// independently of how they are estimated: a flat Lambertian ground's surface radiance over
// the irradiance on it (two estimators: the BSDF's paths with next-event estimation, and one
// cosine-distributed path and a sun ray) is its albedo, while its apparent reflectance factor
// (pi L / E) holds the air's path radiance too; the direct and diffuse irradiance on an open
// flat ground are the downwelling irradiance's quadrature; the transmittance down a nadir view
// is Beer-Lambert's through the column between camera and ground; and apparent radiance =
// path radiance + transmittance x surface radiance in RGB, whose channels span many bins.
#include "renderer/output/atmosphere_layers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <tuple>

#include "renderer/atmosphere/downwelling.h"
#include "renderer/atmosphere/medium.h"
#include "renderer/spectra/colour_matching.h"
#include "renderer/spectra/spectral_colour.h"
#include "renderer/transport/render.h"
#include "tests/renderer/test_scenes.h"

namespace landsim::renderer {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr int kGreen = 8;  // 540-560 nm

// A flat ground of `albedo` under the one atmosphere, the sun `elevation` up in the south,
// rendered with the atmosphere's layers and a one-bin green band.
Scene layered_scene(double visibility, double elevation, float albedo, int spp) {
  const double e = elevation * kDeg;
  Scene s = testing::one_atmosphere_scene({0.0, -std::cos(e), std::sin(e)}, visibility, 600.0,
                                          albedo, 5000.0);
  s.settings.atmosphere_layers = true;
  s.settings.spp = spp;
  SpectralBand green{"green", {}};
  green.weight[kGreen] = 1.0f;
  s.bands = {green};
  return s;
}

// The mean over the film of plane `b`.
double mean(const Film& film, int b) {
  double sum = 0.0;
  for (float v : film.band_data(b)) sum += v;
  return sum / static_cast<double>(film.pixel_count());
}

int layer(AtmospherePart part, int channel) { return atmosphere_layer(part, channel, 1); }

// The view rendered, its surface layers finished as an image set's.
Film finished(const Scene& s, const View& view) {
  Film film = Renderer(s).render(view, {});
  finish_atmosphere_layers(film, static_cast<int>(s.bands.size()));
  return film;
}

TEST(AtmosphereLayers, NamesEachPartInXyzAndEveryBand) {
  const std::vector<std::string> names = atmosphere_layer_names({{"red", {}}, {"photons.nir", {}}});
  ASSERT_EQ(names.size(), 25u);
  EXPECT_EQ(names[0], "atmosphere.path.X");
  EXPECT_EQ(names[3], "atmosphere.path.band.red");
  EXPECT_EQ(names[4], "atmosphere.path.photons.nir");
  EXPECT_EQ(names[5], "atmosphere.transmittance.X");
  EXPECT_EQ(names[24], "atmosphere.diffuse.photons.nir");
  EXPECT_EQ(atmosphere_layer(AtmospherePart::diffuse, 4, 2), 2 + 4 * 5 + 4);
}

// A view 300 m up, 40 degrees below the horizon: the air between camera and ground adds
// light, so the apparent reflectance factor exceeds the albedo; the surface's own does not.
TEST(AtmosphereLayers, AFlatGroundsSurfaceReflectanceIsItsAlbedo) {
  const float albedo = 0.3f;
  for (const auto& [visibility, elevation] :
       {std::tuple{5000.0, 15.0}, {10000.0, 35.0}, {40000.0, 60.0}}) {
    const Scene s = layered_scene(visibility, elevation, albedo, 128);
    const View oblique{"v", {0.0, 0.0, 300.0}, {0.0, 357.5, 0.0}, 20.0, 12, 12};
    const Film film = finished(s, oblique);
    const double surface = mean(film, layer(AtmospherePart::surface, 3));
    const double e = mean(film, layer(AtmospherePart::direct, 3)) +
                     mean(film, layer(AtmospherePart::diffuse, 3));
    const double boa = std::numbers::pi * surface / e / albedo;
    const double apparent =
        std::numbers::pi * mean(film, 0) / downwelling_irradiance(s, 0.0).total()[kGreen] / albedo;
    std::printf("%g m, sun %g: surface reflectance / albedo %.4f, apparent %.4f\n", visibility,
                elevation, boa, apparent);
    EXPECT_NEAR(boa, 1.0, 0.01) << visibility << " m, sun " << elevation;
    if (visibility < 8000.0) {
      EXPECT_GT(apparent, 1.05);
    }
  }
}

TEST(AtmosphereLayers, TheIrradianceOnAnOpenFlatGroundIsTheDownwelling) {
  const Scene s = layered_scene(10000.0, 35.0, 0.3f, 256);
  const View down{"v", {0.0, 0.0, 50.0}, {0.0, 0.1, 0.0}, 20.0, 8, 8};
  const Film film = finished(s, down);
  const Downwelling want = downwelling_irradiance(s, 0.0);
  const double direct = mean(film, layer(AtmospherePart::direct, 3));
  const double diffuse = mean(film, layer(AtmospherePart::diffuse, 3));
  std::printf("direct %.4f (want %.4f), diffuse %.4f (want %.4f)\n", direct, want.direct[kGreen],
              diffuse, want.diffuse[kGreen]);
  EXPECT_NEAR(direct / want.direct[kGreen], 1.0, 0.005);
  EXPECT_NEAR(diffuse / want.diffuse[kGreen], 1.0, 0.02);
}

// Straight down from 2 km: exp(-(column above the ground - column above the camera)).
TEST(AtmosphereLayers, TheTransmittanceDownANadirViewIsBeerLambert) {
  const Scene s = layered_scene(10000.0, 35.0, 0.3f, 4);
  const View nadir{"v", {0.0, 0.0, 2000.0}, {0.0, 0.001, 0.0}, 1.0, 4, 4};
  const Film film = finished(s, nadir);
  const Medium medium(s.haze);
  double tau = 0.0;
  for (int c = 0; c < kMediumComponents; ++c)
    if (medium.component(c).present)
      tau += (medium.vertical_depth(c, 0.0) - medium.vertical_depth(c, 2000.0)) *
             medium.component(c).extinction[kGreen];
  EXPECT_NEAR(mean(film, layer(AtmospherePart::transmittance, 3)), std::exp(-tau), 1e-3);
  EXPECT_LT(std::exp(-tau), 0.8);  // a test of the air, not of 1
}

// Per pixel, where the pixel's samples share one transmittance (a pixel straddling the
// horizon averages samples that reach the ground and samples that do not, and a mean of
// products is not a product of means): ground seen from 300 m, 20 to 60 degrees below level.
TEST(AtmosphereLayers, ApparentIsPathPlusTransmittanceTimesSurface) {
  const Scene s = layered_scene(5000.0, 15.0, 0.3f, 16);
  const View ground{"v", {0.0, 0.0, 300.0}, {0.0, 357.5, 0.0}, 40.0, 16, 16};
  const Film film = finished(s, ground);
  double path_sum = 0.0, apparent_sum = 0.0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const Vec3 apparent = rec709_to_xyz(Vec3(film.rgb(x, y)));  // the parts are X, Y, Z
      for (int c = 0; c < 3; ++c) {
        const float path = film.band(x, y, layer(AtmospherePart::path, c));
        const float t = film.band(x, y, layer(AtmospherePart::transmittance, c));
        const float surface = film.band(x, y, layer(AtmospherePart::surface, c));
        // (a pixel's mean may be below zero at 16 samples: the control variates' noise)
        EXPECT_NEAR(path + t * surface, apparent[c], 1e-4 * std::abs(apparent[c]) + 1e-3)
            << x << ", " << y << " channel " << c;
      }
      path_sum += film.band(x, y, layer(AtmospherePart::path, 1));
      apparent_sum += apparent.y;
    }
  EXPECT_GT(path_sum, 0.05 * apparent_sum);  // the air adds light at 5 km
}

// Where the view meets no surface, under the one atmosphere all of its light is the air's:
// space is black.
TEST(AtmosphereLayers, TheSkyIsAllPathRadiance) {
  const Scene s = layered_scene(10000.0, 35.0, 0.3f, 4);
  const View up{"v", {0.0, 0.0, 100.0}, {0.0, 1000.0, 600.0}, 20.0, 8, 8};
  const Film film = finished(s, up);
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      ASSERT_FALSE(std::isfinite(film.depth(x, y)));
      EXPECT_EQ(film.band(x, y, layer(AtmospherePart::surface, 1)), 0.0f);
      const double luminance = rec709_to_xyz(Vec3(film.rgb(x, y))).y;  // the image's Y
      EXPECT_NEAR(film.band(x, y, layer(AtmospherePart::path, 1)), luminance, 1e-4 * luminance);
    }
}

// Light that crossed many leaves is a saturated green, outside Rec. 709's gamut (R and B below
// zero): the parts are in X, Y, Z, so every part and ratio of it stays at or above zero.
TEST(AtmosphereLayers, ASaturatedGreenKeepsEveryPartNonNegative) {
  Spectrum green = Spectrum::constant(0.0f);
  for (int k = 0; k < kSpectrumBins; ++k)
    if (bin_start(k) >= 520.0 && bin_start(k) < 560.0) green[k] = 1.0f;
  ASSERT_LT(std::min(spectrum_to_rgb(green).x, spectrum_to_rgb(green).z), 0.0f);
  AtmosphereSample sample{green * 0.1f, green * 0.9f, green * 2.0f, green, green * 0.5f};
  std::vector<float> layers(kAtmosphereParts * 3);
  atmosphere_layer_values(sample, {}, layers.data());
  for (std::size_t i = 0; i < layers.size(); ++i) EXPECT_GE(layers[i], 0.0f) << i;
  // Its transmittance lets through 0.9 of the green bins: a positive share of white in Y.
  EXPECT_GT(layers[atmosphere_layer(AtmospherePart::transmittance, 1, 0)], 0.0f);
  EXPECT_NEAR(layers[atmosphere_layer(AtmospherePart::path, 1, 0)], spectrum_to_xyz(green).y * 0.1f,
              1e-3f * spectrum_to_xyz(green).y);
}

}  // namespace
}  // namespace landsim::renderer
