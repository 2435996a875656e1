#include "renderer/camera.h"

#include <cmath>
#include <numbers>

#include "renderer/lens_distortion.h"
#include "trees/degradation.h"

namespace landsim::renderer {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// Half an angle in radians, evaluated as every perspective formula always has (the same
// bits).
double half_radians(double degrees) { return 0.5 * degrees * std::numbers::pi / 180.0; }

// Rotates the image axes clockwise about the optical axis (seen from behind the camera).
void roll(CameraBasis& b, double degrees) {
  const double c = std::cos(degrees * kDegree), s = std::sin(degrees * kDegree);
  const Vec3 right = c * b.right - s * b.up;
  b.up = s * b.right + c * b.up;
  b.right = right;
}

// Shirley and Chiu's concentric map of the unit square onto the unit disc.
std::pair<float, float> concentric_disc(float u, float v) {
  const float a = 2.0f * u - 1.0f, b = 2.0f * v - 1.0f;
  if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f};
  const float quarter = std::numbers::pi_v<float> / 4.0f;
  if (std::abs(a) > std::abs(b))
    return {a * std::cos(quarter * b / a), a * std::sin(quarter * b / a)};
  return {b * std::sin(quarter * a / b), b * std::cos(quarter * a / b)};
}

// The perspective focal lengths in pixels.
double focal_y(const View& v) { return 0.5 * v.height / std::tan(half_radians(v.fov_y_deg)); }
double focal_x(const View& v) { return focal_y(v) * v.lens.fx_over_fy; }

}  // namespace

CameraBasis camera_basis(const View& view) {
  // Built in double: the camera may look along a long, nearly horizontal line of sight.
  CameraBasis b;
  b.forward = normalize(view.target - view.position);
  const Vec3 side = cross(b.forward, view.up);
  if (length(side) > 1e-9) {
    b.right = normalize(side);
  } else {  // along the default up: right is horizontal, across the heading
    const double h = view.heading_deg * kDegree;
    b.right = {std::cos(h), -std::sin(h), 0.0};
  }
  b.up = cross(b.right, b.forward);
  if (view.roll_deg != 0.0) roll(b, view.roll_deg);
  return b;
}

double pixel_angle_deg(const View& view) {
  switch (view.lens.projection) {
    case Projection::perspective:
      return view.fov_y_deg / view.height;
    case Projection::orthographic:
      return 0.0;
    case Projection::fisheye_equidistant:
    case Projection::fisheye_equisolid:
      return 1.0 / view.lens.fisheye_focal / kDegree;
    case Projection::spherical:
      return 360.0 / view.width;
  }
  return 0.0;
}

// Metres a pixel spans at `distance` near the image centre (not perspective: that keeps
// its own formulas below).
static double pixel_footprint(const View& view, double distance) {
  if (view.lens.projection == Projection::orthographic)
    return std::max(view.lens.extent_width / view.width, view.lens.extent_height / view.height);
  return distance * pixel_angle_deg(view) * kDegree;
}

double calibrated_view_range(const View& view, double distance) {
  if (view.lens.projection == Projection::perspective)
    return trees::calibrated_range(distance, view.height, view.fov_y_deg);
  // The pixel's footprint over that of the reference camera's pixel (0.06 degrees).
  return pixel_footprint(view, distance) / (0.06 * kDegree);
}

double pixels_across(const View& view, double size, double distance) {
  if (view.lens.projection == Projection::perspective) {
    const double tan_half = std::tan(half_radians(view.fov_y_deg));
    return size / (2.0 * distance * tan_half) * view.height;
  }
  return size / pixel_footprint(view, distance);
}

