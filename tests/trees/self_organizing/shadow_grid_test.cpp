#include "trees/self_organizing/shadow_grid.h"

#include <gtest/gtest.h>

#include <cmath>

namespace landsim::trees::self_organizing {
namespace {

TEST(ShadowGrid, AMetamerCastsAPyramidBelowIt) {
  LightParameters light;
  light.a = 0.4;
  light.b = 2.0;
  light.depth = 3;
  ShadowGrid grid(light, 1.0);
  grid.cast({0.5, 0.5, 10.5}, +1.0);
  for (int q = 0; q <= 3; ++q) {
    const double expected = 0.4 * std::pow(2.0, -q);
    EXPECT_DOUBLE_EQ(grid.shadow({0.5 + q, 0.5 - q, 10.5 - q}), expected) << q;  // corner
    EXPECT_DOUBLE_EQ(grid.shadow({0.5 + q + 1, 0.5, 10.5 - q}), 0.0) << q;       // beyond
  }
  EXPECT_DOUBLE_EQ(grid.shadow({0.5, 0.5, 11.5}), 0.0);  // above
  EXPECT_DOUBLE_EQ(grid.shadow({0.5, 0.5, 6.5}), 0.0);   // below q_max
  // Its own bud sees full light (its own share is taken out), the bud below less.
  EXPECT_DOUBLE_EQ(grid.exposure({0.5, 0.5, 10.5}), light.full);
  EXPECT_DOUBLE_EQ(grid.exposure({0.5, 0.5, 9.5}), light.full - 0.2 + 0.4);
}

TEST(ShadowGrid, GrowsKeepingItsShadowsAndTakesThemBack) {
  LightParameters light;
  ShadowGrid grid(light, 0.5);
  grid.cast({0, 0, 1}, +1.0);
  const double before = grid.shadow({0, 0, 0.6});
  grid.cast({40, -30, 25}, +1.0);  // far away: the grid grows
  EXPECT_DOUBLE_EQ(grid.shadow({0, 0, 0.6}), before);
  EXPECT_GT(grid.shadow({40, -30, 24.6}), 0.0);
  grid.cast({40, -30, 25}, -1.0);
  grid.cast({0, 0, 1}, -1.0);
  EXPECT_NEAR(grid.shadow({0, 0, 0.6}), 0.0, 1e-15);
  EXPECT_NEAR(grid.shadow({40, -30, 24.6}), 0.0, 1e-15);
}

}  // namespace
}  // namespace landsim::trees::self_organizing
