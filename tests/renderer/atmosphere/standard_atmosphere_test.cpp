// The one atmosphere's tables (renderer/atmosphere/standard_atmosphere), checked against what
// they must obey independently of landsim: hydrostatics (the air above a height weighs its
// pressure), the luminous solar constant, and the orbit's perihelion and aphelion.
#include "renderer/atmosphere/standard_atmosphere.h"

#include <gtest/gtest.h>

#include "renderer/spectra/spectral_colour.h"

namespace landsim::renderer {
namespace {

TEST(StandardAtmosphere, TheAirAboveEachHeightWeighsItsPressure) {
  const StandardAtmosphere& a = us_standard_atmosphere();
  // Dry air's mean molecular mass and gravity falling with height as (R / (R + z))^2.
  const double m = 28.9644e-3 / 6.02214076e23, r = 6.371e6;
  // Below 21 km, 95% of the column. Above it the table's own pressures and densities part
  // (1.0% at 24.5 km, 2.4% at 33.5 km, the ideal-gas law still holding within 0.3%): a
  // finding about the AFGL file, documented in docs/ATMOSPHERE.md.
  for (std::size_t i = 0; i < 21; i += 2) {
    const double z = a.heights[i];
    // The weight of the column above z: Simpson over 100 m steps to 120 km.
    const int steps = static_cast<int>((120000.0 - z) / 100.0) & ~1;
    const double h = (120000.0 - z) / steps;
    double sum = 0.0;
    for (int j = 0; j <= steps; ++j) {
      const double y = z + j * h, g = 9.80665 * std::pow(r / (r + y), 2.0);
      sum += a.air.density(y) * m * g * (j == 0 || j == steps ? 1.0 : j % 2 == 1 ? 4.0 : 2.0);
    }
    const double weight = sum * h / 3.0;
    EXPECT_NEAR(weight / a.pressures[i], 1.0, 0.01) << z << " m";
  }
}

TEST(StandardAtmosphere, TheSunAboveTheAtmosphereHasTheLuminousSolarConstant) {
  // Darula, Kittler and Gueymard 2005 (Lighting Res. Technol. 37): 133,334 lx at 1 AU.
  const Vec3f rgb = spectrum_to_rgb(solar_irradiance_toa(1.0));
  const double y = 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z;
  EXPECT_NEAR(y / 133334.0, 1.0, 0.02) << y;
  // Nearer in January: the square of the distances' ratio.
  const double january = solar_irradiance_toa(earth_sun_distance(4))[8];
  const double july = solar_irradiance_toa(earth_sun_distance(185))[8];
  EXPECT_NEAR(january / july, std::pow(1.01671 / 0.98329, 2.0), 0.002);
}

TEST(StandardAtmosphere, TheEarthIsNearestTheSunInEarlyJanuary) {
  EXPECT_NEAR(earth_sun_distance(4), 0.98329, 3e-4);    // perihelion
  EXPECT_NEAR(earth_sun_distance(186), 1.01671, 3e-4);  // aphelion
  EXPECT_NEAR(earth_sun_distance(94), 1.0, 0.002);
}

TEST(StandardAtmosphere, OzoneAbsorbsInChappuisBandAndNotBeyondIt) {
  // The Chappuis band peaks near 600 nm, many times its strength at 450 nm.
  EXPECT_GT(ozone_cross_section(600.0), 4e-25);
  EXPECT_GT(ozone_cross_section(600.0) / ozone_cross_section(450.0), 10.0);
  EXPECT_EQ(ozone_cross_section(900.0), 0.0);
}

}  // namespace
}  // namespace landsim::renderer
