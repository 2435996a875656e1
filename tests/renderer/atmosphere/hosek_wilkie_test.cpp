// The Hosek-Wilkie sky and sun against an independent evaluation of the published tables
// (tests/renderer/hosek_wilkie_reference.py), and against measured daylight.
#include "renderer/atmosphere/hosek_wilkie.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "renderer/atmosphere/preetham.h"
#include "renderer/atmosphere/sky.h"
#include "renderer/spectra/colour_matching.h"
#include "renderer/spectra/spectral_colour.h"
#include "tests/support/run_program.h"

namespace landsim::renderer {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

std::string reference_output() {
  const testing::TempDir dir;
  const testing::ProgramResult r = testing::run_command(
      std::string(LANDSIM_PYTHON) + " " + LANDSIM_SOURCE_DIR +
          "/tests/renderer/hosek_wilkie_reference.py " + LANDSIM_SOURCE_DIR + "/data/sky",
      dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.out;
}

void expect_within(const Vec3& got, const Vec3& want, double tolerance, const std::string& where) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got[c] / want[c], 1.0, tolerance)
        << where << " channel " << c << ": " << got[c] << " against " << want[c];
}

TEST(HosekWilkie, AgreesWithAnIndependentEvaluationOfThePublishedTables) {
  std::istringstream lines(reference_output());
  std::string kind;
  int sky_lines = 0, sun_lines = 0;
  while (lines >> kind) {
    if (kind == "sky") {
      double elevation, turbidity, albedo, theta, gamma;
      Vec3 want;
      lines >> elevation >> turbidity >> albedo >> theta >> gamma >> want.x >> want.y >> want.z;
      const HosekWilkieSky sky(elevation * kDeg, turbidity, {albedo, albedo, albedo});
      expect_within(sky.radiance(theta * kDeg, gamma * kDeg), want, 0.005,
                    "sky at sun elevation " + std::to_string(elevation) + ", turbidity " +
                        std::to_string(turbidity) + ", theta " + std::to_string(theta) +
                        ", gamma " + std::to_string(gamma));
      ++sky_lines;
    } else {
      double elevation, turbidity;
      Vec3 want;
      lines >> elevation >> turbidity >> want.x >> want.y >> want.z;
      const HosekWilkieSun sun(elevation * kDeg, turbidity);
      expect_within(sun.irradiance(0.00465), want, 0.005,
                    "sun at elevation " + std::to_string(elevation) + ", turbidity " +
                        std::to_string(turbidity));
      ++sun_lines;
    }
  }
  // 5 solar elevations x 3 turbidities x 20 directions, and the sun at each.
  EXPECT_EQ(sky_lines, 300);
  EXPECT_EQ(sun_lines, 15);
}

Sun sun_at(double elevation_deg, double azimuth_deg = 180.0) {
  Sun s;
  const double el = elevation_deg * kDeg, az = azimuth_deg * kDeg;
  s.direction = {std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), std::sin(el)};
  return s;
}

// Absolute light at two stated conditions, from the published formulas evaluated apart from
// the renderer and pasted here. Derivation: tests/renderer/hosek_wilkie_reference.py's
// functions (sky_parameters, perez_extended, sun_irradiance; written from the papers, sharing
// no code with renderer/) at ground albedo 0.2, the zenith (theta 0, gamma 90 degrees less
// the elevation) and a disc of 0.00465 rad:
//   elevation 60, turbidity 2.5: zenith 2161.8 3503.2 7036.4 cd/m2 (Y 3473.1),
//                                sun 103781 85367 65086 lux (Y 87817);
//   elevation 30, turbidity 4:   zenith 1452.5 2468.8 4498.0 cd/m2 (Y 2399.2),
//                                sun 90467 69616 46185 lux (Y 72357).
// Preetham, Shirley & Smits 1999, appendix: Y_z = (4.0453 T - 4.9710) tan chi - 0.2155 T +
// 2.4192 kcd/m2, chi = (4/9 - T/120)(pi - 2 theta_s): 8.192966 (60, 2.5) and 6.705416 (30, 4).
// The renderer's spectral sky (the spectral tables) keeps the RGB tables' luminance within
// 2.5% (docs/SPECTRAL.md).
TEST(AbsoluteLight, ZenithAndSunAtStatedConditionsMatchThePublishedFormulas) {
  struct Condition {
    double elevation, turbidity;
    Vec3 zenith, sun;
    double preetham_zenith_kcd;
  };
  for (const Condition& c :
       {Condition{60.0, 2.5, {2161.8, 3503.2, 7036.4}, {103781, 85367, 65086}, 8.192966},
        Condition{30.0, 4.0, {1452.5, 2468.8, 4498.0}, {90467, 69616, 46185}, 6.705416}}) {
    const std::string at = "elevation " + std::to_string(c.elevation);
    const double e = c.elevation * kDeg;
    const HosekWilkieSky sky(e, c.turbidity, {0.2, 0.2, 0.2});
    expect_within(sky.radiance(0.0, std::numbers::pi / 2 - e), c.zenith, 0.001, "zenith, " + at);
    expect_within(HosekWilkieSun(e, c.turbidity).irradiance(0.00465), c.sun, 0.001, "sun, " + at);
    const PreethamSky preetham(sun_at(c.elevation).direction, c.turbidity);
    EXPECT_NEAR(preetham.zenith_luminance_kcd(), c.preetham_zenith_kcd, 1e-5) << at;
    // What the renderer's sky gives at the zenith, through its spectral tables.
    Sky model;
    model.turbidity = c.turbidity;
    Sun sun = sun_at(c.elevation);
    sun.irradiance = sun_irradiance(model, c.elevation, sun.angular_radius);
    const SkyModel rendered(model, sun, Vec3f{0.2f, 0.2f, 0.2f}, SpectralGrid{});
    const double zenith_y =
        rec709_luminance(Vec3(spectrum_to_rgb(rendered.spectral_radiance({0.0f, 0.0f, 1.0f}))));
    EXPECT_NEAR(zenith_y / rec709_luminance(c.zenith), 1.0, 0.025) << at;
    EXPECT_NEAR(rec709_luminance(Vec3(sun.irradiance)) / rec709_luminance(c.sun), 1.0, 0.001) << at;
  }
}

