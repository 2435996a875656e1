#include "trees/graph_paths/initial_volume.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace landsim::trees::graph_paths {
namespace {

VolumePrimitive make(PrimitiveKind kind) {
  VolumePrimitive s;
  s.kind = kind;
  return s;
}

TEST(InitialVolume, SphereDepthIsTheDistanceToTheSurface) {
  VolumePrimitive s = make(PrimitiveKind::sphere);
  s.radius = 2.0;
  EXPECT_DOUBLE_EQ(s.depth({0, 0, 0}), 2.0);
  EXPECT_DOUBLE_EQ(s.depth({0, 1.5, 0}), 0.5);
  EXPECT_LT(s.depth({0, 0, 2.1}), 0.0);
}

TEST(InitialVolume, ConeDepthMeasuresToTheSlantedSide) {
  VolumePrimitive s = make(PrimitiveKind::cone);
  s.radius = 1.0;
  s.height = 1.0;
  // On the axis at half height the side is 0.5 away radially, at 45 degrees: 0.5 / sqrt 2.
  EXPECT_NEAR(s.depth({0, 0, 0.5}), 0.5 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(s.depth({0, 0, 0.1}), 0.1, 1e-12);  // nearer the base disc
  EXPECT_LT(s.depth({0.6, 0, 0.5}), 0.0);         // beyond the side
  EXPECT_LT(s.depth({0, 0, 1.01}), 0.0);          // above the apex
}

TEST(InitialVolume, CylinderFollowsItsAxis) {
  VolumePrimitive s = make(PrimitiveKind::cylinder);
  s.axis = {1, 0, 0};
  s.radius = 0.2;
  s.height = 1.0;
  EXPECT_NEAR(s.depth({0.5, 0, 0}), 0.2, 1e-12);
  EXPECT_LT(s.depth({0, 0, 0.5}), 0.0);
  EXPECT_LT(s.depth({-0.1, 0, 0}), 0.0);
}

TEST(InitialVolume, SpherePortionKeepsTheDirectionsWithinItsHalfAngle) {
  VolumePrimitive s = make(PrimitiveKind::sphere_portion);
  s.radius = 1.0;
  s.half_angle = std::numbers::pi / 6;  // 30 degrees
  const auto at = [](double degrees) {
    const double a = degrees * std::numbers::pi / 180;
    return Vec3{0.5 * std::sin(a), 0, 0.5 * std::cos(a)};
  };
  EXPECT_GT(s.depth(at(10)), 0.0);
  EXPECT_NEAR(s.depth(at(10)), 0.5 * std::sin(20 * std::numbers::pi / 180), 1e-12);
  EXPECT_LT(s.depth(at(45)), 0.0);
  // A portion wider than a hemisphere holds directions below the equator too.
  s.half_angle = 2.5;
  EXPECT_GT(s.depth(at(120)), 0.0);
}

TEST(InitialVolume, EllipsoidInsideMatchesItsEquation) {
  VolumePrimitive s = make(PrimitiveKind::ellipsoid);
  s.radii = {1.0, 2.0, 3.0};
  for (double t = -1.5; t <= 1.5; t += 0.1) {
    const Vec3 p{0.4 * t, 1.1 * t, 2.0 * t};
    const double f = p.x * p.x / 1.0 + p.y * p.y / 4.0 + p.z * p.z / 9.0;
    EXPECT_EQ(s.depth(p) > 0.0, f < 1.0) << t;
  }
  // A lower bound of the distance: never more than the gap along the shortest axis.
  EXPECT_LE(s.depth({0.5, 0, 0}), 0.5 + 1e-12);
}

TEST(InitialVolume, SurfaceOfRevolutionMatchesTheShapesItsProfileTraces) {
  VolumePrimitive rev = make(PrimitiveKind::revolution);
  rev.profile = {{0.0, 1.0}, {1.0, 0.0}};  // a cone of radius 1, height 1
  VolumePrimitive cone = make(PrimitiveKind::cone);
  cone.radius = 1.0;
  cone.height = 1.0;
  for (const Vec3& p : {Vec3{0, 0, 0.5}, Vec3{0.3, 0.1, 0.2}, Vec3{0.6, 0, 0.5}, Vec3{0, 0, 1.2}}) {
    // Inside, the same distance; outside, both negative (how negative is not specified).
    EXPECT_EQ(rev.depth(p) > 0, cone.depth(p) > 0) << p.x << " " << p.z;
    if (cone.depth(p) <= 0) continue;
    EXPECT_NEAR(rev.depth(p), cone.depth(p), 1e-12) << p.x << " " << p.z;
  }
  rev.profile = {{0.0, 0.5}, {1.0, 0.5}, {3.0, 0.5}};  // a cylinder, in two segments
  VolumePrimitive cylinder = make(PrimitiveKind::cylinder);
  cylinder.radius = 0.5;
  cylinder.height = 3.0;
  for (const Vec3& p : {Vec3{0, 0, 1.5}, Vec3{0.4, 0, 0.9}, Vec3{0.6, 0, 2}, Vec3{0, 0, -0.1}}) {
    // Inside, the same distance; outside, both negative (how negative is not specified).
    EXPECT_EQ(rev.depth(p) > 0, cylinder.depth(p) > 0) << p.x << " " << p.z;
    if (cylinder.depth(p) <= 0) continue;
    EXPECT_NEAR(rev.depth(p), cylinder.depth(p), 1e-12) << p.x << " " << p.z;
  }
  // A bulging profile: wider in the middle than at its ends.
  rev.profile = {{0.0, 0.2}, {1.0, 1.0}, {2.0, 0.2}};
  EXPECT_GT(rev.depth({0.8, 0, 1.0}), 0.0);
  EXPECT_LT(rev.depth({0.8, 0, 0.2}), 0.0);
  const Box b = rev.bounds();
  EXPECT_LE(b.lo.x, -1.0);
  EXPECT_GE(b.hi.z, 2.0);
}

TEST(InitialVolume, UnionTakesTheDeepestPartAndBoundsAll) {
  VolumePrimitive a = make(PrimitiveKind::sphere);
  VolumePrimitive b = make(PrimitiveKind::sphere);
  b.origin = {5, 0, 0};
  b.radius = 0.5;
  const InitialVolume v({a, b});
  EXPECT_TRUE(v.contains({0, 0, 0}));
  EXPECT_TRUE(v.contains({5.2, 0, 0}));
  EXPECT_FALSE(v.contains({3, 0, 0}));
  const Box box = v.bounds();
  EXPECT_LE(box.lo.x, -1.0);
  EXPECT_GE(box.hi.x, 5.5);
}

}  // namespace
}  // namespace landsim::trees::graph_paths