Camera::Camera(const View& view)
    : view_(view),
      basis_(camera_basis(view)),
      position_(Vec3f(view.position)),
      tan_half_fov_(static_cast<float>(std::tan(half_radians(view.fov_y_deg)))),
      aspect_(static_cast<float>(view.width) / static_cast<float>(view.height) /
              static_cast<float>(view.lens.fx_over_fy)),
      width_(static_cast<float>(view.width)),
      height_(static_cast<float>(view.height)),
      shift_x_(static_cast<float>(view.lens.principal_x / focal_x(view))),
      shift_y_(static_cast<float>(view.lens.principal_y / focal_y(view))),
      aperture_(static_cast<float>(view.lens.aperture_radius)),
      focus_(static_cast<float>(view.lens.focus_distance)) {
  forward_ = Vec3f(basis_.forward);
  right_ = Vec3f(basis_.right);
  up_ = Vec3f(basis_.up);
}

std::optional<Ray> Camera::ray(float px, float py, float lu, float lv) const {
  switch (view_.lens.projection) {
    case Projection::perspective:
      return perspective_ray(px, py, lu, lv);
    case Projection::orthographic:
      return orthographic_ray(px, py);
    case Projection::fisheye_equidistant:
    case Projection::fisheye_equisolid:
      return fisheye_ray(px, py);
    case Projection::spherical:
      return spherical_ray(px, py);
  }
  return std::nullopt;
}

std::optional<Ray> Camera::perspective_ray(float px, float py, float lu, float lv) const {
  float sx = (2.0f * px / width_ - 1.0f) * tan_half_fov_ * aspect_ - shift_x_;
  float sy = (1.0f - 2.0f * py / height_) * tan_half_fov_ + shift_y_;
  if (view_.lens.distortion.any()) {  // the pixel shows where the lens bent the scene's ray
    const std::optional<Normalised> u = undistort(view_.lens.distortion, {sx, -sy});
    if (!u) return std::nullopt;
    sx = static_cast<float>(u->x);
    sy = static_cast<float>(-u->y);
  }
  const Vec3f through = forward_ + sx * right_ + sy * up_;  // 1 ahead along the axis
  if (aperture_ <= 0.0f) return Ray{position_, normalize(through)};
  // Thin lens: every ray from the aperture meets the pinhole ray on the plane in focus.
  const auto [dx, dy] = concentric_disc(lu, lv);
  const Vec3f origin = position_ + aperture_ * (dx * right_ + dy * up_);
  return Ray{origin, normalize(position_ + focus_ * through - origin)};
}

Vec3f Camera::towards(double x_right, double y_up, double z_forward) const {
  return Vec3f(normalize(x_right * basis_.right + y_up * basis_.up + z_forward * basis_.forward));
}

std::optional<Ray> Camera::fisheye_ray(float px, float py) const {
  const double x = px - (0.5 * view_.width + view_.lens.principal_x);
  const double y = py - (0.5 * view_.height + view_.lens.principal_y);
  const double r = std::hypot(x, y), f = view_.lens.fisheye_focal;
  double theta = r / f;
  if (view_.lens.projection == Projection::fisheye_equisolid) {
    if (r > 2.0 * f) return std::nullopt;
    theta = 2.0 * std::asin(r / (2.0 * f));
  }
  if (theta > half_radians(view_.fov_y_deg)) return std::nullopt;  // outside the circle
  const double s = r > 0.0 ? std::sin(theta) / r : 0.0;
  return Ray{position_, towards(s * x, -s * y, std::cos(theta))};
}

Ray Camera::spherical_ray(float px, float py) const {
  const double azimuth = (double{px} / view_.width - 0.5) * 2.0 * std::numbers::pi;
  const double elevation = (0.5 - double{py} / view_.height) * std::numbers::pi;
  const double c = std::cos(elevation);
  return {position_, towards(c * std::sin(azimuth), std::sin(elevation), c * std::cos(azimuth))};
}

Ray Camera::orthographic_ray(float px, float py) const {
  const double x = (double{px} / view_.width - 0.5) * view_.lens.extent_width;
  const double y = (0.5 - double{py} / view_.height) * view_.lens.extent_height;
  return {Vec3f(view_.position + x * basis_.right + y * basis_.up), forward_};
}

