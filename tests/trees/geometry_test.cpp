#include "trees/geometry.h"

#include <gtest/gtest.h>

#include <set>

namespace landsim::trees {
namespace {

TEST(TreeGeometry, CountsTrianglesAndBoundsOverEveryGroup) {
  TreeGeometry g;
  g.group(Group::trunk).triangles.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  g.group(Group::trunk).triangles.indices = {0, 1, 2};
  g.group(Group::leaves).triangles.vertices = {{0, 0, 5}, {1, 0, 5}, {0, 1, 6}, {2, -1, 4}};
  g.group(Group::leaves).triangles.indices = {0, 1, 2, 0, 2, 3};
  EXPECT_EQ(g.triangle_count(), 3u);
  const auto b = g.bounds();
  EXPECT_EQ(b[0], (Vec3f{0, -1, 0}));
  EXPECT_EQ(b[1], (Vec3f{2, 1, 6}));
}

TEST(TreeGeometry, EmptyTreeHasZeroBounds) {
  const TreeGeometry g;
  EXPECT_EQ(g.triangle_count(), 0u);
  EXPECT_EQ(g.bounds()[0], Vec3f{});
}

TEST(RankMajor, PositionsArePermutationWithRankZeroFirst) {
  for (std::size_t count : {1u, 4u, 15u, 16u, 17u, 50u, 100u}) {
    std::set<std::size_t> seen;
    for (std::size_t i = 0; i < count; ++i) seen.insert(rank_major_position(i, count, 16));
    EXPECT_EQ(seen.size(), count);
    EXPECT_EQ(*seen.rbegin(), count - 1);
  }
  // 50 items in masses of 16: masses 0..3 (the last holds 2). Rank 0 of each comes first.
  EXPECT_EQ(rank_major_position(0, 50, 16), 0u);
  EXPECT_EQ(rank_major_position(16, 50, 16), 1u);
  EXPECT_EQ(rank_major_position(32, 50, 16), 2u);
  EXPECT_EQ(rank_major_position(48, 50, 16), 3u);
  EXPECT_EQ(rank_major_position(1, 50, 16), 4u);   // rank 1 of mass 0
  EXPECT_EQ(rank_major_position(49, 50, 16), 7u);  // rank 1 of the short last mass
  EXPECT_EQ(rank_major_position(2, 50, 16), 8u);   // rank 2: only three masses have it
  EXPECT_EQ(rank_major_position(47, 50, 16), 49u);
}

}  // namespace
}  // namespace landsim::trees
