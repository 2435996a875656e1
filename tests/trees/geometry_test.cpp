#include "trees/geometry.h"

#include <gtest/gtest.h>

namespace landsim::trees {
namespace {

TEST(TreeGeometry, CountsTrianglesOverEveryGroup) {
  TreeGeometry g;
  g.triangles[0].vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  g.triangles[0].indices = {0, 1, 2};
  g.triangles[4].vertices = {{0, 0, 5}, {1, 0, 5}, {0, 1, 6}, {2, -1, 4}};
  g.triangles[4].indices = {0, 1, 2, 0, 2, 3};
  EXPECT_EQ(g.triangle_count(), 3u);
  const auto b = g.bounds();
  EXPECT_EQ(b[0], (Vec3f{0, -1, 0}));
  EXPECT_EQ(b[1], (Vec3f{2, 1, 6}));
}

TEST(TreeGeometry, EmptyTreeHasZeroBounds) {
  const TreeGeometry g;
  EXPECT_EQ(g.triangle_count(), 0u);
  EXPECT_EQ(g.bounds()[0], Vec3f{});
  EXPECT_EQ(g.bounds()[1], Vec3f{});
}

}  // namespace
}  // namespace landsim::trees
