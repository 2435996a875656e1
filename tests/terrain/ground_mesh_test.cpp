#include "terrain/ground_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "terrain/dem_loader.h"
#include "tests/support/temp_dir.h"

namespace landsim::terrain {
namespace {

ElevationGrid flat_grid(int n, std::vector<int> nodata_cells = {}) {
  std::vector<float> h(static_cast<std::size_t>(n * n), 10.0f);
  for (int i : nodata_cells) h[static_cast<std::size_t>(i)] = NAN;
  return ElevationGrid(n, n, GeoTransform{0.0, 10.0 * n, 10.0, 10.0}, h);
}

Vec3f triangle_normal(const GroundMesh& m, std::size_t t) {
  const Vec3f a = m.vertices[m.indices[3 * t]];
  const Vec3f b = m.vertices[m.indices[3 * t + 1]];
  const Vec3f c = m.vertices[m.indices[3 * t + 2]];
  return cross(b - a, c - a);
}

TEST(GroundMesh, TwoTrianglesPerQuadFacingUp) {
  const GroundMesh m = build_ground_mesh(flat_grid(3), Vec3{});
  EXPECT_EQ(m.vertices.size(), 9u);
  EXPECT_EQ(m.normals.size(), 9u);
  ASSERT_EQ(m.triangle_count(), 8u);
  for (std::size_t t = 0; t < m.triangle_count(); ++t) EXPECT_GT(triangle_normal(m, t).z, 0.0f);
}

TEST(GroundMesh, NodataCornerDropsOnlyItsTriangle) {
  const GroundMesh corner = build_ground_mesh(flat_grid(3, {0}), Vec3{});
  EXPECT_EQ(corner.triangle_count(), 7u);  // 3 full quads + 1 triangle
  const GroundMesh centre = build_ground_mesh(flat_grid(3, {4}), Vec3{});
  EXPECT_EQ(centre.triangle_count(), 4u);  // every quad keeps the triangle of its 3 valid corners
  for (std::uint32_t i : centre.indices) EXPECT_NE(i, 4u);
  for (std::size_t t = 0; t < centre.triangle_count(); ++t)
    EXPECT_GT(triangle_normal(centre, t).z, 0.0f);
}

TEST(GroundMesh, RealNodataLeavesHolesNotSpikes) {
  const ElevationGrid g =
      load_elevation(testing::source_file("data/terrain/gorillas_elevation.asc").string());
  const Vec3 origin = g.centre();
  const GroundMesh m = build_ground_mesh(g, origin);
  ASSERT_GT(m.triangle_count(), 0u);
  const std::set<std::uint32_t> used(m.indices.begin(), m.indices.end());
  for (std::uint32_t i : used) {
    const double z = m.vertices[i].z + origin.z;
    ASSERT_GE(z, 1165.0 - 0.01);
    ASSERT_LE(z, 2062.0 + 0.01);
  }
  // Fewer triangles than a full grid: the nodata region is left out.
  EXPECT_LT(m.triangle_count(), 2u * 180u * 148u);
}

TEST(GroundMesh, GeoreferencedGridKeepsMillimetrePrecision) {
  const ElevationGrid g =
      load_elevation(testing::source_file("data/terrain/gorillas_elevation.asc").string());
  const Vec3 origin = g.centre();
  const GroundMesh m = build_ground_mesh(g, origin);
  const std::size_t i = 148u * 181u + 180u;  // the south-east cell
  EXPECT_NEAR(m.vertices[i].x + origin.x, g.x_of_col(180), 1e-3);
  EXPECT_NEAR(m.vertices[i].y + origin.y, g.y_of_row(148), 1e-3);
}

TEST(GroundMesh, VertexNormalsFollowTheSlope) {
  // Heights rise eastward by 1 m per 10 m cell: normals lean west.
  std::vector<float> h;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) h.push_back(static_cast<float>(c));
  const GroundMesh m =
      build_ground_mesh(ElevationGrid(3, 3, GeoTransform{0, 30, 10, 10}, h), Vec3{});
  const Vec3f expected = normalize(Vec3f{-0.1f, 0.0f, 1.0f});
  EXPECT_NEAR(m.normals[4].x, expected.x, 1e-6);
  EXPECT_NEAR(m.normals[4].y, 0.0f, 1e-6);
}

}  // namespace
}  // namespace landsim::terrain
