#include "trees/self_organizing/markers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace landsim::trees::self_organizing {
namespace {

TEST(Markers, EnvelopeMarkersFillItAtItsDensity) {
  Envelope e;
  e.kind = EnvelopeKind::ellipsoid;
  e.centre = {0, 0, 3};
  e.radii = {2, 1, 1.5};
  e.density = 100;
  Random rng(1, 0);
  MarkerSet markers;
  add_envelope_markers(e, rng, markers);
  for (const Vec3& p : markers.points()) ASSERT_TRUE(e.contains(p));
  const double volume = 4.0 / 3.0 * std::numbers::pi * 2 * 1 * 1.5;
  EXPECT_NEAR(static_cast<double>(markers.size()), e.density * volume, 0.05 * e.density * volume);
}

TEST(Markers, StrokeMarkersFollowTheBrushAndExpire) {
  BrushStroke s;
  s.points = {{{0, 0, 1}, 0.5}, {{0, 0, 3}, 0.5}, {{2, 0, 3}, 1.0}};
  s.start_step = 2;
  s.points_per_step = 0.5;
  s.markers_per_step = 50;
  s.max_age = 3;
  Random rng(2, 0);
  MarkerSet markers;
  add_stroke_markers(s, 1, rng, markers);
  EXPECT_EQ(markers.size(), 0u);           // before the stroke starts
  add_stroke_markers(s, 4, rng, markers);  // t = 1: at the second point
  ASSERT_EQ(markers.size(), 50u);
  for (const Vec3& p : markers.points()) EXPECT_LE(length(p - Vec3{0, 0, 3}), 0.5 + 1e-12);
  markers.expire(6);  // born at step 4, living 3 steps: 4, 5, 6
  EXPECT_EQ(markers.size(), 50u);
  markers.expire(7);
  EXPECT_EQ(markers.size(), 0u);
  StrokePoint where;
  EXPECT_FALSE(brush_position(s, 7, where));  // t = 2.5: past the last point
}

TEST(Markers, ConeMarkersLieInTheCone) {
  Random rng(4, 0);
  MarkerSet markers;
  const Vec3 axis = normalize(Vec3{1, 0, 1});
  add_cone_markers({1, 1, 1}, axis, std::numbers::pi / 3, 2.0, 200, 1, rng, markers);
  ASSERT_EQ(markers.size(), 200u);
  for (const Vec3& p : markers.points()) {
    const Vec3 d = p - Vec3{1, 1, 1};
    EXPECT_LE(length(d), 2.0);
    EXPECT_GE(dot(normalize(d), axis), std::cos(std::numbers::pi / 6) - 1e-12);
  }
}

}  // namespace
}  // namespace landsim::trees::self_organizing
