// Each camera model projects known scene points where its textbook formula, written out
// here independently of renderer/camera.cpp, puts them (within 0.05 pixel), and its rays go
// back through those points.
#include "renderer/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "renderer/lens_distortion.h"

namespace landsim::renderer {
namespace {

constexpr double kPi = std::numbers::pi;
const View kView{"v", {10.0, -20.0, 5.0}, {10.0, 80.0, 5.0}, 60.0, 200, 100};

// The angle, in pixels of `pixel_angle` radians, between the ray and the way to p.
double miss(const Ray& r, const Vec3& p, double pixel_angle) {
  const Vec3 to = normalize(p - Vec3(r.origin));
  const double c = std::clamp(dot(to, normalize(Vec3(r.direction))), -1.0, 1.0);
  return std::acos(c) / pixel_angle;
}

TEST(Camera, CentreRayLooksAtTheTarget) {
  const Ray r = *Camera(kView).ray(100.0f, 50.0f);
  EXPECT_NEAR(r.direction.x, 0.0f, 1e-6);
  EXPECT_NEAR(r.direction.y, 1.0f, 1e-6);
  EXPECT_NEAR(r.direction.z, 0.0f, 1e-6);
  EXPECT_EQ(r.origin, (Vec3f{10.0f, -20.0f, 5.0f}));
}

TEST(Camera, TopEdgeIsHalfTheVerticalFovUp) {
  const Camera cam(kView);
  const Ray top = *cam.ray(100.0f, 0.0f);
  EXPECT_NEAR(std::atan2(top.direction.z, top.direction.y), 30.0 * kPi / 180.0, 1e-5);
  EXPECT_LT(cam.ray(100.0f, 100.0f)->direction.z, 0.0f);
}

TEST(Camera, ImageLeftIsWestWhenLookingNorth) {
  const Camera cam(kView);
  EXPECT_LT(cam.ray(0.0f, 50.0f)->direction.x, 0.0f);
  EXPECT_GT(cam.ray(200.0f, 50.0f)->direction.x, 0.0f);
  // Horizontal half-angle follows the aspect ratio: tan = 2 * tan(30 deg).
  const Ray right = *cam.ray(200.0f, 50.0f);
  EXPECT_NEAR(right.direction.x / right.direction.y, 2.0 * std::tan(kPi / 6.0), 1e-5);
}

// Looking north from the origin, level: camera x = east, y (down) = -up, z = north.
TEST(Camera, PerspectiveWithAPrincipalPointIsThePinholeFormula) {
  View v{"p", {0.0, 0.0, 0.0}, {0.0, 100.0, 0.0}, 50.0, 640, 480};
  v.lens.principal_x = 12.5;
  v.lens.principal_y = -7.0;
  v.lens.fx_over_fy = 1.1;
  const double fy = 240.0 / std::tan(25.0 * kPi / 180.0), fx = 1.1 * fy;
  const double cx = 320.0 + 12.5, cy = 240.0 - 7.0;  // from the top-left corner
  const Camera cam(v);
  for (const Vec3 p : {Vec3{3.0, 40.0, 2.0}, Vec3{-10.0, 25.0, -6.0}, Vec3{0.5, 300.0, 40.0}}) {
    const double u = fx * p.x / p.y + cx, w = fy * -p.z / p.y + cy;
    const auto at = cam.project(p);
    ASSERT_TRUE(at);
    EXPECT_NEAR(at->x, u, 0.05);
    EXPECT_NEAR(at->y, w, 0.05);
    EXPECT_LT(miss(*cam.ray(float(u), float(w)), p, 1.0 / fy), 0.05);
  }
  // K in OpenCV's convention: pixel (0, 0)'s centre at 0.
  const std::array<double, 9> k = cam.intrinsics();
  EXPECT_NEAR(k[0], fx, 1e-9);
  EXPECT_NEAR(k[2], cx - 0.5, 1e-9);
  EXPECT_NEAR(k[5], cy - 0.5, 1e-9);
  EXPECT_FALSE(Camera(v).project({0.0, -5.0, 0.0}));  // behind the camera
}

TEST(Camera, RollTurnsTheCameraClockwiseSoTheSceneTurnsTheOtherWay) {
  View v{"r", {0.0, 0.0, 0.0}, {0.0, 100.0, 0.0}, 40.0, 400, 400};
  v.roll_deg = 90.0;
  // The camera's right side now points down: a point east of the axis shows above the centre.
  const auto east = Camera(v).project({5.0, 100.0, 0.0});
  ASSERT_TRUE(east);
  EXPECT_NEAR(east->x, 200.0, 0.05);
  EXPECT_LT(east->y, 190.0);
  // 30 degrees: image coordinates about the centre (x right, y up) turn by -30 degrees.
  v.roll_deg = 30.0;
  const double f = 200.0 / std::tan(20.0 * kPi / 180.0), a = 30.0 * kPi / 180.0;
  const Vec3 p{4.0, 100.0, 3.0};
  const double x = f * p.x / p.y, y = f * p.z / p.y;
  const double xr = std::cos(a) * x - std::sin(a) * y, yr = std::sin(a) * x + std::cos(a) * y;
  const auto at = Camera(v).project(p);
  ASSERT_TRUE(at);
  EXPECT_NEAR(at->x, 200.0 + xr, 0.05);
  EXPECT_NEAR(at->y, 200.0 - yr, 0.05);
}

TEST(Camera, NadirHasNorthUpAndTheHeadingTurnsIt) {
  View v{"n", {0.0, 0.0, 2000.0}, {0.0, 0.0, 0.0}, 30.0, 300, 200};
  const Camera down(v);
  const double f = 100.0 / std::tan(15.0 * kPi / 180.0);
  const auto north = down.project({0.0, 100.0, 0.0});
  const auto east = down.project({100.0, 0.0, 0.0});
  ASSERT_TRUE(north && east);
  EXPECT_NEAR(north->x, 150.0, 0.05);
  EXPECT_NEAR(north->y, 100.0 - f * 100.0 / 2000.0, 0.05);
  EXPECT_NEAR(east->x, 150.0 + f * 100.0 / 2000.0, 0.05);
  EXPECT_NEAR(east->y, 100.0, 0.05);
  // Heading east: east is at the top, south on the right.
  v.heading_deg = 90.0;
  const auto e = Camera(v).project({100.0, 0.0, 0.0});
  const auto s = Camera(v).project({0.0, -100.0, 0.0});
  EXPECT_LT(e->y, 99.0);
  EXPECT_NEAR(e->x, 150.0, 0.05);
  EXPECT_GT(s->x, 151.0);
  // Straight up works too.
  const View up{"u", {0.0, 0.0, 0.0}, {0.0, 0.0, 10.0}, 30.0, 300, 200};
  EXPECT_NEAR(Camera(up).ray(150.0f, 100.0f)->direction.z, 1.0f, 1e-6f);
}

TEST(Camera, AGivenUpVectorSetsTheImagesUp) {
  View v{"g", {0.0, 0.0, 0.0}, {0.0, 0.0, -10.0}, 30.0, 100, 100};
  v.up = {1.0, 0.0, 0.0};  // looking down with east at the top
  const auto e = Camera(v).project({1.0, 0.0, -10.0});
  ASSERT_TRUE(e);
  EXPECT_LT(e->y, 49.0);
  EXPECT_NEAR(e->x, 50.0, 0.05);
}

TEST(Camera, OrthographicPixelsAreTheExtentOverTheSize) {
  View v{"o", {100.0, 200.0, 500.0}, {100.0, 200.0, 0.0}, 40.0, 400, 200};
  v.lens.projection = Projection::orthographic;
  v.lens.extent_width = 800.0;
  v.lens.extent_height = 400.0;
  const Camera cam(v);
  for (const Vec3 p : {Vec3{50.0, 260.0, 0.0}, Vec3{-280.0, 390.0, 37.0}}) {
    const auto at = cam.project(p);
    ASSERT_TRUE(at);
    EXPECT_NEAR(at->x, (p.x - 100.0) / 2.0 + 200.0, 0.05);
    EXPECT_NEAR(at->y, (200.0 - p.y) / 2.0 + 100.0, 0.05);
    const Ray r = *cam.ray(float(at->x), float(at->y));
    EXPECT_NEAR(r.origin.x, p.x, 1e-3);
    EXPECT_NEAR(r.origin.y, p.y, 1e-3);
    EXPECT_EQ(r.direction, (Vec3f{0.0f, 0.0f, -1.0f}));
  }
}

TEST(Camera, FisheyesMapTheAngleFromTheAxisToTheRadius) {
  for (const Projection p : {Projection::fisheye_equidistant, Projection::fisheye_equisolid}) {
    View v{"f", {0.0, 0.0, 0.0}, {0.0, 10.0, 0.0}, 200.0, 500, 500};
    v.lens.projection = p;
    v.lens.fisheye_focal = 140.0;
    const Camera cam(v);
    const double theta = 80.0 * kPi / 180.0;
    const double r =
        p == Projection::fisheye_equidistant ? 140.0 * theta : 2.0 * 140.0 * std::sin(0.5 * theta);
    // 80 degrees off the axis, towards the upper left at 45 degrees.
    const Vec3 q{-std::sin(theta) * std::sqrt(0.5), std::cos(theta),
                 std::sin(theta) * std::sqrt(0.5)};
    const auto at = cam.project(q * 50.0);
    ASSERT_TRUE(at);
    EXPECT_NEAR(at->x, 250.0 - r * std::sqrt(0.5), 0.05);
    EXPECT_NEAR(at->y, 250.0 - r * std::sqrt(0.5), 0.05);
    EXPECT_LT(miss(*cam.ray(float(at->x), float(at->y)), q * 50.0, 1.0 / 140.0), 0.05);
    // Beyond half the fov there is no ray, and nothing is shown.
    EXPECT_FALSE(cam.ray(0.0f, 0.0f));
    EXPECT_FALSE(cam.project({0.0, -10.0, 0.0}));
  }
}

TEST(Camera, SphericalIsAzimuthAcrossAndElevationDown) {
  View v{"s", {0.0, 0.0, 0.0}, {0.0, 10.0, 0.0}, 40.0, 720, 360};
  v.lens.projection = Projection::spherical;
  const Camera cam(v);
  // East (90 degrees right of the heading) and 45 degrees up.
  const auto at = cam.project({10.0, 0.0, 10.0});
  ASSERT_TRUE(at);
  EXPECT_NEAR(at->x, 720.0 * 0.75, 0.05);
  EXPECT_NEAR(at->y, 360.0 * 0.25, 0.05);
  const auto behind = cam.project({-1.0, -10.0, -3.0});
  ASSERT_TRUE(behind);
  EXPECT_NEAR(behind->x, 360.0 * (std::atan2(-1.0, -10.0) / kPi + 1.0), 0.05);
  EXPECT_LT(miss(*cam.ray(float(at->x), float(at->y)), {10.0, 0.0, 10.0}, kPi / 360.0), 0.05);
}

// OpenCV's distortion (cv::projectPoints), written out.
std::pair<double, double> opencv_distort(double x, double y, const Distortion& d) {
  const double r2 = x * x + y * y;
  const double radial = 1 + d.k1 * r2 + d.k2 * r2 * r2 + d.k3 * r2 * r2 * r2;
  return {x * radial + 2 * d.p1 * x * y + d.p2 * (r2 + 2 * x * x),
          y * radial + d.p1 * (r2 + 2 * y * y) + 2 * d.p2 * x * y};
}

TEST(Camera, DistortionPlacesPointsAsOpenCvDoes) {
  View v{"d", {0.0, 0.0, 0.0}, {0.0, 100.0, 0.0}, 60.0, 640, 480};
  v.lens.distortion = {-0.28, 0.07, 0.0, 1e-3, -5e-4};
  v.lens.principal_x = 4.0;
  const Camera cam(v);
  const double f = 240.0 / std::tan(30.0 * kPi / 180.0);
  for (const Vec3 p : {Vec3{30.0, 60.0, 20.0}, Vec3{-2.0, 50.0, -1.0}, Vec3{-35.0, 60.0, 25.0}}) {
    const auto [xd, yd] = opencv_distort(p.x / p.y, -p.z / p.y, v.lens.distortion);
    const double u = f * xd + 324.0, w = f * yd + 240.0;
    const auto at = cam.project(p);
    ASSERT_TRUE(at);
    EXPECT_NEAR(at->x, u, 0.05);
    EXPECT_NEAR(at->y, w, 0.05);
    EXPECT_LT(miss(*cam.ray(float(u), float(w)), p, 1.0 / f), 0.05);
  }
  // A straight line above the centre comes out curved: its ends are pulled in towards the
  // centre more than its middle, which bows outwards (barrel distortion, k1 < 0).
  const auto a = cam.project({-40.0, 60.0, 25.0}), b = cam.project({40.0, 60.0, 25.0});
  const auto m = cam.project({0.0, 60.0, 25.0});
  EXPECT_LT(m->y, 0.5 * (a->y + b->y) - 1.0);
}

TEST(LensDistortion, AFoldInsideTheFrameIsFound) {
  EXPECT_TRUE(unfolded_within({-0.28, 0.07, 0.0, 0.0, 0.0}, 0.7));
  // r (1 - 0.5 r^2) stops growing at r = 0.816, where it reaches 0.544.
  EXPECT_FALSE(unfolded_within({-0.5, 0.0, 0.0, 0.0, 0.0}, 0.6));
  EXPECT_TRUE(unfolded_within({-0.5, 0.0, 0.0, 0.0, 0.0}, 0.5));
}

TEST(Camera, AThinLensFocusesItsRaysOnThePlaneInFocus) {
  View v{"t", {0.0, 0.0, 0.0}, {0.0, 100.0, 0.0}, 40.0, 100, 100};
  v.lens.aperture_radius = 0.05;
  v.lens.focus_distance = 25.0;
  const Camera cam(v);
  const Ray centre = *cam.ray(70.5f, 20.5f);
  const Vec3 focus = Vec3(centre.origin) + (25.0 / centre.direction.y) * Vec3(centre.direction);
  double spread = 0.0;
  for (const auto& [lu, lv] : {std::pair{0.1f, 0.2f}, {0.9f, 0.4f}, {0.3f, 0.95f}}) {
    const Ray r = *cam.ray(70.5f, 20.5f, lu, lv);
    const double t = (25.0 - r.origin.y) / r.direction.y;
    EXPECT_LT(length(Vec3(r.origin) + t * Vec3(r.direction) - focus), 1e-4);
    spread = std::max(spread, length(Vec3(r.origin) - Vec3(centre.origin)));
  }
  EXPECT_GT(spread, 0.01);  // the rays do leave from across the aperture
}

TEST(Camera, DetailRangeFollowsThePixelFootprint) {
  View o{"o", {0.0, 0.0, 500.0}, {0.0, 0.0, 0.0}, 40.0, 400, 200};
  o.lens.projection = Projection::orthographic;
  o.lens.extent_width = 800.0;
  o.lens.extent_height = 400.0;
  // 2 m pixels: the reference camera's pixel is 2 m wide at 2 / (0.06 degrees) metres.
  const double r2 = 2.0 / (0.06 * kPi / 180.0);
  EXPECT_NEAR(calibrated_view_range(o, 10.0), r2, 1e-6 * r2);
  EXPECT_NEAR(calibrated_view_range(o, 5000.0), r2, 1e-6 * r2);
  // A fisheye's central pixel spans 1 / f radians.
  View f{"f", {0.0, 0.0, 0.0}, {0.0, 10.0, 0.0}, 180.0, 400, 400};
  f.lens.projection = Projection::fisheye_equidistant;
  f.lens.fisheye_focal = 100.0;
  EXPECT_NEAR(calibrated_view_range(f, 300.0), 300.0 * 0.01 / (0.06 * kPi / 180.0), 1e-6);
  EXPECT_NEAR(pixels_across(f, 3.0, 300.0), 3.0 / (300.0 * 0.01), 1e-9);
}

}  // namespace
}  // namespace landsim::renderer
