#include "renderer/camera.h"

#include <gtest/gtest.h>

namespace landsim::renderer {
namespace {

const View kView{"v", {10.0, -20.0, 5.0}, {10.0, 80.0, 5.0}, 60.0, 200, 100};

TEST(Camera, CentreRayLooksAtTheTarget) {
  const Camera cam(kView);
  const Ray r = cam.ray(100.0f, 50.0f);
  EXPECT_NEAR(r.direction.x, 0.0f, 1e-6);
  EXPECT_NEAR(r.direction.y, 1.0f, 1e-6);
  EXPECT_NEAR(r.direction.z, 0.0f, 1e-6);
  EXPECT_EQ(r.origin, (Vec3f{10.0f, -20.0f, 5.0f}));
}

TEST(Camera, TopEdgeIsHalfTheVerticalFovUp) {
  const Camera cam(kView);
  const Ray top = cam.ray(100.0f, 0.0f);
  EXPECT_NEAR(std::atan2(top.direction.z, top.direction.y), 30.0 * M_PI / 180.0, 1e-5);
  const Ray bottom = cam.ray(100.0f, 100.0f);
  EXPECT_LT(bottom.direction.z, 0.0f);
}

TEST(Camera, ImageLeftIsWestWhenLookingNorth) {
  const Camera cam(kView);
  EXPECT_LT(cam.ray(0.0f, 50.0f).direction.x, 0.0f);
  EXPECT_GT(cam.ray(200.0f, 50.0f).direction.x, 0.0f);
  // Horizontal half-angle follows the aspect ratio: tan = 2 * tan(30 deg).
  const Ray right = cam.ray(200.0f, 50.0f);
  EXPECT_NEAR(right.direction.x / right.direction.y, 2.0 * std::tan(M_PI / 6.0), 1e-5);
}

}  // namespace
}  // namespace landsim::renderer
