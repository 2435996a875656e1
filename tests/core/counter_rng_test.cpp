#include "core/counter_rng.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <array>
#include <set>
#include <vector>

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

// Padded Owen-scrambled Sobol: a pixel's 16 samples put one point in every elementary
// interval of area 1/16 of each pair of dimensions (4 x 4, 16 x 1, 1 x 16, 2 x 8, 8 x 2).
TEST(CounterRng, SobolPairsAreStratifiedOverAPixelsSamples) {
  for (std::uint64_t pixel : {0u, 17u, 123456u})
    for (std::uint32_t pair : {0u, 1u, 6u, 2147450880u /* the lens's */}) {
      for (int columns : {1, 2, 4, 8, 16}) {
        const int rows = 16 / columns;
        std::set<int> cells;
        for (int s = 0; s < 16; ++s) {
          const CounterRng rng(5, pixel, static_cast<std::uint64_t>(s), SampleSequence::sobol);
          const float u = rng.uniform(2 * pair), v = rng.uniform(2 * pair + 1);
          ASSERT_GE(u, 0.0f);
          ASSERT_LT(v, 1.0f);
          cells.insert(static_cast<int>(u * static_cast<float>(columns)) * rows +
                       static_cast<int>(v * static_cast<float>(rows)));
        }
        EXPECT_EQ(cells.size(), 16u) << "pixel " << pixel << " pair " << pair << " " << columns;
      }
    }
}

// Pairs take the samples in orders of their own, and pixels scramble differently: no two
// pairs or pixels see the same points.
TEST(CounterRng, SobolPairsAndPixelsAreDecorrelated) {
  const auto order = [](std::uint64_t pixel, std::uint32_t dimension) {
    std::vector<int> strata;
    for (int s = 0; s < 16; ++s)
      strata.push_back(static_cast<int>(
          16.0f * CounterRng(5, pixel, static_cast<std::uint64_t>(s), SampleSequence::sobol)
                      .uniform(dimension)));
    return strata;
  };
  EXPECT_NE(order(3, 0), order(3, 2));
  EXPECT_NE(order(3, 2), order(3, 4));
  EXPECT_NE(order(3, 0), order(4, 0));
  // Over many pixels each dimension is uniform.
  double sum = 0.0;
  for (std::uint64_t k = 0; k < 20000; ++k)
    sum +=
        CounterRng(1, k, k % 16, SampleSequence::sobol).uniform(static_cast<std::uint32_t>(k % 40));
  EXPECT_NEAR(sum / 20000.0, 0.5, 0.01);
}

// Each pixel's points are its own, not another pixel's in another order: the sorted values
// of a dimension over a pixel's samples differ from pixel to pixel (a sampler that only
// shuffled the order would give every pixel the same point set, and correlated images).
TEST(CounterRng, SobolPixelsHaveTheirOwnPointSets) {
  const auto sorted = [](std::uint64_t pixel, std::uint32_t dimension) {
    std::vector<float> v;
    for (int s = 0; s < 16; ++s)
      v.push_back(CounterRng(5, pixel, static_cast<std::uint64_t>(s), SampleSequence::sobol)
                      .uniform(dimension));
    std::sort(v.begin(), v.end());
    return v;
  };
  for (std::uint32_t dimension : {0u, 1u, 7u})
    for (std::uint64_t pixel : {3u, 1000u}) {
      const std::vector<float> a = sorted(pixel, dimension), b = sorted(pixel + 1, dimension);
      int same = 0;
      for (std::size_t i = 0; i < a.size(); ++i) same += a[i] == b[i];
      EXPECT_LT(same, 2) << "pixel " << pixel << " dimension " << dimension;
    }
}

// A pair drawn together is the two dimensions drawn alone, bit for bit, under either sampler
// and for odd first dimensions too (then not a Sobol pair: two separate draws).
TEST(CounterRng, APairDrawnTogetherIsItsDimensionsDrawnAlone) {
  for (const SampleSequence sequence : {SampleSequence::independent, SampleSequence::sobol})
    for (std::uint64_t pixel : {0u, 99u, 4000000u})
      for (std::uint64_t sample : {0u, 1u, 15u, 1000u})
        for (std::uint32_t first : {0u, 1u, 2u, 14u, 27u, 0xFFFF0000u}) {
          const CounterRng rng(11, pixel, sample, sequence);
          const std::array<float, 2> pair = rng.uniform2(first);
          EXPECT_EQ(pair[0], rng.uniform(first)) << first;
          EXPECT_EQ(pair[1], rng.uniform(first + 1)) << first;
        }
}

}  // namespace
}  // namespace landsim
