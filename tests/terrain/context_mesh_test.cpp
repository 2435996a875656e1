#include "terrain/context_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "core/value_noise.h"

namespace landsim::terrain {
namespace {

// A 21 x 21 grid of 10 m cells in a 4 km context of 30 m cells with rough relief (+-40 m):
// wherever a coarse cell meets finer ones, a midpoint that is not shared would open a crack.
ElevationGrid test_grid() {
  std::vector<float> h;
  for (int r = 0; r < 21; ++r)
    for (int c = 0; c < 21; ++c) h.push_back(static_cast<float>(300.0 + 3.0 * std::sin(c + r)));
  return ElevationGrid(21, 21, GeoTransform{0.0, 210.0, 10.0, 10.0}, h);
}

ElevationGrid rough_context() {
  const int n = 134;
  std::vector<float> h;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c)
      h.push_back(static_cast<float>(280.0 + 40.0 * (lattice_value(c, r, 7) - 0.5)));
  return ElevationGrid(n, n, GeoTransform{-1900.0, 2110.0, 30.0, 30.0}, h);
}

ContextMeshOptions near_view() {
  ContextMeshOptions o;
  o.views = {{105.0, 105.0}};
  o.range_factor = 6.0;  // coarsens within the test's small context
  return o;
}

Vec3 vertex(const GroundMesh& m, std::uint32_t i) { return Vec3(m.vertices[i]); }

// Some triangle lies over (x, y) seen from above.
bool covered(const GroundMesh& m, double x, double y) {
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const Vec3 a = vertex(m, m.indices[3 * t]), b = vertex(m, m.indices[3 * t + 1]),
               c = vertex(m, m.indices[3 * t + 2]);
    const auto side = [&](const Vec3& p, const Vec3& q) {
      return (q.x - p.x) * (y - p.y) - (q.y - p.y) * (x - p.x);
    };
    if (side(a, b) >= 0 && side(b, c) >= 0 && side(c, a) >= 0) return true;
  }
  return false;
}

TEST(ContextMesh, EveryInnerEdgeIsSharedByTwoTriangles) {
  const ElevationGrid grid = test_grid();
  const TerrainField field(grid, {rough_context()});
  const ContextMesh cm = build_context_mesh(field, Vec3{}, near_view());
  const GroundMesh& m = cm.mesh;
  ASSERT_GT(m.triangle_count(), 1000u);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (std::size_t t = 0; t < m.triangle_count(); ++t)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = m.indices[3 * t + e], b = m.indices[3 * t + (e + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  // The third corner of each edge's triangle, to know which side the triangle lies on.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> opposite;
  for (std::size_t t = 0; t < m.triangle_count(); ++t)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = m.indices[3 * t + e], b = m.indices[3 * t + (e + 1) % 3];
      opposite[{std::min(a, b), std::max(a, b)}] = m.indices[3 * t + (e + 2) % 3];
    }
  int rim_edges = 0;
  for (const auto& [edge, n] : uses) {
    ASSERT_LE(n, 2);
    if (n == 2) continue;
    // An edge of one triangle only: a crack unless nothing lies across it (the data's rim).
    const Vec3 a = vertex(m, edge.first), b = vertex(m, edge.second);
    const Vec3 mid = (a + b) * 0.5, inward = vertex(m, opposite[edge]) - mid;
    Vec3 across = normalize(Vec3{b.y - a.y, a.x - b.x, 0.0});
    if (dot(across, inward) > 0.0) across = across * -1.0;
    const Vec3 probe = mid + across * 1.0;
    ASSERT_FALSE(covered(m, probe.x, probe.y)) << a.x << "," << a.y << " - " << b.x << "," << b.y;
    ++rim_edges;
  }
  EXPECT_GT(rim_edges, 0);
}

// Moller-Trumbore in double precision, edges inclusive.
bool hits(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a, p = cross(d, e2);
  const double det = dot(e1, p);
  if (std::abs(det) < 1e-12) return false;
  const Vec3 s = o - a;
  const double u = dot(s, p) / det;
  const Vec3 q = cross(s, e1);
  const double v = dot(d, q) / det;
  const double t = dot(e2, q) / det;
  return u >= -1e-9 && v >= -1e-9 && u + v <= 1.0 + 1e-9 && t > 0.0;
}

TEST(ContextMesh, OverTheGridsEdgeNoRayEscapes) {
  const ElevationGrid grid = test_grid();
  const TerrainField field(grid, {rough_context()});
  const GroundMesh m = build_context_mesh(field, Vec3{}, near_view()).mesh;
  // Oblique rays aimed at a 60 x 60 grid of points around the grid's east and north edges
  // and out through the first changes of level.
  const Vec3 d = normalize(Vec3{0.5, 0.35, -0.8});
  int escaped = 0;
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j) {
      const Vec3 target{150.0 + i * 7.3, 150.0 + j * 7.3, 280.0};
      const Vec3 o = target - d * 1000.0;
      bool hit = false;
      for (std::size_t t = 0; t < m.triangle_count() && !hit; ++t)
        hit = hits(o, d, vertex(m, m.indices[3 * t]), vertex(m, m.indices[3 * t + 1]),
                   vertex(m, m.indices[3 * t + 2]));
      escaped += hit ? 0 : 1;
    }
  EXPECT_EQ(escaped, 0);
}

