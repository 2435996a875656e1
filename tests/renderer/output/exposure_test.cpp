#include "renderer/output/exposure.h"

#include <gtest/gtest.h>

#include <cmath>

namespace landsim::renderer {
namespace {

Film grey_film(float left, float right) {
  Film film(4, 2);
  auto& rgb = film.rgb_data();
  for (int i = 0; i < 8; ++i) {
    const float v = (i % 4) < 2 ? left : right;
    rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = v;
  }
  return film;
}

TEST(Exposure, LogAverageIsTheGeometricMean) {
  EXPECT_NEAR(log_average_luminance(grey_film(100.0f, 10000.0f)), 1000.0, 1e-6 * 1000.0);
}

TEST(Exposure, AutomaticExposurePutsTheLogAverageOnTheKey) {
  const Film film = grey_film(400.0f, 6400.0f);  // log-average 1600 cd/m2
  const double ev = exposure_ev100(film, std::nullopt);
  EXPECT_NEAR(1600.0 * preview_gain(ev), kExposureKey, 1e-9);
  // Brighter scenes need a larger EV: four times the light, two stops.
  EXPECT_NEAR(exposure_ev100(grey_film(1600.0f, 25600.0f), std::nullopt) - ev, 2.0, 1e-9);
}

TEST(Exposure, AFixedEv100OverridesTheAutomaticOne) {
  EXPECT_EQ(exposure_ev100(grey_film(1.0f, 1.0f), 15.0), 15.0);
  // Sunny 16: EV100 15 brings 1.2 x 2^15 cd/m2 to the display's white.
  EXPECT_NEAR(1.2 * std::exp2(15.0) * preview_gain(15.0), 1.0, 1e-12);
}

}  // namespace
}  // namespace landsim::renderer
