#include "renderer/camera.h"

#include <cmath>
#include <numbers>

namespace landsim::renderer {

Camera::Camera(const View& view)
    : position_(Vec3f(view.position)),
      tan_half_fov_(static_cast<float>(std::tan(0.5 * view.fov_y_deg * std::numbers::pi / 180.0))),
      aspect_(static_cast<float>(view.width) / static_cast<float>(view.height)),
      width_(static_cast<float>(view.width)),
      height_(static_cast<float>(view.height)) {
  // Built in double: the camera may look along a long, nearly horizontal line of sight.
  const Vec3 forward = normalize(view.target - view.position);
  const Vec3 right = normalize(cross(forward, Vec3{0.0, 0.0, 1.0}));
  forward_ = Vec3f(forward);
  right_ = Vec3f(right);
  up_ = Vec3f(cross(right, forward));
}

Ray Camera::ray(float px, float py) const {
  const float sx = (2.0f * px / width_ - 1.0f) * tan_half_fov_ * aspect_;
  const float sy = (1.0f - 2.0f * py / height_) * tan_half_fov_;
  return {position_, normalize(forward_ + sx * right_ + sy * up_)};
}

CameraMatrices Camera::matrices() const {
  const Vec3f b = -forward_;  // the camera looks down its -z axis
  const float tx = -dot(right_, position_), ty = -dot(up_, position_), tz = -dot(b, position_);
  CameraMatrices m;
  m.world_to_camera = {right_.x, right_.y, right_.z, tx, up_.x, up_.y, up_.z, ty,
                       b.x,      b.y,      b.z,      tz, 0,     0,     0,     1};
  const float n = 0.1f, f = 1e5f;
  const float sy = 1.0f / tan_half_fov_, sx = sy / aspect_;
  const std::array<float, 16> projection{
      sx, 0, 0, 0, 0, sy, 0, 0, 0, 0, (f + n) / (n - f), 2 * f * n / (n - f), 0, 0, -1, 0};
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      float sum = 0.0f;
      for (int k = 0; k < 4; ++k)
        sum += projection[static_cast<std::size_t>(r * 4 + k)] *
               m.world_to_camera[static_cast<std::size_t>(k * 4 + c)];
      m.world_to_ndc[static_cast<std::size_t>(r * 4 + c)] = sum;
    }
  }
  return m;
}

}  // namespace landsim::renderer