TEST(ContextMesh, TheGridIsMeshedAsItIsAndTheSurroundingsCoarsenWithRange) {
  const ElevationGrid grid = test_grid();
  const TerrainField field(grid, {rough_context()});
  const Vec3 origin{105.0, 105.0, 300.0};
  const ContextMesh cm = build_context_mesh(field, origin, near_view());
  const GroundMesh& m = cm.mesh;
  // Every sample of the grid is a vertex at its own height.
  std::set<std::pair<long, long>> seen;
  for (const Vec3f& v : m.vertices) {
    const Vec3 p = Vec3(v) + origin;
    const double c = (p.x - 5.0) / 10.0, r = (205.0 - p.y) / 10.0;
    if (c < 0 || r < 0 || c > 20 || r > 20) continue;
    if (c != std::round(c) || r != std::round(r)) continue;
    const auto cc = static_cast<int>(c), rr = static_cast<int>(r);
    EXPECT_NEAR(p.z, grid.at(cc, rr), 1e-4);
    seen.insert({cc, rr});
  }
  EXPECT_EQ(seen.size(), 21u * 21u);
  // Longest edge of the triangles near the view and far from it.
  double near = 0.0, far = 1e30;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const Vec3 a = Vec3(m.vertices[m.indices[3 * t]]), b = Vec3(m.vertices[m.indices[3 * t + 1]]);
    const double range = std::hypot(a.x, a.y), edge = std::hypot(b.x - a.x, b.y - a.y);
    if (range < 90.0) near = std::max(near, edge);
    if (range > 1500.0) far = std::min(far, edge);
  }
  EXPECT_LE(near, 10.0 * std::sqrt(2.0) + 1e-3);  // the grid's own cells
  EXPECT_GE(far, 4.0 * near);
  // Context triangles are marked, the grid's are not.
  ASSERT_EQ(cm.from_context.size(), m.triangle_count());
  EXPECT_EQ(std::count(cm.from_context.begin(), cm.from_context.end(), 0), 2 * 20 * 20);
}

TEST(ContextMesh, CountingTheCellsAgreesWithTheMesh) {
  const ElevationGrid grid = test_grid();
  const TerrainField field(grid, {rough_context()});
  const std::size_t cells = count_context_cells(field, near_view());
  const std::size_t triangles =
      build_context_mesh(field, Vec3{}, near_view()).mesh.triangle_count();
  EXPECT_GE(triangles, 2 * cells * 95 / 100);  // rim cells with no data lose triangles
  EXPECT_LE(triangles, 3 * cells);
}

}  // namespace
}  // namespace landsim::terrain
