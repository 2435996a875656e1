#include "trees/self_organizing/reach_mask.h"

#include <gtest/gtest.h>

#include "trees/random.h"

namespace landsim::trees::self_organizing {
namespace {

bool any_within(const std::vector<Vec3>& buds, const Vec3& p, double radius) {
  for (const Vec3& b : buds)
    if (length(p - b) <= radius) return true;
  return false;
}

TEST(ReachMask, NeverHidesABudWithinReachAndClearsFarPoints) {
  Random rng(4, 0);
  std::vector<Vec3> buds;
  for (int k = 0; k < 200; ++k)
    buds.push_back({rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0, 3)});
  const double radius = 0.3;
  const ReachMask mask(buds, radius);
  int cleared = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec3 p{rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-2, 6)};
    if (any_within(buds, p, radius)) {
      EXPECT_TRUE(mask.may_reach(p)) << k;
    }
    cleared += !mask.may_reach(p);
  }
  EXPECT_GT(cleared, 15000);  // most of the box is beyond reach: the mask must say so
  // Exactly at the radius, along each axis and diagonally from a bud.
  for (const Vec3& d : {Vec3{1, 0, 0}, Vec3{0, -1, 0}, Vec3{0, 0, 1}, normalize(Vec3{1, 1, 1})})
    EXPECT_TRUE(mask.may_reach(buds[7] + d * radius));
}

TEST(ReachMask, WithoutBudsNothingIsReachedAndATooWideTreeLetsEverythingPass) {
  EXPECT_FALSE(ReachMask({}, 1.0).may_reach({0, 0, 0}));
  // Buds 10 km apart at a 1 cm radius: no dense mask; every point passes to the exact test.
  const ReachMask wide({{0, 0, 0}, {1e4, 1e4, 1e4}}, 0.01);
  EXPECT_TRUE(wide.may_reach({5e3, 5e3, 5e3}));
}

}  // namespace
}  // namespace landsim::trees::self_organizing
