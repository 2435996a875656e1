#include "trees/mesher.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace landsim::trees {
namespace {

StemSkeleton straight_stem(int level, int sections, double z0, double radius) {
  StemSkeleton s;
  s.level = level;
  for (int i = 0; i < sections; ++i) {
    s.sections.push_back({{0, 0, z0 + i}, {0, 0, 1}, {1, 0, 0}, radius});
  }
  return s;
}

TEST(Mesher, TubeHasTwoTrianglesPerRingPointAndSegment) {
  TreeSkeleton t;
  t.stems.push_back(straight_stem(0, 4, 0.0, 0.3));
  MeshResolution res;
  res.ring_points = {10, 5, 3, 3};
  const TreeGeometry g = mesh_tree(t, res);
  const GroupGeometry& trunk = g.group(Group::trunk);
  EXPECT_EQ(trunk.triangles.triangle_count(), 3u * 2u * 10u);
  EXPECT_EQ(trunk.triangles.vertices.size(), 44u);  // 4 rings of 10, the seam vertex repeated
  // Texture coordinates: u once around (0 to 1 at the repeated seam), v along the stem in
  // base circumferences (3 m of a 0.3 m radius stem: 3 / (2 pi 0.3)).
  ASSERT_EQ(trunk.triangles.uvs.size(), 2u * 44u);
  EXPECT_FLOAT_EQ(trunk.triangles.uvs[0], 0.0f);
  EXPECT_FLOAT_EQ(trunk.triangles.uvs[2 * 10], 1.0f);
  EXPECT_FLOAT_EQ(trunk.triangles.uvs[2 * 43 + 1],
                  static_cast<float>(3.0 / (2.0 * std::numbers::pi * 0.3)));
  EXPECT_EQ(trunk.lines.segment_count(), 3u);
  EXPECT_FLOAT_EQ(trunk.lines.radii[0], 0.3f);
  for (std::size_t i = 0; i < trunk.triangles.vertices.size(); ++i) {
    const Vec3f v = trunk.triangles.vertices[i];
    EXPECT_NEAR(std::hypot(v.x, v.y), 0.3, 1e-6);
    // Normals point outward, and the triangles wind so that their face normals do too.
    EXPECT_NEAR(dot(trunk.triangles.normals[i], Vec3f{v.x, v.y, 0.0f}) / 0.3f, 1.0f, 1e-5);
  }
  const auto& idx = trunk.triangles.indices;
  for (std::size_t i = 0; i < idx.size(); i += 3) {
    const Vec3f a = trunk.triangles.vertices[idx[i]], b = trunk.triangles.vertices[idx[i + 1]],
                c = trunk.triangles.vertices[idx[i + 2]];
    const Vec3f n = cross(b - a, c - a);
    const Vec3f centre = (a + b + c) / 3.0f;
    EXPECT_GT(dot(n, Vec3f{centre.x, centre.y, 0.0f}), 0.0f);
  }
}

TEST(Mesher, ZeroRadiusEndClosesToAnApex) {
  TreeSkeleton t;
  StemSkeleton s = straight_stem(1, 3, 0.0, 0.1);
  s.sections.back().radius = 0.0;
  t.stems.push_back(s);
  const TreeGeometry g = mesh_tree(t, MeshResolution{});
  EXPECT_EQ(g.group(Group::level1).triangles.vertices.size(), 2u * 6u + 1u);
  EXPECT_EQ(g.group(Group::level1).triangles.triangle_count(), 2u * 5u + 5u);
}

TEST(Mesher, LobesShapeTheTrunkOnly) {
  TreeSkeleton t;
  StemSkeleton s = straight_stem(0, 2, 0.0, 1.0);
  s.lobes = 4;
  s.lobe_depth = 0.1;
  t.stems.push_back(s);
  MeshResolution res;
  res.ring_points[0] = 16;
  const GroupGeometry trunk = mesh_tree(t, res).group(Group::trunk);
  EXPECT_NEAR(std::hypot(trunk.triangles.vertices[0].x, trunk.triangles.vertices[0].y), 1.1,
              1e-6);  // lobe
  EXPECT_NEAR(std::hypot(trunk.triangles.vertices[2].x, trunk.triangles.vertices[2].y), 0.9,
              1e-6);  // between
}

TEST(Mesher, StemsGoToTheirLevelGroupRankMajor) {
  TreeSkeleton t;
  for (int i = 0; i < 20; ++i) t.stems.push_back(straight_stem(1, 2, static_cast<double>(i), 0.05));
  t.stems.push_back(straight_stem(5, 2, 0.0, 0.01));  // level 5 joins level 3+
  const TreeGeometry g = mesh_tree(t, MeshResolution{});
  const GroupGeometry& l1 = g.group(Group::level1);
  ASSERT_EQ(l1.item_count, 20u);
  EXPECT_EQ(l1.mass_count(), 2u);
  EXPECT_EQ(g.group(Group::level3plus).item_count, 1u);
  // Stored order: rank 0 of mass 0 (stem 0) then rank 0 of mass 1 (stem 16), then stem 1...
  const auto item_z = [&](std::size_t k) {
    return l1.lines.points[l1.lines.first[l1.lines_in_prefix(k)]].z;
  };
  EXPECT_FLOAT_EQ(item_z(0), 0.0f);
  EXPECT_FLOAT_EQ(item_z(1), 16.0f);
  EXPECT_FLOAT_EQ(item_z(2), 1.0f);
  // The prefix of the first two stored items holds exactly their primitives.
  EXPECT_EQ(l1.triangles_in_prefix(2), 2u * 2u * 5u);
  EXPECT_EQ(l1.lines_in_prefix(2), 2u);
  EXPECT_EQ(l1.triangles_in_prefix(20), l1.triangles.triangle_count());
}

TEST(Mesher, LeafPointsCarryTheBladesArea) {
  TreeSkeleton t;
  t.leaf_shape = {LeafShapeKind::triangle, 1};
  t.leaves.push_back({{0, 0, 5}, {1, 0, 0}, {0, 0, 1}, 0.2, 0.1});
  const GroupGeometry leaves = mesh_tree(t, MeshResolution{}).group(Group::leaves);
  ASSERT_EQ(leaves.triangles.triangle_count(), 1u);
  ASSERT_EQ(leaves.points.point_count(), 1u);
  const double area = 0.5 * 0.2 * 0.1;
  EXPECT_NEAR(std::numbers::pi * leaves.points.radii[0] * leaves.points.radii[0], area, 1e-7);
  EXPECT_NEAR(leaves.points.centres[0].x, 0.1f, 1e-6);  // half way along the blade
  // The blade lies in the plane of the normal given, along its direction.
  for (const Vec3f& v : leaves.triangles.vertices) EXPECT_NEAR(v.z, 5.0f, 1e-6);
}

TEST(Mesher, LeafVigourIsStoredQuantisedAtEachLeafsStoredPosition) {
  TreeSkeleton t;
  t.leaf_shape = {LeafShapeKind::triangle, 1};
  const float vigour[] = {0.0f, 1.0f, 0.3f, 0.93f, 0.5f, 0.07f, 1.0f};
  for (float v : vigour) {
    LeafSkeleton leaf{{0, 0, 5}, {1, 0, 0}, {0, 0, 1}, 0.2, 0.1};
    leaf.vigour = v;
    t.leaves.push_back(leaf);
  }
  const GroupGeometry leaves = mesh_tree(t, MeshResolution{}).group(Group::leaves);
  ASSERT_EQ(leaves.item_vigour.size(), 7u);
  for (std::size_t i = 0; i < 7; ++i) {
    const std::size_t stored = rank_major_position(i, 7, kLeafMassSize);
    const float expected = std::round(vigour[i] * 7.0f) / 7.0f;
    EXPECT_FLOAT_EQ(leaves.item_vigour[stored], expected) << i;
    // One triangle per leaf here: triangle `stored` is that leaf's.
    EXPECT_FLOAT_EQ(leaves.vigour_of_triangle(static_cast<std::uint32_t>(stored)), expected);
  }
  // Full vigour everywhere stores nothing (the other cores).
  for (LeafSkeleton& leaf : t.leaves) leaf.vigour = 1.0f;
  EXPECT_TRUE(mesh_tree(t, MeshResolution{}).group(Group::leaves).item_vigour.empty());
}

}  // namespace
}  // namespace landsim::trees
