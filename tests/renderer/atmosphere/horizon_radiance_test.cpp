// The tabulated horizon agrees with the sky model it was made from, at any azimuth (the
// physical sky's brightest horizon, toward a low sun, included), for rays of any elevation.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "renderer/atmosphere/horizon_radiance.h"

namespace landsim::renderer {
namespace {

TEST(HorizonRadiance, MatchesTheSkyAtEveryAzimuth) {
  Sun sun;
  const double el = 10.0 * std::numbers::pi / 180.0;
  sun.direction = {std::cos(el), 0.0, std::sin(el)};  // low, in the east: a bright horizon
  const SkyModel sky(Sky{}, sun, Vec3f{0.2f, 0.2f, 0.2f});
  const HorizonRadiance horizon(sky);
  double worst = 0.0;
  for (int i = 0; i < 3600; ++i) {
    const double phi = 2.0 * std::numbers::pi * (i + 0.37) / 3600.0;
    const Vec3f level{static_cast<float>(std::cos(phi)), static_cast<float>(std::sin(phi)), 0.0f};
    const Vec3f exact = sky.horizon_band_radiance(level);
    // A ray climbing at 30 degrees takes the horizon of its azimuth.
    const Vec3f got = horizon.radiance(level + Vec3f{0.0f, 0.0f, 0.577f});
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(double(got[c]) - exact[c]) / exact[c]);
  }
  EXPECT_LT(worst, 1e-3);
}

TEST(HorizonRadiance, StraightUpOrDownIsTheSkysMean) {
  const SkyModel sky(Sky{}, Sun{}, Vec3f{0.2f, 0.2f, 0.2f});
  const HorizonRadiance horizon(sky);
  const Vec3f up = horizon.radiance({0.0f, 0.0f, 1.0f});
  EXPECT_EQ(up.x, sky.mean_radiance().x);
  EXPECT_EQ(up.z, sky.mean_radiance().z);
  EXPECT_EQ(horizon.radiance({0.0f, 0.0f, -1.0f}).y, sky.mean_radiance().y);
}

}  // namespace
}  // namespace landsim::renderer
