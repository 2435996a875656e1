// Vignetting (docs/SENSOR.md "Vignetting"). The natural fall-off is checked against what it
// stands for, measured here through the camera's own rays: a pixel's irradiance from a
// uniformly bright scene is the pupil's foreshortening cos(theta) times the solid angle the
// pixel sees, relative to the axis. The lens polynomial is lensfun's "pa" model.
#include "renderer/sensor/vignetting.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "renderer/camera.h"

namespace landsim::renderer {
namespace {

// The field vignetting sees for `v`, from the camera's K (pixel centres on integers there).
ImageField field_of(const View& v) {
  const std::array<double, 9> k = Camera(v).intrinsics();
  ImageField f;
  f.projection = v.lens.projection;
  f.fx = k[0];
  f.fy = k[4];
  f.cx = k[2] + 0.5;
  f.cy = k[5] + 0.5;
  f.distortion = v.lens.distortion;
  f.half_diagonal_px = 0.5 * std::hypot(v.width, v.height);
  return f;
}

Vec3 direction(const Camera& c, double x, double y) {
  return Vec3(c.ray(static_cast<float>(x), static_cast<float>(y))->direction);
}

// cos(theta) x the solid angle of a small square of image around (x, y), from the rays
// through its edges' midpoints (the tangent parallelogram on the unit sphere).
double seen(const Camera& c, const Vec3& forward, double x, double y) {
  constexpr double h = 0.25;
  const Vec3 across = direction(c, x + h, y) - direction(c, x - h, y);
  const Vec3 down = direction(c, x, y + h) - direction(c, x, y - h);
  return dot(direction(c, x, y), forward) * length(cross(across, down));
}

// The natural fall-off at several points of each lens equals cos(theta) x the pixel's solid
// angle, relative to the axis, within 0.2%.
void expect_fall_off_is_the_solid_angle(const View& v) {
  const Camera camera(v);
  const ImageField f = field_of(v);
  const Vec3 forward = normalize(v.target - v.position);
  const double axis = seen(camera, forward, f.cx, f.cy);
  for (const auto& [x, y] : {std::pair{0.3, 0.4}, {0.9, 0.5}, {0.25, 0.7}, {0.6, 0.1}}) {
    const double px = x * v.width, py = y * v.height;
    const double expected = seen(camera, forward, px, py) / axis;
    EXPECT_NEAR(natural_illumination(f, px, py) / expected, 1.0, 2e-3)
        << projection_name(v.lens.projection) << " at " << px << ", " << py << ": expected "
        << expected;
  }
}

TEST(Vignetting, NaturalFallOffIsCosineTimesTheSolidAngleAPixelSees) {
  View v{"p", {0.0, 0.0, 0.0}, {0.0, 100.0, 0.0}, 70.0, 600, 400};
  v.lens.principal_x = 20.0;
  expect_fall_off_is_the_solid_angle(v);
  v.lens.distortion = {-0.12, 0.03, 0.0, 0.0, 0.0};  // barrel: the corners gather more
  expect_fall_off_is_the_solid_angle(v);
  v.lens.distortion = {0.08, 0.0, 0.0, 0.0, 0.0};  // pincushion
  expect_fall_off_is_the_solid_angle(v);
  View fisheye{"f", {0.0, 0.0, 0.0}, {0.0, 100.0, 0.0}, 170.0, 500, 500};
  fisheye.lens.fisheye_focal = 160.0;
  fisheye.lens.projection = Projection::fisheye_equidistant;
  expect_fall_off_is_the_solid_angle(fisheye);
  fisheye.lens.projection = Projection::fisheye_equisolid;
  expect_fall_off_is_the_solid_angle(fisheye);
}

TEST(Vignetting, RectilinearWithoutDistortionIsCosineToTheFourth) {
  ImageField f;
  f.fx = f.fy = 1000.0;
  f.cx = 500.0;
  f.cy = 300.0;
  EXPECT_DOUBLE_EQ(natural_illumination(f, 500.0, 300.0), 1.0);
  EXPECT_NEAR(natural_illumination(f, 1500.0, 300.0), 0.25, 1e-12);  // 45 degrees
  const double theta = std::atan(std::hypot(300.0, 400.0) / 1000.0);
  EXPECT_NEAR(natural_illumination(f, 800.0, 700.0), std::pow(std::cos(theta), 4), 1e-12);
}

TEST(Vignetting, TelecentricAndSphericalViewsHaveNone) {
  ImageField f;
  f.projection = Projection::orthographic;
  EXPECT_EQ(natural_illumination(f, 0.0, 0.0), 1.0);
  f.projection = Projection::spherical;
  EXPECT_EQ(natural_illumination(f, 10.0, 900.0), 1.0);
}

// lensfun's "pa": 1 + k1 r^2 + k2 r^4 + k3 r^6, r = 1 at the half diagonal.
TEST(Vignetting, LensPolynomialIsLensfunsPaModel) {
  ImageField f;
  f.cx = 300.0;
  f.cy = 200.0;
  f.half_diagonal_px = std::hypot(300.0, 200.0);
  const std::array<double, 3> k{-0.3, 0.1, -0.05};
  EXPECT_DOUBLE_EQ(lens_illumination(f, k, 300.0, 200.0), 1.0);
  EXPECT_NEAR(lens_illumination(f, k, 0.0, 0.0), 1.0 - 0.3 + 0.1 - 0.05, 1e-12);
  EXPECT_NEAR(lens_illumination(f, k, 450.0, 300.0), 1.0 - 0.3 / 4 + 0.1 / 16 - 0.05 / 64, 1e-12);
  EXPECT_NEAR(lens_polynomial_minimum(k, 1.0), 0.75, 1e-9);
  EXPECT_LT(lens_polynomial_minimum({-1.5, 0.0, 0.0}, 1.0), 0.0);
}

TEST(Vignetting, AppliedAtEachPixelsCentreAndNotAtAll) {
  ImageField f;
  f.fx = f.fy = 4.0;
  f.cx = 2.0;
  f.cy = 1.0;
  f.half_diagonal_px = std::hypot(2.0, 1.0);
  std::vector<float> plane(8, 2.0f);
  apply_vignetting(plane, vignetting_factors(4, 2, f, {}));
  EXPECT_EQ(plane, std::vector<float>(8, 2.0f));
  apply_vignetting(plane, vignetting_factors(4, 2, f, {true, {-0.2, 0.0, 0.0}}));
  // Pixel (0, 0)'s centre (0.5, 0.5): 1.5 pixels left of and 0.5 above the axis.
  const double rho2 = (1.5 * 1.5 + 0.5 * 0.5) / 16.0;
  const double r2 = (1.5 * 1.5 + 0.5 * 0.5) / (f.half_diagonal_px * f.half_diagonal_px);
  EXPECT_NEAR(plane[0], 2.0 / ((1.0 + rho2) * (1.0 + rho2)) * (1.0 - 0.2 * r2), 1e-6);
  EXPECT_FLOAT_EQ(plane[1], plane[2]);  // symmetric about the axis
}

}  // namespace
}  // namespace landsim::renderer
