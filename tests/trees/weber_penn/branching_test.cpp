#include "trees/weber_penn/branching.h"

#include <gtest/gtest.h>

#include <cmath>

namespace landsim::trees::weber_penn {
namespace {

TEST(ErrorDiffusion, KeepsTheExactTotalOverManySegments) {
  for (double value : {0.3, 0.5, 1.25, 2.0 / 3.0, 4.9}) {
    ErrorDiffusion d;
    long total = 0;
    for (int i = 0; i < 1000; ++i) {
      const int n = d.next(value);
      EXPECT_TRUE(n == static_cast<int>(std::floor(value)) ||
                  n == static_cast<int>(std::ceil(value)));
      total += n;
    }
    EXPECT_NEAR(static_cast<double>(total), 1000.0 * value, 0.5) << value;
  }
}

TEST(ErrorDiffusion, SpreadsHalvesEvenly) {
  ErrorDiffusion d;
  EXPECT_EQ(d.next(0.5), 1);  // 0.5 rounds up, then the carried -0.5 holds the next back
  EXPECT_EQ(d.next(0.5), 0);
  EXPECT_EQ(d.next(0.5), 1);
}

TEST(ChildCount, FormulasOfSection4_3) {
  EXPECT_DOUBLE_EQ(child_count(0, 50, 13.0, 0.0, 0.0, 0.0), 50.0);
  // Level 1: a stem 3 m long on a 10 m parent with 1Length 0.3 is as long as it may be.
  EXPECT_DOUBLE_EQ(child_count(1, 30, 3.0, 10.0, 0.3, 4.0), 30.0);
  EXPECT_DOUBLE_EQ(child_count(1, 30, 1.5, 10.0, 0.3, 4.0), 30.0 * (0.2 + 0.8 * 0.5));
  // Deeper: fewer children the farther out along the parent.
  EXPECT_DOUBLE_EQ(child_count(2, 10, 1.0, 4.0, 0.5, 0.0), 10.0);
  EXPECT_DOUBLE_EQ(child_count(2, 10, 1.0, 4.0, 0.5, 4.0), 5.0);
  EXPECT_DOUBLE_EQ(child_count(3, 10, 1.0, 4.0, 0.5, 2.0), 7.5);
}

TEST(NextRotation, PositiveRotateSpirals) {
  LevelParameters lp;
  lp.rotate = 140.0;
  lp.rotate_v = 0.0;
  Random r(1, 0);
  double state = 0.0;
  EXPECT_DOUBLE_EQ(next_rotation(state, lp, r), 140.0);
  EXPECT_DOUBLE_EQ(next_rotation(state, lp, r), 280.0);
  EXPECT_DOUBLE_EQ(next_rotation(state, lp, r), 60.0);  // wraps at 360
}

TEST(NextRotation, NegativeRotateAlternatesSides) {
  LevelParameters lp;
  lp.rotate = -30.0;  // sides at +-150 degrees: near-coplanar, alternating
  lp.rotate_v = 0.0;
  Random r(1, 0);
  double state = 0.0;
  const double a = next_rotation(state, lp, r);
  const double b = next_rotation(state, lp, r);
  const double c = next_rotation(state, lp, r);
  EXPECT_DOUBLE_EQ(std::abs(a), 150.0);
  EXPECT_DOUBLE_EQ(b, -a);
  EXPECT_DOUBLE_EQ(c, a);
}

TEST(DownAngle, VariationOrSweepAlongTheParent) {
  LevelParameters lp;
  lp.down_angle = 60.0;
  lp.down_angle_v = 10.0;
  Random r(3, 0);
  for (int i = 0; i < 100; ++i) {
    const double d = down_angle(lp, 0.5, r);
    ASSERT_GE(d, 50.0);
    ASSERT_LE(d, 70.0);
  }
  // Negative: the paper's sweep, 60 - 50 (1 - 2 (0.2 + 0.8 ratio)): the quaking aspen's main
  // branches, 110 degrees from the trunk at the lowest child, 30 at the tip (a linear sweep
  // would give 10), 70 half way.
  lp.down_angle_v = -50.0;
  EXPECT_DOUBLE_EQ(down_angle(lp, 1.0, r), 110.0);
  EXPECT_DOUBLE_EQ(down_angle(lp, 0.0, r), 30.0);
  EXPECT_DOUBLE_EQ(down_angle(lp, 0.5, r), 70.0);
}

}  // namespace
}  // namespace landsim::trees::weber_penn
