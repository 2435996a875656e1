#include "trees/weber_penn/shape_ratio.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace landsim::trees::weber_penn {
namespace {

// Expected values computed by hand from the formulas printed in section 4.3.
TEST(ShapeRatio, EveryShapeAtKnownRatios) {
  const double pi = std::numbers::pi;
  EXPECT_DOUBLE_EQ(shape_ratio(kConical, 0.25), 0.2 + 0.8 * 0.25);
  EXPECT_DOUBLE_EQ(shape_ratio(kSpherical, 0.5), 1.0);
  EXPECT_NEAR(shape_ratio(kSpherical, 0.25), 0.2 + 0.8 * std::sin(pi / 4), 1e-12);
  EXPECT_NEAR(shape_ratio(kHemispherical, 1.0), 1.0, 1e-12);
  EXPECT_NEAR(shape_ratio(kHemispherical, 0.5), 0.2 + 0.8 * std::sin(pi / 4), 1e-12);
  EXPECT_DOUBLE_EQ(shape_ratio(kCylindrical, 0.1), 1.0);
  EXPECT_DOUBLE_EQ(shape_ratio(kTaperedCylindrical, 0.0), 0.5);
  EXPECT_DOUBLE_EQ(shape_ratio(kTaperedCylindrical, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(shape_ratio(kFlame, 0.35), 0.5);
  EXPECT_NEAR(shape_ratio(kFlame, 0.85), 0.5, 1e-12);
  EXPECT_NEAR(shape_ratio(kFlame, 0.7), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(shape_ratio(kInverseConical, 0.5), 0.6);
  EXPECT_NEAR(shape_ratio(kTendFlame, 0.35), 0.75, 1e-12);
  EXPECT_NEAR(shape_ratio(kTendFlame, 1.0), 0.5, 1e-12);
}

TEST(ShapeRatio, EnvelopeIsZeroOutsideAndOneAtThePeak) {
  const Envelope e{0.5, 0.3, 2.0, 0.5};
  EXPECT_EQ(shape_ratio(kEnvelope, -0.01, e), 0.0);
  EXPECT_EQ(shape_ratio(kEnvelope, 1.01, e), 0.0);
  EXPECT_NEAR(shape_ratio(kEnvelope, 0.7, e), 1.0, 1e-12);  // peak at ratio 1 - PruneWidthPeak
  EXPECT_NEAR(shape_ratio(kEnvelope, 0.35, e), std::pow(0.5, 0.5), 1e-12);  // upper branch
  EXPECT_NEAR(shape_ratio(kEnvelope, 0.85, e), std::pow(0.5, 2.0), 1e-12);  // lower branch
  EXPECT_NEAR(shape_ratio(kEnvelope, 1.0, e), 0.0, 1e-12);
}

TEST(ShapeRatio, EnvelopeIsContinuousAtThePeak) {
  // The erratum: as printed the lower branch divides by (1 - peak) and jumps here.
  for (double peak : {0.2, 0.5, 0.8}) {
    const Envelope e{0.5, peak, 1.5, 0.7};
    const double at = 1.0 - peak;
    EXPECT_NEAR(shape_ratio(kEnvelope, at - 1e-9, e), shape_ratio(kEnvelope, at + 1e-9, e), 1e-6)
        << peak;
  }
}

}  // namespace
}  // namespace landsim::trees::weber_penn
