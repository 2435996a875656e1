#include "scenes/scenario/solar_position.h"

#include <gtest/gtest.h>

namespace landsim::scenes {
namespace {

// Expected values from geometry alone: at solar noon the elevation is 90 - latitude +
// declination (+23.44 at the June solstice, about 0 at the equinox).
TEST(SolarPosition, NoonAtTheSolstice) {
  const SolarPosition p = solar_position(2026, 6, 21, 12.0, 51.48, 0.0);  // Greenwich, 12:00 UTC
  EXPECT_NEAR(p.elevation_deg, 90.0 - 51.48 + 23.44, 0.5);
  EXPECT_NEAR(p.azimuth_deg, 180.0, 2.0);  // due south
}

TEST(SolarPosition, EquinoxAtTheEquatorIsOverhead) {
  const SolarPosition p = solar_position(2026, 3, 20, 12.0, 0.0, 0.0);
  EXPECT_GT(p.elevation_deg, 87.0);
}

TEST(SolarPosition, MorningSunIsInTheEastAndLow) {
  const SolarPosition p = solar_position(2026, 9, 23, 7.0, 0.0, 0.0);  // an hour after sunrise
  EXPECT_NEAR(p.elevation_deg, 15.0, 2.0);
  EXPECT_NEAR(p.azimuth_deg, 90.0, 3.0);
  const SolarPosition night = solar_position(2026, 9, 23, 0.0, 0.0, 0.0);
  EXPECT_LT(night.elevation_deg, 0.0);
}

}  // namespace
}  // namespace landsim::scenes
