#include "terrain/surface_detail.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/value_noise.h"
#include "terrain/context_mesh.h"

namespace landsim::terrain {
namespace {

// 30 x 30 cells of 10 m with rolling heights.
ElevationGrid test_grid() {
  std::vector<float> h;
  for (int r = 0; r < 30; ++r)
    for (int c = 0; c < 30; ++c)
      h.push_back(static_cast<float>(100.0 + 5.0 * std::sin(0.3 * c) + 3.0 * r));
  return ElevationGrid(30, 30, GeoTransform{0.0, 300.0, 10.0, 10.0}, h);
}

SurfaceDetail detail_of(const ElevationGrid& g, float amplitude, std::uint64_t seed) {
  return SurfaceDetail(g, std::vector<float>(900, amplitude), std::vector<float>(900, 0.5f), seed);
}

TEST(SurfaceDetail, ZeroAtEverySampleAndBoundedByTheAmplitude) {
  const ElevationGrid g = test_grid();
  const SurfaceDetail d = detail_of(g, 0.5f, 3);
  for (int r = 0; r < 30; ++r)
    for (int c = 0; c < 30; ++c) ASSERT_EQ(d.displacement(g.x_of_col(c), g.y_of_row(r)), 0.0);
  double largest = 0.0;
  for (int i = 0; i < 5000; ++i) {
    const double x = 5.0 + 290.0 * lattice_value(i, 1, 9), y = 5.0 + 290.0 * lattice_value(i, 2, 9);
    const double v = d.displacement(x, y);
    ASSERT_LE(std::abs(v), 0.5) << x << "," << y;
    largest = std::max(largest, std::abs(v));
  }
  EXPECT_GT(largest, 0.2);                      // it is there
  EXPECT_EQ(d.displacement(-50.0, 20.0), 0.0);  // none off the grid
}

TEST(SurfaceDetail, SameSeedSameSurfaceAnotherSeedAnother) {
  const ElevationGrid g = test_grid();
  const SurfaceDetail a = detail_of(g, 0.5f, 3), b = detail_of(g, 0.5f, 3),
                      c = detail_of(g, 0.5f, 4);
  int differ = 0;
  for (int i = 0; i < 200; ++i) {
    const double x = 7.3 + i * 1.37, y = 11.1 + i * 0.91;
    EXPECT_EQ(a.displacement(x, y), b.displacement(x, y));
    differ += a.displacement(x, y) != c.displacement(x, y);
  }
  EXPECT_GT(differ, 150);
}

TEST(SurfaceDetail, MeshedFinerNearTheViewAndTheSamplesStayPut) {
  const ElevationGrid g = test_grid();
  const SurfaceDetail d = detail_of(g, 0.5f, 3);
  const TerrainField field(g, {});
  ContextMeshOptions o;
  o.views = {{50.0, 50.0}};
  o.detail = &d;
  o.detail_levels = 3;
  o.detail_factor = 4.0;
  const GroundMesh m = build_context_mesh(field, Vec3{}, o).mesh;
  // Every grid sample is a vertex at its own height.
  int samples = 0;
  for (const Vec3f& v : m.vertices) {
    const double c = (v.x - 5.0) / 10.0, r = (295.0 - v.y) / 10.0;
    if (c != std::round(c) || r != std::round(r)) continue;
    EXPECT_NEAR(v.z, g.at(static_cast<int>(c), static_cast<int>(r)), 1e-4);
    ++samples;
  }
  EXPECT_EQ(samples, 900);
  // The longest edge near the view and the shortest far from it.
  double near = 0.0, far = 1e30;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const Vec3f a = m.vertices[m.indices[3 * t]], b = m.vertices[m.indices[3 * t + 1]];
    const double range = std::hypot(a.x - 50.0, a.y - 50.0);
    const double edge = std::hypot(b.x - a.x, b.y - a.y);
    if (range < 4.0) near = std::max(near, edge);
    if (range > 200.0) far = std::min(far, edge);
  }
  EXPECT_LE(near, 10.0 / 8.0 * std::sqrt(2.0) + 1e-3);  // an eighth of a cell
  EXPECT_GE(far, 10.0 - 1e-3);                          // the grid's own cells
  // No cracks where finer cells meet coarser ones: an edge of one triangle lies on the rim.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (std::size_t t = 0; t < m.triangle_count(); ++t)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = m.indices[3 * t + e], b = m.indices[3 * t + (e + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  const auto rim = [](const Vec3f& v) {
    return v.x == 5.0f || v.x == 295.0f || v.y == 5.0f || v.y == 295.0f;
  };
  for (const auto& [edge, n] : uses) {
    ASSERT_LE(n, 2);
    if (n == 1) {
      ASSERT_TRUE(rim(m.vertices[edge.first]) && rim(m.vertices[edge.second]));
    }
  }
  // Between the samples the surface is displaced.
  double off = 0.0;
  for (const Vec3f& v : m.vertices) {
    const auto h = g.height(v.x, v.y);
    if (h) off = std::max(off, std::abs(v.z - *h));
  }
  EXPECT_GT(off, 0.05);
  EXPECT_LE(off, 0.5 + 1e-3);
}

}  // namespace
}  // namespace landsim::terrain
