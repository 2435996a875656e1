#include "core/counter_rng.h"

#include <gtest/gtest.h>

#include <set>

namespace landsim {
namespace {

TEST(CounterRng, SameCountersGiveSameValue) {
  const CounterRng a(7, 1234, 5);
  const CounterRng b(7, 1234, 5);
  for (std::uint32_t d = 0; d < 16; ++d) EXPECT_EQ(a.uniform(d), b.uniform(d));
}

TEST(CounterRng, EveryCounterChangesTheValue) {
  const float base = CounterRng(7, 1234, 5).uniform(3);
  EXPECT_NE(base, CounterRng(8, 1234, 5).uniform(3));
  EXPECT_NE(base, CounterRng(7, 1235, 5).uniform(3));
  EXPECT_NE(base, CounterRng(7, 1234, 6).uniform(3));
  EXPECT_NE(base, CounterRng(7, 1234, 5).uniform(4));
}

TEST(CounterRng, UniformInUnitIntervalWithRightMeanAndSpread) {
  constexpr int kN = 200000;
  double sum = 0.0, sum_sq = 0.0;
  int below_tenth = 0;
  for (int i = 0; i < kN; ++i) {
    const float u = CounterRng(1, static_cast<std::uint64_t>(i), 0).uniform(0);
    ASSERT_GE(u, 0.0f);
    ASSERT_LT(u, 1.0f);
    sum += u;
    sum_sq += double(u) * u;
    below_tenth += u < 0.1f;
  }
  EXPECT_NEAR(sum / kN, 0.5, 0.005);
  EXPECT_NEAR(sum_sq / kN - (sum / kN) * (sum / kN), 1.0 / 12.0, 0.002);
  EXPECT_NEAR(below_tenth / double(kN), 0.1, 0.005);
}

TEST(CounterRng, NextWalksTheDimensions) {
  CounterRng rng(3, 4, 5);
  const CounterRng same(3, 4, 5);
  EXPECT_EQ(rng.next(), same.uniform(0));
  EXPECT_EQ(rng.next(), same.uniform(1));
}

TEST(CounterRng, NeighbouringPixelsAreNotCorrelated) {
  // A weak mixer would give near-identical values for keys 0, 1, 2...
  std::set<float> values;
  for (std::uint64_t k = 0; k < 1000; ++k) values.insert(CounterRng(0, k, 0).uniform(0));
  EXPECT_GT(values.size(), 990u);
}

}  // namespace
}  // namespace landsim
