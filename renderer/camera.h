#pragma once
// A view's camera (docs/CAMERAS.md): turns a position on the image (and on the lens) into a
// primary ray, and a scene point into its position on the image. Every truth layer comes
// from these rays, so every layer agrees with the model.
#include <array>
#include <optional>

#include "core/vec3.h"
#include "renderer/output/image_output.h"
#include "renderer/scene.h"

namespace landsim::renderer {

struct Ray {
  Vec3f origin;
  Vec3f direction;  // unit
};

// A position on the image, pixels from the top-left corner (pixel (i, j)'s centre is at
// i + 0.5, j + 0.5).
struct ImagePoint {
  double x = 0.0, y = 0.0;
};

// The camera's axes in the scene frame: right, up (the image's) and forward (the optical
// axis), orthonormal, right-handed as right x up = -forward.
struct CameraBasis {
  Vec3 right, up, forward;
};
CameraBasis camera_basis(const View& view);

// Degrees per pixel at the image centre (angular models) or 0 (orthographic).
double pixel_angle_deg(const View& view);
// The range at which a tree seen by `view` shows the detail of a tree at `distance` metres
// in Weber & Penn's reference camera (60 degrees over 1000 pixels, section 5): from the
// model's true pixel footprint, including the view's detail_range_scale.
double calibrated_view_range(const View& view, double distance);
// How many pixels across an object of `size` metres at `distance` looks near the image
// centre.
double pixels_across(const View& view, double size, double distance);

class Camera {
 public:
  explicit Camera(const View& view);
  // The ray through image position (px, py), through lens position (lu, lv) in [0, 1)^2
  // (a thin lens only); empty where the model sends no ray (outside a fisheye's circle).
  std::optional<Ray> ray(float px, float py, float lu = 0.5f, float lv = 0.5f) const;
  // Where scene point p appears; empty where the model shows it nowhere (behind a
  // perspective camera, beyond a fisheye's angle).
  std::optional<ImagePoint> project(const Vec3& p) const;
  bool has_aperture() const { return aperture_ > 0.0f; }
  // Scene frame -> camera (x right, y up, looking down -z), and -> normalised device
  // coordinates for the models that have them (perspective: OpenGL-style, near 0.1 m, far
  // 100 km; orthographic: the extent to [-1, 1]), row-major.
  CameraMatrices matrices() const;
  // Perspective: K in OpenCV's convention (pixel centres on integers, y down), row-major.
  std::array<double, 9> intrinsics() const;

 private:
  std::optional<Ray> perspective_ray(float px, float py, float lu, float lv) const;
  std::optional<Ray> fisheye_ray(float px, float py) const;
  Ray spherical_ray(float px, float py) const;
  Ray orthographic_ray(float px, float py) const;
  Vec3f towards(double x_right, double y_up, double z_forward) const;

  View view_;
  CameraBasis basis_;
  Vec3f position_;
  Vec3f forward_, right_, up_;
  float tan_half_fov_;
  float aspect_;
  float width_, height_;
  float shift_x_, shift_y_;  // the principal point's offset in normalised coordinates
  float aperture_, focus_;
};

}  // namespace landsim::renderer
