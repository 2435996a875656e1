#include "trees/weber_penn/leaf_orientation.h"

#include <gtest/gtest.h>

namespace landsim::trees::weber_penn {
namespace {

Frame leaf_at(Vec3 position, Vec3 normal, Vec3 along) {
  Frame f;
  f.position = position;
  f.y = normalize(normal);
  f.z = normalize(along);
  f.x = cross(f.y, f.z);
  return f;
}

TEST(LeafOrientation, ZeroBendChangesNothing) {
  const Frame f = leaf_at({1, 0, 3}, {0, 1, 0}, {0, 0, 1});
  const Frame g = bend_leaf(f, 0.0);
  EXPECT_EQ(g.y, f.y);
  EXPECT_EQ(g.z, f.z);
}

TEST(LeafOrientation, FullBendTurnsTheFaceToTheSky) {
  const Vec3 normal = normalize(Vec3{1, -1, 0.2});
  const Frame f = leaf_at({2, 1, 3}, normal, normalize(cross(normal, Vec3{1, 1, 0})));
  const Frame g = bend_leaf(f, 1.0);
  EXPECT_NEAR(g.y.z, 1.0, 1e-9);
  EXPECT_NEAR(length(g.z), 1.0, 1e-9);
  EXPECT_NEAR(dot(g.y, g.z), 0.0, 1e-9);  // still a rigid frame
}

TEST(LeafOrientation, PartialBendTurnsOutwardAndUp) {
  // A leaf east of the trunk facing north: bending turns its face toward east and up.
  const Frame f = leaf_at({3, 0, 2}, {0, 1, 0}, {0, 0, 1});
  const Frame g = bend_leaf(f, 0.5);
  EXPECT_GT(g.y.x, 0.1);  // toward outward (east)
  EXPECT_GT(g.y.z, 0.1);  // and upward
  const Frame h = bend_leaf(f, 0.8);
  EXPECT_GT(h.y.z, g.y.z);
}

}  // namespace
}  // namespace landsim::trees::weber_penn
