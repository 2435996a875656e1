#include "trees/graph_paths/poisson_disc.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "core/input_error.h"

namespace landsim::trees::graph_paths {
namespace {

InitialVolume unit_sphere() {
  VolumePrimitive s;
  s.kind = PrimitiveKind::sphere;
  return InitialVolume({s});
}

TEST(PoissonDisc, NodesAreInsideAndNoCloserThanTheSpacing) {
  const InitialVolume v = unit_sphere();
  const auto nodes = poisson_disc(v, {.spacing = 0.15}, 7);
  ASSERT_GT(nodes.size(), 300u);
  double closest = 1e9;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    EXPECT_TRUE(v.contains(nodes[i]));
    for (std::size_t j = i + 1; j < nodes.size(); ++j)
      closest = std::min(closest, length(nodes[i] - nodes[j]));
  }
  EXPECT_GE(closest, 0.15);
}

TEST(PoissonDisc, LeavesNoWideGaps) {
  // Dart throwing from an active list fills the volume: any point inside has a node within
  // about twice the spacing.
  const InitialVolume v = unit_sphere();
  const auto nodes = poisson_disc(v, {.spacing = 0.15}, 7);
  std::mt19937_64 gen(3);
  std::uniform_real_distribution<double> u(-0.9, 0.9);
  for (int k = 0; k < 200; ++k) {
    const Vec3 p{u(gen), u(gen), u(gen)};
    if (!v.contains(p)) continue;
    double nearest = 1e9;
    for (const Vec3& n : nodes) nearest = std::min(nearest, length(n - p));
    EXPECT_LT(nearest, 0.3) << p.x << " " << p.y << " " << p.z;
  }
}

TEST(PoissonDisc, PacksAsDenselyAsTheNodeCountEstimateAssumes) {
  const InitialVolume v = unit_sphere();
  const double spacing = 0.05, inner = 0.6;
  const auto nodes = poisson_disc(v, {.spacing = spacing}, 3);
  const auto inside =
      std::count_if(nodes.begin(), nodes.end(), [&](const Vec3& p) { return length(p) < inner; });
  const double cubic_spacings = 4.0 / 3.0 * std::numbers::pi * std::pow(inner / spacing, 3);
  const double density = static_cast<double>(inside) / cubic_spacings;
  // Bounds that owe nothing to the sampler: nodes no closer than the spacing d are disjoint
  // balls of radius d/2, and a random sequential fill of such balls saturates at a volume
  // fraction of 0.38278 (Torquato, Uche & Stillinger 2006), 0.38278 / (pi / 6) = 0.7311
  // nodes per d^3. A dart thrower with finitely many attempts per node stops below
  // saturation, but not far below (within 20%).
  EXPECT_LT(density, 0.7311);
  EXPECT_GT(density, 0.8 * 0.7311);
  // The node-count estimate's constant is this sampler's density.
  EXPECT_NEAR(density, kNodesPerCubicSpacing, 0.03);
}

TEST(PoissonDisc, StoresNodesNearTheirNeighbours) {
  // Morton order: a node's nearest neighbour is usually close in the array too, where the
  // sampler's own wavefront order scatters it (the later stages rely on this for speed).
  const auto nodes = poisson_disc(unit_sphere(), {.spacing = 0.08}, 5);
  std::vector<double> gaps;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    std::size_t nearest = i == 0 ? 1 : 0;
    for (std::size_t j = 0; j < nodes.size(); ++j)
      if (j != i && length(nodes[j] - nodes[i]) < length(nodes[nearest] - nodes[i])) nearest = j;
    gaps.push_back(std::abs(static_cast<double>(nearest) - static_cast<double>(i)));
  }
  std::nth_element(gaps.begin(), gaps.begin() + gaps.size() / 2, gaps.end());
  EXPECT_LT(gaps[gaps.size() / 2], 0.01 * static_cast<double>(nodes.size()));
}

TEST(PoissonDisc, FillsEverySeparatePartOfAUnion) {
  VolumePrimitive a, b;
  b.origin = {4, 0, 0};
  const auto nodes = poisson_disc(InitialVolume({a, b}), {.spacing = 0.2}, 1);
  const auto far = std::count_if(nodes.begin(), nodes.end(), [](const Vec3& p) { return p.x > 2; });
  EXPECT_GT(far, 100);
  EXPECT_GT(static_cast<long>(nodes.size()) - far, 100);
}

TEST(PoissonDisc, SameSeedSameNodesOtherSeedOtherNodes) {
  const InitialVolume v = unit_sphere();
  const auto a = poisson_disc(v, {.spacing = 0.2}, 11);
  const auto b = poisson_disc(v, {.spacing = 0.2}, 11);
  const auto c = poisson_disc(v, {.spacing = 0.2}, 12);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
}

TEST(PoissonDisc, RefusesExplosiveNodeCounts) {
  EXPECT_THROW(poisson_disc(unit_sphere(), {.spacing = 0.05, .max_nodes = 1000}, 1), InputError);
  EXPECT_THROW(poisson_disc(unit_sphere(), {.spacing = 1e-5}, 1), InputError);
  EXPECT_THROW(poisson_disc(unit_sphere(), {.spacing = 0.0}, 1), InputError);
}

}  // namespace
}  // namespace landsim::trees::graph_paths
