#pragma once
// Pinhole camera: turns a position on the image plane into a primary ray.
#include "core/vec3.h"
#include "renderer/output/image_output.h"
#include "renderer/scene.h"

namespace landsim::renderer {

struct Ray {
  Vec3f origin;
  Vec3f direction;  // unit
};

class Camera {
 public:
  explicit Camera(const View& view);
  // (px, py) in pixels from the top-left corner of the image, fractional within a pixel.
  Ray ray(float px, float py) const;
  // Scene frame -> camera (x right, y up, looking down -z) and -> normalised device
  // coordinates (OpenGL-style perspective, near 0.1 m, far 100 km), row-major.
  CameraMatrices matrices() const;

 private:
  Vec3f position_;
  Vec3f forward_, right_, up_;
  float tan_half_fov_;
  float aspect_;
  float width_, height_;
};

}  // namespace landsim::renderer
