#include "renderer/atmosphere/sky.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/counter_rng.h"

namespace landsim::renderer {
namespace {

Sky gradient(Vec3f zenith, Vec3f horizon) {
  Sky s;
  s.model = SkyKind::gradient;
  s.zenith_radiance = zenith;
  s.horizon_radiance = horizon;
  return s;
}

Sun sun_at(double elevation_deg, double azimuth_deg = 180.0) {
  Sun s;
  const double el = elevation_deg * std::numbers::pi / 180.0,
               az = azimuth_deg * std::numbers::pi / 180.0;
  s.direction = {std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), std::sin(el)};
  return s;
}

Vec3f dir(double elevation_deg, double azimuth_deg) {
  return Vec3f(sun_at(elevation_deg, azimuth_deg).direction);
}

float lum(const Vec3f& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

TEST(SkyModel, UniformSkyGivesPiTimesRadianceOnAHorizontalSurface) {
  const SkyModel model(gradient({0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}), Sun{}, Vec3f{},
                       SpectralGrid{});
  EXPECT_NEAR(model.horizontal_irradiance().x, std::numbers::pi * 0.5, 2e-3);
}

TEST(SkyModel, GradientRunsFromHorizonToZenith) {
  const SkyModel model(gradient({0.1f, 0.2f, 0.4f}, {0.6f, 0.6f, 0.6f}), Sun{}, Vec3f{},
                       SpectralGrid{});
  EXPECT_NEAR(model.radiance({0.0f, 0.0f, 1.0f}).z, 0.4f, 1e-6);
  EXPECT_NEAR(model.radiance({1.0f, 0.0f, 0.0f}).z, 0.6f, 1e-6);
}

TEST(SkyModel, BelowTheHorizonIsASunlitPlainOfTheGroundAlbedo) {
  Sun sun = sun_at(30.0);
  sun.irradiance = {2.0f, 2.0f, 2.0f};
  const SkyModel model(gradient({0.2f, 0.2f, 0.2f}, {0.2f, 0.2f, 0.2f}), sun,
                       Vec3f{0.5f, 0.5f, 0.5f}, SpectralGrid{});
  const float e = 2.0f * 0.5f + std::numbers::pi_v<float> * 0.2f;
  EXPECT_NEAR(model.radiance({0.0f, 0.6f, -0.8f}).x, 0.5f * e / std::numbers::pi_v<float>, 2e-3);
}

TEST(SkyModel, NoSkyLeavesTheSunAlone) {
  Sky none;
  none.model = SkyKind::none;  // its gradient radiances, left at their defaults, must not show
  Sun sun = sun_at(50.0);
  sun.irradiance = {3.0f, 3.0f, 3.0f};
  const SkyModel model(none, sun, Vec3f{0.5f, 0.5f, 0.5f}, SpectralGrid{});
  EXPECT_EQ(model.horizontal_irradiance().y, 0.0f);
  EXPECT_EQ(lum(model.radiance(dir(10.0, 90.0))), 0.0f);
  EXPECT_EQ(max_component(model.spectral_radiance(dir(60.0, 200.0))), 0.0f);
  EXPECT_GT(max_component(model.sun_spectral_irradiance()), 0.0f);
  // Sampling stays defined: a direction above the horizon with a finite density.
  float pdf = 0.0f;
  const Vec3f d = model.sample(0.3f, 0.7f, pdf);
  EXPECT_GT(d.z, 0.0f);
  EXPECT_TRUE(std::isfinite(pdf) && pdf > 0.0f);
}

Sky model_sky(SkyKind kind, double turbidity = 3.0) {
  Sky s;
  s.model = kind;
  s.turbidity = turbidity;
  return s;
}

TEST(PreethamSky, BlueBrightTowardTheSunAndAtTheHorizon) {
  const Sky sky = model_sky(SkyKind::preetham);
  const SkyModel model(sky, sun_at(40.0, 180.0), Vec3f{}, SpectralGrid{});
  const Vec3f zenith = model.radiance(dir(90.0, 0.0));
  EXPECT_GT(zenith.z, zenith.x);  // blue
  EXPECT_GT(lum(model.radiance(dir(45.0, 180.0))),
            2.0f * lum(model.radiance(dir(45.0, 0.0))));        // circumsolar
  EXPECT_GT(lum(model.radiance(dir(3.0, 90.0))), lum(zenith));  // horizon brightening
  // A clear sky's zenith is a few kcd/m^2.
  EXPECT_GT(lum(zenith), 1000.0f);
  EXPECT_LT(lum(zenith), 20000.0f);
}

TEST(PreethamSky, HazierSkiesAreWhiter) {
  const Sky clear = model_sky(SkyKind::preetham, 2.0), hazy = model_sky(SkyKind::preetham, 8.0);
  const Vec3f c = SkyModel(clear, sun_at(50.0), Vec3f{}, SpectralGrid{}).radiance(dir(60.0, 0.0));
  const Vec3f h = SkyModel(hazy, sun_at(50.0), Vec3f{}, SpectralGrid{}).radiance(dir(60.0, 0.0));
  EXPECT_GT(c.z / c.x, h.z / h.x);
}

TEST(SkyModel, ImportanceSamplingIsUnbiased) {
  Sky sky;
  const SkyModel model(sky, sun_at(30.0, 200.0), Vec3f{0.2f, 0.2f, 0.2f}, SpectralGrid{});
  // Reference: the upper hemisphere's integral of luminance by the midpoint rule (below the
  // horizon the path tracer meets the plain as a surface: renderer/transport/plain.h).
  double reference = 0.0;
  const int n = 400;
  for (int i = 0; i < n / 2; ++i) {
    const double theta = std::numbers::pi * (i + 0.5) / n;
    for (int j = 0; j < 2 * n; ++j) {
      const double phi = 2.0 * std::numbers::pi * (j + 0.5) / (2 * n);
      const Vec3f d{static_cast<float>(std::sin(theta) * std::cos(phi)),
                    static_cast<float>(std::sin(theta) * std::sin(phi)),
                    static_cast<float>(std::cos(theta))};
      reference += lum(model.radiance(d)) * std::sin(theta);
    }
  }
  reference *= (std::numbers::pi / n) * (2.0 * std::numbers::pi / (2 * n));
  double estimate = 0.0;
  const int samples = 200000;
  for (int k = 0; k < samples; ++k) {
    const CounterRng r(3, static_cast<std::uint64_t>(k), 0);
    float pdf = 0.0f;
    const Vec3f d = model.sample(r.uniform(0), r.uniform(1), pdf);
    ASSERT_GT(pdf, 0.0f);
    ASSERT_GE(d.z, 0.0f);
    ASSERT_NEAR(pdf, model.pdf(d), 1e-3f * pdf + 1e-6f);
    estimate += lum(model.radiance(d)) / pdf;
  }
  estimate /= samples;
  EXPECT_NEAR(estimate / reference, 1.0, 0.01);
}

class SunIrradiance : public ::testing::TestWithParam<SkyKind> {};

TEST_P(SunIrradiance, LowerSunIsDimmerAndRedder) {
  const double r = Sun{}.angular_radius;
  const auto sun = [&](double elevation, double turbidity = 3.0) {
    return sun_irradiance(model_sky(GetParam(), turbidity), elevation, r);
  };
  const Vec3f high = sun(60.0);
  const Vec3f low = sun(8.0);
  EXPECT_GT(lum(high), 2.0f * lum(low));
  EXPECT_GT(low.x / low.z, high.x / high.z);
  EXPECT_GT(lum(high), 60000.0f);  // lux: a high sun in a clear sky gives about 90-100 klx
  EXPECT_LT(lum(high), 130000.0f);
  EXPECT_EQ(lum(sun(-1.0)), 0.0f);
  EXPECT_GT(lum(sun(60.0, 2.0)), lum(sun(60.0, 8.0)));  // turbidity dims it
}

INSTANTIATE_TEST_SUITE_P(BothModels, SunIrradiance,
                         ::testing::Values(SkyKind::hosek_wilkie, SkyKind::preetham));

}  // namespace
}  // namespace landsim::renderer
