#include "renderer/guiding/directional_tree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace landsim::renderer {
namespace {

constexpr double kPi = std::numbers::pi;

// A lobe of light about `axis` (cos^8 of the angle to it) plus a faint uniform floor: what
// a region might receive from a bright gap in a crown over the rest of its sky.
double lobe(const Vec3f& d, const Vec3f& axis) {
  const double c = std::max(0.0f, dot(d, axis));
  return std::pow(c, 8.0) + 0.05;
}
// Its integral over the sphere: 2 pi / 9 for the lobe, 4 pi x 0.05 for the floor.
constexpr double kLobeIntegral = 2.0 * kPi / 9.0 + 4.0 * kPi * 0.05;

// Training records as a path tracer makes them: directions drawn uniformly over the sphere
// (density 1 / 4 pi), each carrying the radiance over that density.
std::vector<DirectionalRecord> records_of(const Vec3f& axis, int n, std::uint32_t seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<DirectionalRecord> out;
  for (int k = 0; k < n; ++k) {
    const float a = u(gen), b = u(gen);
    const Vec3f d = square_to_direction(a, b);
    out.push_back({a, b, static_cast<float>(lobe(d, axis) * 4.0 * kPi)});
  }
  return out;
}

TEST(DirectionalTree, TheSquaresMappingKeepsAreasAndRoundTrips) {
  for (float a : {0.01f, 0.3f, 0.5f, 0.77f, 0.99f})
    for (float b : {0.02f, 0.25f, 0.6f, 0.95f}) {
      const Vec3f d = square_to_direction(a, b);
      EXPECT_NEAR(length(d), 1.0f, 1e-6f);
      const auto back = direction_to_square(d);
      EXPECT_NEAR(back[0], a, 1e-5f);
      EXPECT_NEAR(back[1], b, 1e-5f);
    }
  // Equal areas: the band of the square below u = 0.25 is the cap below cos theta = -0.5, a
  // quarter of the sphere.
  EXPECT_NEAR(direction_to_square(Vec3f{0.0f, std::sqrt(0.75f), -0.5f})[0], 0.25f, 1e-6f);
}

TEST(DirectionalTree, NoFluxLearnsNothing) {
  std::vector<DirectionalRecord> none{{0.2f, 0.3f, 0.0f}, {0.7f, 0.1f, 0.0f}};
  const DirectionalTree tree(none);
  EXPECT_TRUE(tree.empty());
  EXPECT_EQ(tree.square_pdf(0.2f, 0.3f), 0.0f);
}

// The learned density integrates to one over the sphere and follows the light: its value
// over the lobe's axis and far from it against the lobe's own normalised density.
TEST(DirectionalTree, LearnsTheDensityOfTheLightItRecorded) {
  const Vec3f axis = normalize(Vec3f{0.3f, -0.2f, 0.9f});
  auto records = records_of(axis, 200000, 7);
  const DirectionalTree tree(records);
  ASSERT_FALSE(tree.empty());
  EXPECT_GT(tree.node_count(), 10u);
  double integral = 0.0;
  constexpr int kGrid = 256;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j)
      integral += tree.square_pdf((i + 0.5f) / kGrid, (j + 0.5f) / kGrid) / (kGrid * kGrid);
  EXPECT_NEAR(integral, 1.0, 1e-3);
  // The lobe's peak is 1.05 / kLobeIntegral a steradian; quadrants average over their area,
  // which lowers the peak a little.
  const double peak = 1.05 / kLobeIntegral, floor = 0.05 / kLobeIntegral;
  EXPECT_NEAR(tree.pdf(axis), peak, 0.15 * peak);
  EXPECT_NEAR(tree.pdf(-axis), floor, 0.3 * floor);
}

// Directions drawn by `sample` fall into each cell of the square as often as the density
// says, and `sample`'s density is pdf()'s at the direction it drew (but for the odd point
// within a float's rounding of a quadrant's edge, which the trip through the direction's
// angles may carry across).
TEST(DirectionalTree, SamplesFollowTheirDensity) {
  const Vec3f axis = normalize(Vec3f{-0.5f, 0.4f, 0.3f});
  auto records = records_of(axis, 50000, 11);
  const DirectionalTree tree(records);
  constexpr int kCells = 8, kSamples = 400000;
  std::vector<double> counts(kCells * kCells, 0.0);
  std::mt19937 gen(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  int differ = 0;
  for (int k = 0; k < kSamples; ++k) {
    float pdf = 0.0f;
    const Vec3f d = tree.sample(u(gen), u(gen), pdf);
    const float looked_up = tree.pdf(d);
    if (std::abs(pdf - looked_up) > 1e-4f * looked_up) ++differ;
    const auto s = direction_to_square(d);
    counts[static_cast<std::size_t>(static_cast<int>(s[0] * kCells) +
                                    kCells * static_cast<int>(s[1] * kCells))] += 1.0;
  }
  EXPECT_LE(differ, kSamples / 20000);
  // Each cell's expected share by the density integrated over it (16 x 16 points a cell).
  for (int i = 0; i < kCells; ++i)
    for (int j = 0; j < kCells; ++j) {
      double expected = 0.0;
      for (int a = 0; a < 16; ++a)
        for (int b = 0; b < 16; ++b)
          expected +=
              tree.square_pdf((i + (a + 0.5f) / 16.0f) / kCells, (j + (b + 0.5f) / 16.0f) / kCells);
      expected *= static_cast<double>(kSamples) / (16.0 * 16.0 * kCells * kCells);
      const double seen = counts[static_cast<std::size_t>(i + kCells * j)];
      EXPECT_NEAR(seen, expected, 5.0 * std::sqrt(expected) + 1.0) << "cell " << i << "," << j;
    }
}

}  // namespace
}  // namespace landsim::renderer
