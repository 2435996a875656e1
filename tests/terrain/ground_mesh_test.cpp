#include "terrain/ground_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
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

// The mesh's area seen from above, m2.
double plan_area(const GroundMesh& m) {
  double area = 0.0;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) area += 0.5 * triangle_normal(m, t).z;
  return area;
}

// The heights of the triangles over (x, y), seen from above (edges included).
std::vector<double> heights_over(const GroundMesh& m, double x, double y) {
  std::vector<double> out;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const Vec3 a(m.vertices[m.indices[3 * t]]), b(m.vertices[m.indices[3 * t + 1]]),
        c(m.vertices[m.indices[3 * t + 2]]);
    const double d = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    const double u = ((b.x - x) * (c.y - y) - (c.x - x) * (b.y - y)) / d;
    const double v = ((c.x - x) * (a.y - y) - (a.x - x) * (c.y - y)) / d;
    const double w = 1.0 - u - v;
    if (u >= -1e-9 && v >= -1e-9 && w >= -1e-9) out.push_back(u * a.z + v * b.z + w * c.z);
  }
  return out;
}

TEST(GroundMesh, AWholeGridIsDrawnToItsExtentFacingUp) {
  const GroundMesh m = build_ground_mesh(flat_grid(3), Vec3{});
  EXPECT_EQ(m.vertices.size(), m.normals.size());
  // The quads between the nine centres, two triangles each, on the centres' own vertices.
  std::size_t on_centres = 0;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    EXPECT_GT(triangle_normal(m, t).z, 0.0f);
    on_centres += m.indices[3 * t] < 9 && m.indices[3 * t + 1] < 9 && m.indices[3 * t + 2] < 9;
  }
  EXPECT_EQ(on_centres, 8u);
  // And the outer cells to the grid's edge: 30 m x 30 m, cell edges at 0 and 30.
  EXPECT_NEAR(plan_area(m), 900.0, 1e-6);
  float lo = 1e9f, hi = -1e9f;
  for (const Vec3f& v : m.vertices) lo = std::min(lo, v.x), hi = std::max(hi, v.x);
  EXPECT_EQ(lo, 0.0f);
  EXPECT_EQ(hi, 30.0f);
}

// Each cell with data drawn over its whole square, each nodata cell's square left open: a
// point a quarter cell from any cell's centre is over ground exactly when the cell has data.
TEST(GroundMesh, EachCellWithDataIsDrawnWholeAndNoNodataCell) {
  for (const std::vector<int> holes : {std::vector<int>{0}, {4}, {1, 5}, {0, 2, 6, 8}}) {
    const ElevationGrid g = flat_grid(3, holes);
    const GroundMesh m = build_ground_mesh(g, Vec3{});
    EXPECT_NEAR(plan_area(m), 100.0 * (9 - static_cast<double>(holes.size())), 1e-6);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        for (const double dx : {-2.5, 0.0, 2.5})
          for (const double dy : {-2.5, 0.0, 2.5}) {
            const auto over = heights_over(m, g.x_of_col(c) + dx, g.y_of_row(r) + dy);
            EXPECT_EQ(!over.empty(), g.valid(c, r)) << c << "," << r << " " << dx << "," << dy;
            for (const double h : over) EXPECT_NEAR(h, 10.0, 1e-5);
          }
    for (std::size_t t = 0; t < m.triangle_count(); ++t) EXPECT_GT(triangle_normal(m, t).z, 0.0f);
  }
}

// On a slope with nodata cells, no crack: every edge of the mesh is met from both sides, but
// where data ends (a cell's side with nodata or the grid's edge beyond it). Edges keyed by
// their ends' positions: the quads beside the holes share the whole quads' sides exactly.
TEST(GroundMesh, TheSurfaceAroundNodataHasNoCracks) {
  const int n = 6;
  std::vector<float> h(n * n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c)
      h[r * n + c] = static_cast<float>(100.0 + 3.0 * c - 2.0 * r + (c * r % 3));
  for (const int hole : {8, 9, 15, 27}) h[hole] = NAN;
  const ElevationGrid g(n, n, GeoTransform{0.0, 10.0 * n, 10.0, 10.0}, h);
  const GroundMesh m = build_ground_mesh(g, Vec3{});
  using Point = std::array<float, 3>;
  std::map<std::pair<Point, Point>, int> edges;  // directed
  const auto point = [&](std::uint32_t i) {
    return Point{m.vertices[i].x, m.vertices[i].y, m.vertices[i].z};
  };
  for (std::size_t t = 0; t < m.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k)
      ++edges[{point(m.indices[3 * t + k]), point(m.indices[3 * t + (k + 1) % 3])}];
  int open = 0;
  for (const auto& [edge, count] : edges) {
    EXPECT_EQ(count, 1);
    if (edges.count({edge.second, edge.first})) continue;
    ++open;
    // An open edge: on a cell border, with data on one side only.
    const double mx = 0.5 * (edge.first[0] + edge.second[0]),
                 my = 0.5 * (edge.first[1] + edge.second[1]);
    const double ex = edge.second[0] - edge.first[0], ey = edge.second[1] - edge.first[1];
    const double len = std::hypot(ex, ey);
    const auto valid_at = [&](double x, double y) {
      const int c = static_cast<int>(std::floor(x / 10.0)),
                r = static_cast<int>(std::floor((60.0 - y) / 10.0));
      return c >= 0 && r >= 0 && c < n && r < n && g.valid(c, r);
    };
    // Left of a counter-clockwise triangle's edge is inside: data there, none to the right.
    EXPECT_TRUE(valid_at(mx - 0.5 * ey / len, my + 0.5 * ex / len)) << mx << "," << my;
    EXPECT_FALSE(valid_at(mx + 0.5 * ey / len, my - 0.5 * ex / len)) << mx << "," << my;
  }
  EXPECT_GT(open, 0);
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
