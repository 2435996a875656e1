// The downwelling irradiance (docs/SENSOR.md "Irradiance and reflectance"): the sun's beam on a
// horizontal surface and the sky's hemisphere, through the haze above the surface.
#include "renderer/atmosphere/downwelling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "renderer/atmosphere/sky.h"
#include "renderer/spectra/colour_matching.h"
#include "renderer/spectra/spectral_colour.h"
#include "tests/renderer/test_scenes.h"

namespace landsim::renderer {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

Scene sunny(double elevation_deg) {
  Scene s;
  s.sun.direction = {0.0, -std::cos(elevation_deg * kDeg), std::sin(elevation_deg * kDeg)};
  s.sun.irradiance = sun_irradiance(s.sky, elevation_deg, s.sun.angular_radius);
  return s;
}

TEST(Downwelling, SunOnTheHorizontalAndTheSkysHemisphere) {
  const Scene s = sunny(35.0);
  const Downwelling e = downwelling_irradiance(s, 0.0);
  const SkyModel sky(s.sky, s.sun, s.ground.plain_albedo(), s.spectral_grid);
  // The beam: the sun's irradiance times the sine of its elevation, bin by bin.
  for (int k = 0; k < kSpectrumBins; ++k)
    EXPECT_NEAR(e.direct[k], sky.sun_spectral_irradiance()[k] * std::sin(35.0 * kDeg),
                1e-4 * sky.sun_spectral_irradiance()[k]);
  // The sky: its spectral radiance x cos(theta) over the hemisphere, by another quadrature
  // (midpoints of one-degree steps in theta and phi).
  const Spectrum want = testing::sky_hemisphere_irradiance(sky);
  for (int k = 0; k < kSpectrumBins; k += 3) EXPECT_NEAR(e.diffuse[k] / want[k], 1.0, 0.005) << k;
  // ...and about the sky model's own RGB integral (the RGB and spectral fits differ a little).
  const Vec3f diffuse = spectrum_to_rgb(e.diffuse), model = sky.horizontal_irradiance();
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(diffuse[c] / model[c], 1.0, 0.06) << c;
}

TEST(Downwelling, HazeDimsTheBeamByItsOpticalDepth) {
  Scene s = sunny(30.0);
  const Downwelling clear = downwelling_irradiance(s, 100.0);
  s.haze.enabled = true;
  s.haze.visibility = 5000.0;
  s.haze.scale_height = 800.0;
  s.haze.base_height = 0.0;
  s.haze.molecular = false;  // the air scatters only on the way to surfaces, never the sun's
  s.haze.angstrom = 0.0;     // grey: one optical depth for every bin
  const Downwelling hazy = downwelling_irradiance(s, 100.0);
  // Extinction 3.912 / V at the base, falling with e^(-z / H): from z up along the sun, the
  // optical depth is 3.912 / V x H x e^(-z / H) / sin(elevation).
  const double depth = 3.912 / 5000.0 * 800.0 * std::exp(-100.0 / 800.0) / std::sin(30.0 * kDeg);
  for (int k = 0; k < kSpectrumBins; k += 5)
    EXPECT_NEAR(hazy.direct[k] / clear.direct[k], std::exp(-depth), 1e-4) << k;
  // Higher up there is less haze above.
  EXPECT_GT(downwelling_irradiance(s, 1500.0).direct[10], hazy.direct[10]);
}

// Aerosols that scatter nearly all they take from the beam (albedo 0.99) send it down as
// diffuse light: thicker haze, more of it (before, the haze only absorbed, and the diffuse
// light fell with the beam). The global irradiance falls by what the haze reflects up.
TEST(Downwelling, DiffuseLightRisesAsTheHazeThickens) {
  Scene s = sunny(35.0);
  s.ground.albedo = {0.15f, 0.13f, 0.09f};
  s.haze.enabled = true;
  s.haze.albedo = {0.99f, 0.99f, 0.99f};
  double last_diffuse = 0.0, last_total = 1e30;
  // Issue 57's range: vertical optical depth 0.12 to 0.94. (Much thicker, the diffuse light
  // falls again: what is scattered down is scattered again, and absorbed a little each time.)
  for (const double v : {40000.0, 10000.0, 5000.0}) {
    s.haze.visibility = v;
    const Downwelling e = downwelling_irradiance(s, 0.0);
    const double diffuse = rec709_luminance(Vec3(spectrum_to_rgb(e.diffuse)));
    const double total = rec709_luminance(Vec3(spectrum_to_rgb(e.total())));
    EXPECT_GT(diffuse, 1.1 * last_diffuse) << v;
    EXPECT_LT(total, last_total) << v;
    last_diffuse = diffuse;
    last_total = total;
  }
}

TEST(Downwelling, NoBeamFromASunBelowTheHorizon) {
  Scene s = sunny(20.0);
  s.sun.direction.z = -s.sun.direction.z;
  EXPECT_EQ(max_component(downwelling_irradiance(s, 0.0).direct), 0.0f);
}

}  // namespace
}  // namespace landsim::renderer