TEST(HosekWilkie, ClearSkyGlobalIlluminanceMatchesMeasuredDaylight) {
  // The IES clear-sky daylight availability model, fit to measured daylight (IESNA Lighting
  // Handbook, 9th ed., chapter 8; docs/ATMOSPHERE.md): sun at 60 degrees, direct normal
  // 127.5 klx x exp(-0.21 / sin 60) = 100.0 klx, horizontal direct 86.6 klx, sky 0.8 + 15.5
  // sin(60)^0.5 = 15.2 klx: global 101.8 klx.
  Sky sky;
  sky.turbidity = 2.5;
  Sun sun = sun_at(60.0);
  sun.irradiance = sun_irradiance(sky, 60.0, sun.angular_radius);
  const SkyModel model(sky, sun, Vec3f{0.2f, 0.2f, 0.2f}, SpectralGrid{});
  const double direct = rec709_luminance(Vec3(sun.irradiance)) * std::sin(60.0 * kDeg);
  const double diffuse = rec709_luminance(Vec3(model.horizontal_irradiance()));
  EXPECT_NEAR((direct + diffuse) / 101800.0, 1.0, 0.15) << direct << " + " << diffuse;
  EXPECT_NEAR(diffuse / 15200.0, 1.0, 0.3);
}

TEST(HosekWilkie, SkyIsBluishWhiteAtTheHorizonAndBlueAtTheZenith) {
  for (double elevation : {25.0, 45.0, 70.0}) {  // lower suns warm the horizon (physical)
    Sky sky;
    sky.turbidity = 3.0;
    const SkyModel model(sky, sun_at(elevation, 180.0), Vec3f{0.18f, 0.17f, 0.12f}, SpectralGrid{});
    const Vec3f zenith = model.radiance({0.0f, 0.0f, 1.0f});
    EXPECT_GT(zenith.z, 1.3f * zenith.x) << elevation;
    // Away from the sun, 4 degrees up: blue at least equals red (Preetham's horizon is pink).
    const float c = std::cos(4.0f * static_cast<float>(kDeg)),
                s = std::sin(4.0f * static_cast<float>(kDeg));
    const Vec3f horizon = model.radiance({0.0f, c, s});  // north, the sun in the south
    EXPECT_GE(horizon.z, horizon.x) << elevation;
  }
}

TEST(HosekWilkie, SunDiscIsLimbDarkenedAndGivesTheSunsIrradiance) {
  const HosekWilkieSun model(40.0 * kDeg, 3.0);
  const Vec3 centre = model.radiance(1.0), limb = model.radiance(0.1);
  EXPECT_LT(rec709_luminance(limb), 0.6 * rec709_luminance(centre));
  EXPECT_GT(limb.x / limb.z, centre.x / centre.z);  // the limb is redder
  // The renderer's disc, integrated over its solid angle, gives back the scene's irradiance.
  Sky sky;
  Sun sun = sun_at(40.0);
  sun.irradiance = sun_irradiance(sky, 40.0, sun.angular_radius);
  const SkyModel sky_model(sky, sun, Vec3f{0.2f, 0.2f, 0.2f}, SpectralGrid{});
  const Vec3 axis = normalize(sun.direction);
  Vec3 t, b;
  orthonormal_basis(axis, t, b);
  Vec3 sum{};
  constexpr int n = 400;
  const double r = sun.angular_radius * 1.02, cell = (2.0 * r / n) * (2.0 * r / n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = -r + (i + 0.5) * 2.0 * r / n, v = -r + (j + 0.5) * 2.0 * r / n;
      sum += Vec3(sky_model.sun_radiance(Vec3f(normalize(axis + t * u + b * v)))) * cell;
    }
  expect_within(sum, Vec3(sun.irradiance), 0.01, "disc integral");
  EXPECT_EQ(max_component(sky_model.sun_radiance(Vec3f(normalize(axis + t * (2.0 * r))))), 0.0f);
}

}  // namespace
}  // namespace landsim::renderer
