#include "trees/weber_penn/taper.h"

#include <gtest/gtest.h>

#include <cmath>

namespace landsim::trees::weber_penn {
namespace {

constexpr double kLength = 10.0;
constexpr double kRadius = 0.5;

TEST(Taper, ZeroIsACylinder) {
  for (double z : {0.0, 3.0, 9.9})
    EXPECT_DOUBLE_EQ(stem_radius(z, kLength, kRadius, 0.0, 0.0), kRadius);
}

TEST(Taper, OneIsAConeToAPoint) {
  EXPECT_DOUBLE_EQ(stem_radius(0.0, kLength, kRadius, 1.0, 0.0), kRadius);
  EXPECT_DOUBLE_EQ(stem_radius(5.0, kLength, kRadius, 1.0, 0.0), 0.25);
  EXPECT_NEAR(stem_radius(10.0, kLength, kRadius, 1.0, 0.0), 0.0, 1e-12);
}

TEST(Taper, FractionalBelowOneIsAPartialCone) {
  EXPECT_DOUBLE_EQ(stem_radius(5.0, kLength, kRadius, 0.5, 0.0), 0.5 * (1.0 - 0.5 * 0.5));
}

TEST(Taper, OneToTwoEndsInASphere) {
  // nTaper 2: a cylinder (unit taper 0) with a hemispherical end of the stem's radius.
  EXPECT_DOUBLE_EQ(stem_radius(5.0, kLength, kRadius, 2.0, 0.0), kRadius);
  EXPECT_NEAR(stem_radius(kLength - 0.25, kLength, kRadius, 2.0, 0.0), std::sqrt(0.25 - 0.0625),
              1e-12);
  EXPECT_NEAR(stem_radius(kLength, kLength, kRadius, 2.0, 0.0), 0.0, 1e-12);
  // nTaper 1.5: half a cone (unit taper 0.5) and the end rounded.
  const double r_mid = kRadius * (1.0 - 0.5 * 0.5);
  EXPECT_DOUBLE_EQ(stem_radius(5.0, kLength, kRadius, 1.5, 0.0), r_mid);
}

TEST(Taper, AboveTwoIsPeriodic) {
  // nTaper 3 (depth 1): spheres of the stem radius end to end. 10 m of 0.5 m radius holds
  // ten spheres; at a sphere's centre the full radius, where two meet nothing.
  const double taper = 2.9999;
  EXPECT_NEAR(stem_radius(kLength - 0.5, kLength, kRadius, taper, 0.0), kRadius, 1e-3);
  EXPECT_NEAR(stem_radius(kLength - 1.0, kLength, kRadius, taper, 0.0), 0.0, 1e-3);
  EXPECT_NEAR(stem_radius(kLength - 1.5, kLength, kRadius, taper, 0.0), kRadius, 1e-3);
  // nTaper 2.5 (depth 0.5): the pinch between spheres keeps half the radius.
  EXPECT_NEAR(stem_radius(kLength - 1.0, kLength, kRadius, 2.5, 0.0), 0.25, 1e-6);
}

TEST(Taper, FlareWidensOnlyTheBase) {
  const double flare = 0.6;
  EXPECT_NEAR(stem_radius(0.0, kLength, kRadius, 0.0, flare), kRadius * (1.0 + flare * 0.99),
              1e-12);
  EXPECT_DOUBLE_EQ(stem_radius(2.0, kLength, kRadius, 0.0, flare),
                   kRadius);  // above 1/8 of the stem
}

}  // namespace
}  // namespace landsim::trees::weber_penn
