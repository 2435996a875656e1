#include "trees/leaf_shape.h"

#include <gtest/gtest.h>

namespace landsim::trees {
namespace {

TEST(LeafShape, EveryTemplateFillsTheUnitFrame) {
  for (int k = 0; k <= 8; ++k) {
    const LeafTemplate t = make_leaf_template({static_cast<LeafShapeKind>(k), 5});
    ASSERT_FALSE(t.indices.empty()) << k;
    EXPECT_EQ(t.indices.size() % 3, 0u);
    float lo_x = 1, hi_x = -1, lo_y = 1, hi_y = -1;
    for (const Vec3f& v : t.vertices) {
      lo_x = std::min(lo_x, v.x);
      hi_x = std::max(hi_x, v.x);
      lo_y = std::min(lo_y, v.y);
      hi_y = std::max(hi_y, v.y);
    }
    EXPECT_NEAR(lo_x, -0.5f, 1e-5) << k;
    EXPECT_NEAR(hi_x, 0.5f, 1e-5) << k;
    EXPECT_NEAR(lo_y, 0.0f, 1e-5) << k;
    EXPECT_NEAR(hi_y, 1.0f, 1e-5) << k;
    EXPECT_GT(t.area, 0.1f) << k;
    EXPECT_LT(t.area, 1.0f) << k;
  }
}

TEST(LeafShape, FlatBladesFaceUp) {
  for (LeafShapeKind k :
       {LeafShapeKind::oval, LeafShapeKind::triangle, LeafShapeKind::oak3, LeafShapeKind::maple5}) {
    const LeafTemplate t = make_leaf_template({k, 6});
    for (std::size_t i = 0; i < t.indices.size(); i += 3) {
      const Vec3f a = t.vertices[t.indices[i]], b = t.vertices[t.indices[i + 1]],
                  c = t.vertices[t.indices[i + 2]];
      EXPECT_GE(cross(b - a, c - a).z, 0.0f) << static_cast<int>(k);
    }
  }
}

TEST(LeafShape, OvalAreaIsAnEllipses) {
  // Six triangles approximate the ellipse of axes 1 and 1/2 (area pi/4) from inside.
  const float area = make_leaf_template({LeafShapeKind::oval, 6}).area;
  EXPECT_GT(area, 0.55f);
  EXPECT_LT(area, 0.7854f);
}

TEST(LeafShape, ParsesIndicesAndArbaroNames) {
  LeafShape s;
  ASSERT_TRUE(parse_leaf_shape("0", s));
  EXPECT_EQ(s.kind, LeafShapeKind::oval);
  ASSERT_TRUE(parse_leaf_shape("disc1", s));
  EXPECT_EQ(s.kind, LeafShapeKind::disc_n);
  EXPECT_EQ(make_leaf_template(s).indices.size(), 3u);  // one triangle
  ASSERT_TRUE(parse_leaf_shape("disc3", s));
  EXPECT_EQ(make_leaf_template(s).indices.size(), 9u);
  ASSERT_TRUE(parse_leaf_shape("sphere", s));
  EXPECT_EQ(s.kind, LeafShapeKind::sphere);
  ASSERT_TRUE(parse_leaf_shape("palm", s));
  EXPECT_FALSE(parse_leaf_shape("fern", s));
  EXPECT_FALSE(parse_leaf_shape("disc0", s));
  EXPECT_FALSE(parse_leaf_shape("disc65", s));
  EXPECT_FALSE(parse_leaf_shape("disc99999999999", s));  // std::stoi's out_of_range escaped
  EXPECT_FALSE(parse_leaf_shape("9", s));
}

}  // namespace
}  // namespace landsim::trees
