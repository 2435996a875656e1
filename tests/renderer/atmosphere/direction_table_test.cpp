// DirectionTable (renderer/atmosphere/direction_table.h): its density is a density (it
// integrates to 1 over the sphere, none below the horizon), sampling draws directions at the
// density it reports, and a bright lobe gets its share of the samples.
#include "renderer/atmosphere/direction_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/counter_rng.h"

namespace landsim::renderer {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
const Vec3f kLobe = normalize(Vec3f{0.6f, -0.3f, 0.5f});

// A sky of 1 with a lobe 400 times brighter within 10 degrees of kLobe.
float lobed(const Vec3f& d) {
  return dot(d, kLobe) > std::cos(10.0f * kPi / 180.0f) ? 400.0f : 1.0f;
}

// The density's integral over the directions where `inside` holds (a fine midpoint rule).
template <typename Inside>
double probability(const DirectionTable& table, Inside&& inside) {
  double sum = 0.0;
  constexpr int kSteps = 6 * DirectionTable::kRows;  // sub-cells within the table's cells
  for (int i = 0; i < kSteps; ++i) {
    const float theta = kPi * (static_cast<float>(i) + 0.5f) / kSteps;
    for (int j = 0; j < 2 * kSteps; ++j) {
      const float phi = 2.0f * kPi * (static_cast<float>(j) + 0.5f) / (2 * kSteps);
      const Vec3f d = DirectionTable::direction_of(theta, phi);
      if (inside(d)) sum += table.pdf(d) * std::sin(theta) * (kPi / kSteps) * (kPi / kSteps);
    }
  }
  return sum;
}

TEST(DirectionTable, DensityIntegratesToOneAboveTheHorizon) {
  const DirectionTable table(lobed);
  EXPECT_NEAR(probability(table, [](const Vec3f&) { return true; }), 1.0, 2e-3);
  EXPECT_EQ(probability(table, [](const Vec3f& d) { return d.z < -0.01f; }), 0.0);
  // The lobe, 400 times brighter over 0.095 sr, holds most of the density (the cells smear
  // its edge by up to a cell).
  EXPECT_GT(probability(table, [](const Vec3f& d) { return lobed(d) > 1.0f; }), 0.7);
}

TEST(DirectionTable, SamplesFallAtTheDensityTheyReport) {
  const DirectionTable table(lobed);
  const auto in_lobe = [](const Vec3f& d) { return lobed(d) > 1.0f; };
  constexpr int kSamples = 100000;
  int hits = 0, other_cell = 0;
  for (int n = 0; n < kSamples; ++n) {
    const auto u = CounterRng(7, static_cast<std::uint32_t>(n), 0).uniform2(0);
    float pdf = 0.0f;
    const Vec3f d = table.sample(u[0], u[1], pdf);
    ASSERT_GT(d.z, -1e-6f);
    // The density of the cell drawn from; pdf(d) finds the same cell but where rounding puts
    // d on a cell's edge.
    if (std::abs(pdf / table.pdf(d) - 1.0f) > 1e-3f) ++other_cell;
    if (in_lobe(d)) ++hits;
  }
  EXPECT_LT(other_cell, kSamples / 1000);
  const double p = probability(table, in_lobe);
  // Five standard errors of a binomial share.
  EXPECT_NEAR(static_cast<double>(hits) / kSamples, p, 5.0 * std::sqrt(p * (1.0 - p) / kSamples));
}

// The luminance toward a direction is its density times the integral: what the sky's
// shadow-ray roulette estimates a ray's light by before tracing it.
TEST(DirectionTable, DensityTimesIntegralIsTheTabulatedLuminance) {
  const DirectionTable table(lobed);
  // Cell centres well inside and well outside the lobe (its edge crosses cells).
  const Vec3f inside = kLobe;
  const Vec3f outside = DirectionTable::direction_of(0.3f * kPi / 2.0f, 2.6f);
  ASSERT_EQ(lobed(outside), 1.0f);
  // The floor adds 1e-3 of the mean per cell, far below 0.5% of either.
  EXPECT_NEAR(table.pdf(inside) * table.integral(), 400.0f, 400.0f * 0.005f);
  EXPECT_NEAR(table.pdf(outside) * table.integral(), 1.0f, 0.005f);
}

}  // namespace
}  // namespace landsim::renderer
