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

}  // namespace landsim::renderer
