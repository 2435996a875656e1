// SkyIrradiance (renderer/atmosphere/sky_irradiance.h): the model's irradiance is the
// integral of its own integrand (what makes the control variate unbiased), a uniform sky of
// radiance 1 gives a plane the textbook pi (up) and pi / 2 (a wall), and the integrand is the
// sky's radiance times the cosine where a plane sees the sky, nothing below the horizon.
#include "renderer/atmosphere/sky_irradiance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/counter_rng.h"

namespace landsim::renderer {
namespace {

constexpr double kPi = std::numbers::pi;
const Vec3f kSun = normalize(Vec3f{0.8f, 0.2f, 0.35f});

// A sky brighter toward the sun and the horizon, different in every bin.
Spectrum hazy(const Vec3f& d) {
  Spectrum s;
  for (int k = 0; k < kSpectrumBins; ++k)
    s[k] = (1.0f + 0.05f * static_cast<float>(k)) *
           (0.3f + 4.0f * std::pow(std::max(0.0f, dot(d, kSun)), 8.0f)) / (0.2f + d.z);
  return s;
}

Vec3f uniform_sphere(float u1, float u2) {
  const float z = 1.0f - 2.0f * u1, r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float a = 2.0f * std::numbers::pi_v<float> * u2;
  return {r * std::cos(a), r * std::sin(a), z};
}

TEST(SkyIrradiance, IrradianceIsTheIntegralOfItsIntegrand) {
  const SkyIrradiance model(hazy);
  const Vec3f normals[] = {{0.0f, 0.0f, 1.0f},
                           normalize(Vec3f{0.5f, -0.2f, 0.8f}),
                           normalize(Vec3f{-0.9f, 0.1f, 0.3f}),
                           {0.0f, 1.0f, 0.0f},
                           normalize(Vec3f{0.3f, 0.4f, -0.6f})};
  constexpr int kSamples = 400000;
  for (const Vec3f& n : normals) {
    const int bin = model.bin_of(n);
    for (int k : {0, 31}) {
      double sum = 0.0, square = 0.0;
      for (int i = 0; i < kSamples; ++i) {
        const auto u = CounterRng(3, static_cast<std::uint32_t>(i), 0).uniform2(0);
        const double g = model.integrand(bin, n, uniform_sphere(u[0], u[1]))[k] * 4.0 * kPi;
        sum += g;
        square += g * g;
      }
      const double mean = sum / kSamples;
      const double error = std::sqrt((square / kSamples - mean * mean) / kSamples);
      const double exact = model.irradiance(bin, n)[k];
      EXPECT_NEAR(mean, exact, 4.0 * error + 1e-6) << "normal " << n.x << " " << n.y << " " << n.z;
      EXPECT_GT(std::abs(exact), 20.0 * error);  // the check has power
    }
  }
}

TEST(SkyIrradiance, AUniformSkyGivesAPlaneItsCosineIntegral) {
  const SkyIrradiance model([](const Vec3f&) { return Spectrum::constant(1.0f); });
  const Vec3f up{0.0f, 0.0f, 1.0f}, wall{1.0f, 0.0f, 0.0f}, down{0.0f, 0.0f, -1.0f};
  // The bins' centres lean up to 7.5 degrees from these normals: the cells they count differ
  // from the plane's own hemisphere only where the cosine is near zero (a floor facing down
  // counts a sliver of the horizon, at cosines of -0.13 at most).
  EXPECT_NEAR(model.irradiance(model.bin_of(up), up)[5], kPi, 0.01 * kPi);
  EXPECT_NEAR(model.irradiance(model.bin_of(wall), wall)[5], kPi / 2.0, 0.02 * kPi);
  EXPECT_NEAR(model.irradiance(model.bin_of(down), down)[5], 0.0, 0.02);
}

TEST(SkyIrradiance, TheIntegrandIsTheCellsRadianceTimesTheCosine) {
  const SkyIrradiance model(hazy);
  const Vec3f n = normalize(Vec3f{0.2f, 0.1f, 0.9f});
  const int bin = model.bin_of(n);
  const Vec3f toward = normalize(Vec3f{0.3f, -0.4f, 0.7f});
  // The cell's radiance is the sky's at its centre, 5.6 degrees across at most from here.
  EXPECT_NEAR(model.integrand(bin, n, toward)[7] / dot(n, toward), hazy(toward)[7],
              0.1 * hazy(toward)[7]);
  EXPECT_EQ(model.integrand(bin, n, Vec3f{0.6f, 0.0f, -0.8f})[7], 0.0f);  // below the horizon
  const Vec3f tilted = normalize(Vec3f{0.6f, 0.0f, 0.8f});
  const Vec3f behind = normalize(Vec3f{-0.9f, 0.0f, 0.436f});  // cosine -0.19
  EXPECT_EQ(model.integrand(model.bin_of(tilted), tilted, behind)[7], 0.0f);
}

}  // namespace
}  // namespace landsim::renderer