std::optional<ImagePoint> Camera::project(const Vec3& p) const {
  const Vec3 d = p - view_.position;
  const double cx = dot(d, basis_.right), cy = dot(d, basis_.up), cz = dot(d, basis_.forward);
  const double w = view_.width, h = view_.height;
  const Lens& lens = view_.lens;
  switch (lens.projection) {
    case Projection::perspective: {
      if (cz <= 0.0) return std::nullopt;
      const Normalised n = distort(lens.distortion, {cx / cz, -cy / cz});
      return ImagePoint{focal_x(view_) * n.x + 0.5 * w + lens.principal_x,
                        focal_y(view_) * n.y + 0.5 * h + lens.principal_y};
    }
    case Projection::orthographic:
      if (cz < 0.0) return std::nullopt;
      return ImagePoint{(cx / lens.extent_width + 0.5) * w, (0.5 - cy / lens.extent_height) * h};
    case Projection::fisheye_equidistant:
    case Projection::fisheye_equisolid: {
      const double rho = std::hypot(cx, cy), theta = std::atan2(rho, cz);
      if (theta > half_radians(view_.fov_y_deg)) return std::nullopt;
      const double r = lens.projection == Projection::fisheye_equidistant
                           ? lens.fisheye_focal * theta
                           : 2.0 * lens.fisheye_focal * std::sin(0.5 * theta);
      const double s = rho > 0.0 ? r / rho : 0.0;
      return ImagePoint{0.5 * w + lens.principal_x + s * cx, 0.5 * h + lens.principal_y - s * cy};
    }
    case Projection::spherical: {
      const double azimuth = std::atan2(cx, cz), elevation = std::atan2(cy, std::hypot(cx, cz));
      return ImagePoint{(azimuth / (2.0 * std::numbers::pi) + 0.5) * w,
                        (0.5 - elevation / std::numbers::pi) * h};
    }
  }
  return std::nullopt;
}

CameraMatrices Camera::matrices() const {
  const Vec3f b = -forward_;  // the camera looks down its -z axis
  const float tx = -dot(right_, position_), ty = -dot(up_, position_), tz = -dot(b, position_);
  CameraMatrices m;
  m.world_to_camera = {right_.x, right_.y, right_.z, tx, up_.x, up_.y, up_.z, ty,
                       b.x,      b.y,      b.z,      tz, 0,     0,     0,     1};
  const float n = 0.1f, f = 1e5f;
  std::array<float, 16> projection{};
  if (view_.lens.projection == Projection::perspective) {
    const float sy = 1.0f / tan_half_fov_, sx = sy / aspect_;
    // The principal point moves the image centre: NDC x = 2 u / W - 1, y = 1 - 2 v / H.
    const auto ox = static_cast<float>(-2.0 * view_.lens.principal_x / view_.width);
    const auto oy = static_cast<float>(2.0 * view_.lens.principal_y / view_.height);
    projection = {sx, 0, ox, 0, 0, sy, oy, 0, 0, 0, (f + n) / (n - f), 2 * f * n / (n - f),
                  0,  0, -1, 0};
  } else if (view_.lens.projection == Projection::orthographic) {
    const auto sx = static_cast<float>(2.0 / view_.lens.extent_width);
    const auto sy = static_cast<float>(2.0 / view_.lens.extent_height);
    projection = {sx, 0, 0, 0, 0, sy, 0, 0, 0, 0, -2 / (f - n), -(f + n) / (f - n), 0, 0, 0, 1};
  } else {
    return m;  // no linear map to the image
  }
  m.has_ndc = true;
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

std::array<double, 9> Camera::intrinsics() const {
  const double fx = is_fisheye(view_.lens.projection) ? view_.lens.fisheye_focal : focal_x(view_);
  const double fy = is_fisheye(view_.lens.projection) ? view_.lens.fisheye_focal : focal_y(view_);
  // OpenCV puts pixel (0, 0)'s centre at (0, 0): half a pixel left of and above landsim's.
  return {fx,  0.0, 0.5 * view_.width + view_.lens.principal_x - 0.5,
          0.0, fy,  0.5 * view_.height + view_.lens.principal_y - 0.5,
          0.0, 0.0, 1.0};
}

}  // namespace landsim::renderer
